#version 330 core
// Hardware 3x3 PCF: nine hardware compares (GL_NEAREST) one texel apart, averaged: ten levels
// of visibility across an edge instead of the 2x2 filter's bilinear ramp.
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;

uniform sampler2DShadow shadowMap;
uniform float texelSize;  // 1 / map size
out vec4 fragColor;

float litFraction()
{
    if (shadowCoord.w <= 0.0) return 1.0;
    vec3 p = shadowCoord.xyz / shadowCoord.w;
    float reference = min(p.z, 1.0);  // a float map (32f) does not clamp it: see lit.frag
    // BEGIN SOLUTION
    float lit = 0.0;
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            lit += texture(shadowMap, vec3(p.xy + vec2(x, y) * texelSize, reference));
    return lit / 9.0;
    // END SOLUTION
    // STUB: // TODO: nine hardware compares one texel (texelSize) apart around p.xy, at
    // STUB: // offsets -1, 0, +1 in x and y, each against `reference`; return their average.
    // STUB: return 1.0;
}

void main()
{
    fragColor = shade(worldPosition, worldNormal, litFraction(), shadowCoord.z / shadowCoord.w);
}
