#version 120
// LearnOpenGL's lookup: a plain depth texture compared by hand at the nine texels around the
// point (3x3 PCF), with a bias that grows as the light grazes the surface; points beyond the
// light's far plane count as lit.
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 shadowCoord;

uniform sampler2D shadowMap;
uniform float texelSize;  // 1 / map size

float litFraction(vec3 N, vec3 L)
{
    if (shadowCoord.w <= 0.0) return 1.0;
    vec3 p = shadowCoord.xyz / shadowCoord.w;
    if (p.z > 1.0) return 1.0;
    // BEGIN SOLUTION
    float bias = max(0.05 * (1.0 - dot(N, L)), 0.005);
    float shadowed = 0.0;
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y) {
            float stored = texture2D(shadowMap, p.xy + vec2(x, y) * texelSize).r;
            shadowed += p.z - bias > stored ? 1.0 : 0.0;
        }
    return 1.0 - shadowed / 9.0;
    // END SOLUTION
    // STUB: // TODO: LearnOpenGL's lookup: bias = max(0.05 * (1.0 - N.L), 0.005); compare p.z - bias
    // STUB: // with the depth stored at the nine texels around p.xy (texelSize apart) and return
    // STUB: // the fraction of them that do not shadow (1.0 all lit, 0.0 all shadowed).
    // STUB: return 1.0;
}

void main()
{
    vec3 N = normalize(worldNormal);
    vec3 L = normalize(lightPosition - worldPosition);
    gl_FragColor = shade(worldPosition, worldNormal, litFraction(N, L), shadowCoord.z / shadowCoord.w);
}
