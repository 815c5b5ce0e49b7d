#version 330 core
// Phong with the hardware stage's shadow test, so shadows are reflected too.
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;

uniform sampler2DShadow shadowMap;
uniform int shadows;  // 0: no shadow map, every fragment lit
out vec4 fragColor;

void main()
{
    float visibility = 1.0;
    if (shadows == 1 && shadowCoord.w > 0.0) visibility = textureProj(shadowMap, shadowCoord);
    fragColor = shade(worldPosition, worldNormal, visibility, shadowCoord.z / shadowCoord.w);
}
