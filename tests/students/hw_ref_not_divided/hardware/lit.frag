#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;

uniform sampler2DShadow shadowMap;
out vec4 fragColor;

void main()
{
    vec2 st = shadowCoord.xy / shadowCoord.w;
    float light = texture(shadowMap, vec3(st, shadowCoord.z));
    fragColor = shade(worldPosition, worldNormal, light, shadowCoord.z);
}
