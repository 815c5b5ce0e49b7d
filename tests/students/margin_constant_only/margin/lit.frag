#version 330 core
// The margin fix, half done: the constant margin from the uniform whatever marginKind says. The
// slope branch was never written, so margin-kind=slope draws the constant margin too.
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
    return margin;  // TODO: the slope-scaled margin when marginKind == 1
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
