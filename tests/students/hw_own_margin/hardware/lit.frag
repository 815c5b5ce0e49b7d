#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;

uniform sampler2DShadow shadowMap;
out vec4 fragColor;

void main()
{
    vec4 sc = shadowCoord;
    sc.z -= 0.005 * sc.w;   // extra safety margin against acne
    float lit = sc.w > 0.0 ? textureProj(shadowMap, sc) : 1.0;
    fragColor = shade(worldPosition, worldNormal, lit, sc.z / sc.w);
}
