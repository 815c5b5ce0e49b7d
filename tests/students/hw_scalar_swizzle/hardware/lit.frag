#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;

uniform sampler2DShadow shadowMap;
out vec4 fragColor;

void main()
{
    float v = textureProj(shadowMap, shadowCoord).r;
    fragColor = shade(worldPosition, worldNormal, v, shadowCoord.z / shadowCoord.w);
}
