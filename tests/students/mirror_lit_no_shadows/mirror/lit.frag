#version 330 core
// Phong for the mirror scene; the shadow lookup left out ("the mirror stage is about reflections").
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;

uniform sampler2DShadow shadowMap;
uniform int shadows;
out vec4 fragColor;

void main()
{
    fragColor = shade(worldPosition, worldNormal, 1.0, shadowCoord.z / shadowCoord.w);
}
