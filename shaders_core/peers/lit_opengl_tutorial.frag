#version 330 core
// opengl-tutorial's lookup: four hardware compares (each a GL_LINEAR 2x2 PCF) spread on a
// Poisson disk about 1/700 of the map wide, with a bias of 0.005 tan(acos(N.L)) in [0, 0.01].
// The tutorial darkens by 0.2 per shadowed tap; here the lit fraction of the four taps feeds
// the shared lighting, so only the lookup differs from ours.
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;

uniform sampler2DShadow shadowMap;
out vec4 fragColor;

const vec2 disk[4] = vec2[](vec2(-0.94, -0.40), vec2(0.95, -0.77), vec2(-0.09, -0.93), vec2(0.34, 0.29));

float litFraction(vec3 N, vec3 L)
{
    if (shadowCoord.w <= 0.0) return 1.0;
    vec3 p = shadowCoord.xyz / shadowCoord.w;
    // BEGIN SOLUTION
    float cosTheta = clamp(dot(N, L), 0.0, 1.0);
    float bias = clamp(0.005 * tan(acos(cosTheta)), 0.0, 0.01);
    float lit = 0.0;
    for (int i = 0; i < 4; ++i)
        lit += texture(shadowMap, vec3(p.xy + disk[i] / 700.0, p.z - bias));
    return lit / 4.0;
    // END SOLUTION
    // STUB: // TODO: opengl-tutorial's lookup: bias = 0.005 * tan(acos(N.L)) clamped to [0, 0.01];
    // STUB: // four hardware compares at p.xy + disk[i] / 700.0 against p.z - bias, averaged.
    // STUB: return 1.0;
}

void main()
{
    vec3 N = normalize(worldNormal);
    vec3 L = normalize(lightPosition - worldPosition);
    fragColor = shade(worldPosition, worldNormal, litFraction(N, L), shadowCoord.z / shadowCoord.w);
}
