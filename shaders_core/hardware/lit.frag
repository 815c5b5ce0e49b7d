#version 330 core
// Hardware compare: the texture has GL_TEXTURE_COMPARE_MODE = GL_COMPARE_REF_TO_TEXTURE, so
// sampling returns the result of (u <= stored depth), not the depth. With GL_LINEAR the four
// nearest compares are averaged: percentage-closer filtering, soft edges for free.
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;

uniform sampler2DShadow shadowMap;
out vec4 fragColor;

void main()
{
    // The projective divide done once here (not by textureProj) serves the lookup and the
    // light-depth view alike: fewer instructions per pixel on llvmpipe (docs/bench.md, issue 14).
    vec3 p = shadowCoord.xyz / shadowCoord.w;
    // A fixed-point depth texture clamps the reference to [0, 1]; a float one (depth-format=32f,
    // the default) does not, and a receiver beyond the light's far plane would fail the compare
    // against the cleared map. Clamp it here so both formats agree: beyond the far plane only a
    // caster in the map can shadow.
    // BEGIN SOLUTION
    float visibility = shadowCoord.w > 0.0 ? texture(shadowMap, vec3(p.xy, min(p.z, 1.0))) : 1.0;
    // END SOLUTION
    // STUB: // TODO: look the fragment up in the sampler2DShadow at (p.xy, p.z clamped to 1.0): with
    // STUB: // compare mode on, the texture returns the comparison (1.0 lit, 0.0 shadowed, PCF between).
    // STUB: // Only in front of the light (shadowCoord.w > 0.0); elsewhere 1.0.
    // STUB: float visibility = 1.0;
    fragColor = shade(worldPosition, worldNormal, visibility, p.z);
}
