#version 120
// rgb shadow test, GLSL 1.20
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;
uniform int packedDepth;

void main()
{
    vec4 clipL = lightSpace;
    float vis = 1.0;
    float d = 0.0;
    if (clipL.w > 0.0) {
        vec2 st = 0.5 * clipL.xy / clipL.w + 0.5;
        d = min(0.5 * clipL.z / clipL.w + 0.5, 1.0);
        vec3 rgb = texture2D(shadowMap, st).rgb;
        float stored = rgb.r;
        if (packedDepth == 1) stored = dot(rgb, vec3(1.0, 1.0 / 255.0, 1.0 / 65025.0));
        vis = (d - margin > stored) ? 0.0 : 1.0;
    }
    gl_FragColor = shade(worldPosition, worldNormal, vis, d);
}
