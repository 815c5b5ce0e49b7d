#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;

uniform sampler2DShadow shadowMap;
out vec4 fragColor;

void main()
{
    float lit = texture(shadowMap, shadowCoord.xyz);   // sampler does the rest
    fragColor = shade(worldPosition, worldNormal, lit, shadowCoord.z);
}
