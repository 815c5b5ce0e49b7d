#version 120
// Hardware compare: the texture has GL_TEXTURE_COMPARE_MODE = GL_COMPARE_REF_TO_TEXTURE, so
// sampling returns the result of (u <= stored depth), not the depth. With GL_LINEAR the four
// nearest compares are averaged: percentage-closer filtering, soft edges for free.
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 shadowCoord;

uniform sampler2DShadow shadowMap;

void main()
{
    // A fixed-point depth texture clamps the reference to [0, 1]; a float one (depth-format=32f)
    // does not, and a receiver beyond the light's far plane would fail the compare against the
    // cleared map. Clamp it here so both formats agree: beyond the far plane only a caster in
    // the map can shadow.
    vec4 coord = vec4(shadowCoord.xy, min(shadowCoord.z, shadowCoord.w), shadowCoord.w);
    float visibility = shadowCoord.w > 0.0 ? shadow2DProj(shadowMap, coord).r : 1.0;
    gl_FragColor = shade(worldPosition, worldNormal, visibility, shadowCoord.z / shadowCoord.w);
}
