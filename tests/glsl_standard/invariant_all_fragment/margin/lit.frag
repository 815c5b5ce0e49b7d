#version 330 core
#pragma STDGL invariant(all)
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
    // BEGIN SOLUTION
    if (marginKind == 0) return margin;
    float cosTheta = clamp(dot(N, L), 0.001, 1.0);
    float tanTheta = sqrt(1.0 - cosTheta * cosTheta) / cosTheta;  // tan(acos(N.L))
    return clamp(slopeK * tanTheta, slopeMin, slopeMax);
    // END SOLUTION
    // STUB: // TODO: `margin` when marginKind == 0; else slopeK * tan(acos(N.L)) clamped to
    // STUB: // [slopeMin, slopeMax] (grazing light needs a larger margin).
    // STUB: return 0.0;
}

void main()
{
    vec3 N = normalize(worldNormal);
    vec3 L = normalize(lightPosition - worldPosition);
    vec3 ndc = lightSpace.xyz / lightSpace.w;
    vec3 shadowCoord = ndc * 0.5 + 0.5;
    shadowCoord.z = min(shadowCoord.z, 1.0);  // beyond the far plane: as far as can be stored
    float visibility = 1.0;
    // BEGIN SOLUTION
    if (lightSpace.w > 0.0)
        visibility = shadowCoord.z <= texture(shadowMap, shadowCoord.xy).r + marginFor(N, L) ? 1.0 : 0.0;
    // END SOLUTION
    // STUB: // TODO: the shadow test with marginFor(N, L) as the margin: visibility 0.0 where
    // STUB: // shadowCoord.z lies behind the stored depth plus the margin (lightSpace.w > 0.0).
    fragColor = shade(worldPosition, worldNormal, visibility, shadowCoord.z);
}
