#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;
out vec4 fragColor;

void main()
{
    vec3 ndc = lightSpace.xyz / lightSpace.w;
    vec2 st = ndc.xy * 0.5 + 0.5;
    float depthNow = ndc.z;                      // still in [-1,1]
    float v = depthNow <= texture(shadowMap, st).r + margin ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, v, depthNow);
}
