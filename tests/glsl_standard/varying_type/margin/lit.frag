#version 330 core
// A fragment input whose type differs from the vertex output of its name (vec3 out, vec4 in):
// the standard makes it a link error.
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec3 lightSpace;

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
    float tanTheta = sqrt(1.0 - cosTheta * cosTheta) / cosTheta;  // tan(acos(N.L))
    return clamp(slopeK * tanTheta, slopeMin, slopeMax);
}

void main()
{
    vec3 N = normalize(worldNormal);
    vec3 L = normalize(lightPosition - worldPosition);
    vec3 ndc = lightSpace;
    vec3 shadowCoord = ndc * 0.5 + 0.5;
    shadowCoord.z = min(shadowCoord.z, 1.0);  // beyond the far plane: as far as can be stored
    float visibility = 1.0;
    visibility = shadowCoord.z <= texture(shadowMap, shadowCoord.xy).r + marginFor(N, L) ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, visibility, shadowCoord.z);
}
