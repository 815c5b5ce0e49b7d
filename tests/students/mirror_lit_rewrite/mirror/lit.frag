#version 330 core
// Mirror stage, lit pass: phong + the hardware shadow compare (so the reflection has shadows).
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;

uniform sampler2DShadow shadowMap;
uniform int shadows;
out vec4 color;

void main()
{
    bool useMap = shadows != 0 && shadowCoord.w > 0.0;
    vec3 proj = shadowCoord.xyz / shadowCoord.w;
    float lightHere = useMap ? texture(shadowMap, proj) : 1.0;
    color = shade(worldPosition, worldNormal, lightHere, proj.z);
}
