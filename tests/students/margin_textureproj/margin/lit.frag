#version 330 core
#include "common/phong.glsl"

in vec3 fragPos;
in vec3 fragNormal;
in vec4 mapCoord;

uniform sampler2D shadowMap;
uniform int marginKind;
uniform float margin;
uniform float slopeK;
uniform float slopeMin;
uniform float slopeMax;
out vec4 fragColor;

float chooseMargin()
{
    if (marginKind == 0) return margin;
    float ndl = clamp(dot(normalize(fragNormal), normalize(lightPosition - fragPos)), 0.001, 1.0);
    return clamp(slopeK * tan(acos(ndl)), slopeMin, slopeMax);
}

void main()
{
    float ownDepth = min(mapCoord.z / mapCoord.w, 1.0);
    float mapDepth = textureProj(shadowMap, mapCoord).r;
    float seen = (mapCoord.w > 0.0 && ownDepth > mapDepth + chooseMargin()) ? 0.0 : 1.0;
    fragColor = shade(fragPos, fragNormal, seen, ownDepth);
}
