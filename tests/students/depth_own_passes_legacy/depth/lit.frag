#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;

float visibilityAt(vec4 clipPos)
{
    if (clipPos.w <= 0.0) return 1.0;
    vec3 p = clipPos.xyz / clipPos.w;
    p = p * 0.5 + 0.5;
    if (p.z >= 1.0) return 1.0;
    return step(p.z, texture2D(shadowMap, p.xy).r + margin);
}

void main()
{
    float depthHere = lightSpace.z / lightSpace.w * 0.5 + 0.5;
    gl_FragColor = shade(worldPosition, worldNormal, visibilityAt(lightSpace), depthHere);
}
