#version 120
// Hardware compare: the texture has GL_TEXTURE_COMPARE_MODE = GL_COMPARE_REF_TO_TEXTURE, so
// sampling returns the result of (u <= stored depth), not the depth. With GL_LINEAR the four
// nearest compares are averaged: percentage-closer filtering, soft edges for free.
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 shadowCoord;

uniform sampler2DShadow shadowMap;
uniform sampler2D depthPeek;  // left from debugging: the raw map, to look at its depths

void main()
{
    // The projective divide done once here (not by shadow2DProj) serves the lookup and the
    // light-depth view alike: fewer instructions per pixel on llvmpipe (docs/bench.md, issue 14).
    vec3 p = shadowCoord.xyz / shadowCoord.w;
    // A fixed-point depth texture clamps the reference to [0, 1]; a float one (depth-format=32f,
    // the default) does not, and a receiver beyond the light's far plane would fail the compare
    // against the cleared map. Clamp it here so both formats agree: beyond the far plane only a
    // caster in the map can shadow.
    float visibility = shadowCoord.w > 0.0 ? shadow2D(shadowMap, vec3(p.xy, min(p.z, 1.0))).r : 1.0;
    if (debugView == 7) {  // never set by the stage: the debugging peek
        gl_FragColor = vec4(vec3(texture2D(depthPeek, p.xy).r), 1.0);
        return;
    }
    gl_FragColor = shade(worldPosition, worldNormal, visibility, p.z);
}
