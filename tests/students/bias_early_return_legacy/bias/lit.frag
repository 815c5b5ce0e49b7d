#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 shadowCoord;

uniform sampler2D shadowMap;
uniform float margin;

void main()
{
    if (shadowCoord.w <= 0.0) {
        gl_FragColor = shade(worldPosition, worldNormal, 1.0, 0.0);
        return;
    }
    float s = shadowCoord.x / shadowCoord.w;
    float t = shadowCoord.y / shadowCoord.w;
    float u = shadowCoord.z / shadowCoord.w;
    float stored = texture2D(shadowMap, vec2(s, t)).r;
    if (u - margin > stored) {
        gl_FragColor = shade(worldPosition, worldNormal, 0.0, u);
        return;
    }
    gl_FragColor = shade(worldPosition, worldNormal, 1.0, u);
}
