#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;

uniform sampler2DShadow shadowMap;
out vec4 fragColor;

void main()
{
    vec3 p = shadowCoord.xyz / shadowCoord.w;
    float lit = shadowCoord.w > 0.0 ? texture(shadowMap, p) : 1.0;
    fragColor = shade(worldPosition, worldNormal, lit, p.z);
}
