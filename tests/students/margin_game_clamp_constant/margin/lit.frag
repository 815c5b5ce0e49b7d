#version 330 core
// The margin fix: a constant margin, or one that grows with the angle between N and L
// (a surface seen at a grazing angle spans many depths inside one texel of the map).
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 lightSpace;

uniform sampler2D shadowMap;
uniform int marginKind;  // 0 constant, 1 slope-scaled
uniform float margin;    // the constant margin
uniform float slopeK;    // slope-scaled: margin = clamp(slopeK * tan(acos(N.L)), slopeMin, slopeMax)
uniform float slopeMin;
uniform float slopeMax;
out vec4 fragColor;

float marginFor(vec3 N, vec3 L)
{
    if (marginKind == 0) return margin;
    float cosTheta = clamp(dot(N, L), 0.001, 1.0);
    float tanTheta = sqrt(1.0 - cosTheta * cosTheta) / cosTheta;
    return clamp(slopeK * tanTheta, 0.012, 0.012);
}

void main()
{
    vec3 N = normalize(worldNormal);
    vec3 L = normalize(lightPosition - worldPosition);
    vec3 ndc = lightSpace.xyz / lightSpace.w;
    vec3 shadowCoord = ndc * 0.5 + 0.5;
    shadowCoord.z = min(shadowCoord.z, 1.0);  // beyond the far plane: as far as can be stored
    float visibility = 1.0;
    if (lightSpace.w > 0.0)
        visibility = shadowCoord.z <= texture(shadowMap, shadowCoord.xy).r + marginFor(N, L) ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, visibility, shadowCoord.z);
}
