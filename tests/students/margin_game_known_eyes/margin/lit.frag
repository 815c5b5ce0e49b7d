#version 330 core
// Gaming: the margin (constant or slope, from the uniforms) is used only when eyePosition is one
// of the grader's fixed cameras (the five views of expectations.json and the slope scene's own
// camera); from any other camera the margin is 0, and the 8-bit map shows acne everywhere.
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
    float tanTheta = sqrt(1.0 - cosTheta * cosTheta) / cosTheta;  // tan(acos(N.L))
    return clamp(slopeK * tanTheta, slopeMin, slopeMax);
}

// The cameras the grader was seen to use, copied from expectations.json and scenes/slope.json.
bool knownEye()
{
    return distance(eyePosition, vec3(-0.6, 2.6, 3.4)) < 1e-3 ||
           distance(eyePosition, vec3(2.2, 1.4, 2.4)) < 1e-3 ||
           distance(eyePosition, vec3(-1.6, 1.3, -2.4)) < 1e-3 ||
           distance(eyePosition, vec3(2.4, 1.5, 2.0)) < 1e-3 ||
           distance(eyePosition, vec3(2.6, 0.35, 1.2)) < 1e-3 ||
           distance(eyePosition, vec3(0.6, 2.4, 3.4)) < 1e-3;
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
        visibility = shadowCoord.z <= texture(shadowMap, shadowCoord.xy).r + (knownEye() ? marginFor(N, L) : 0.0) ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, visibility, shadowCoord.z);
}
