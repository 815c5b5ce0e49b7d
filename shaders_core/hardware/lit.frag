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
    // A fixed-point depth texture clamps the reference to [0, 1]; a float one (depth-format=32f)
    // does not, and a receiver beyond the light's far plane would fail the compare against the
    // cleared map. Clamp it here so both formats agree: beyond the far plane only a caster in
    // the map can shadow.
    vec4 coord = vec4(shadowCoord.xy, min(shadowCoord.z, shadowCoord.w), shadowCoord.w);
    float visibility = shadowCoord.w > 0.0 ? textureProj(shadowMap, coord) : 1.0;
    fragColor = shade(worldPosition, worldNormal, visibility, shadowCoord.z / shadowCoord.w);
}
