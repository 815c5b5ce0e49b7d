#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 shadowCoord;

uniform sampler2D shadowMap;
uniform float margin;

void main()
{
    vec3 c = shadowCoord.xyz / shadowCoord.w;
    float m = texture2D(shadowMap, c.xy).r;
    float light = (c.z >= m + margin) ? 1.0 : 0.0;
    gl_FragColor = shade(worldPosition, worldNormal, light, c.z);
}
