#version 330 core
// The 8-bit lookup with the margin; with packedDepth set the map holds r, g and b parts, but
// only r is read ("r is the depth, g and b are just extra precision"): the low bytes are lost.
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;
uniform int packedDepth;
out vec4 fragColor;

void main()
{
    vec3 ndc = lightSpace.xyz / lightSpace.w;
    vec3 shadowCoord = ndc * 0.5 + 0.5;
    shadowCoord.z = min(shadowCoord.z, 1.0);
    float stored = texture(shadowMap, shadowCoord.xy).r;
    float visibility = 1.0;
    if (lightSpace.w > 0.0) visibility = shadowCoord.z <= stored + margin ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, visibility, shadowCoord.z);
}
