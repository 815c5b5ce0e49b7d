#version 120
// Normal offset: instead of moving the compared depth, move the point looked up: along the
// surface normal by a few texels' width at that distance from the light, more as N.L falls.
// The pushed point sits in front of its own surface, so no depth margin is needed. One
// hardware compare with GL_LINEAR (2x2 PCF) as in our hardware stage.
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 shadowCoord;

uniform sampler2DShadow shadowMap;
uniform mat4 lightViewProjection;  // P_light * V_light
uniform float texelPerDepth;       // a texel's world width per unit of depth from the light
uniform float normalOffset;        // texels along N added as N.L falls to 0
uniform float minOffset;           // texels along N where the light hits square on

float litFraction(vec3 N, vec3 L)
{
    vec4 here = lightViewProjection * vec4(worldPosition, 1.0);
    if (here.w <= 0.0) return 1.0;
    // BEGIN SOLUTION
    float texelWorld = here.w * texelPerDepth;
    float texels = minOffset + normalOffset * (1.0 - clamp(dot(N, L), 0.0, 1.0));
    vec3 pushed = worldPosition + N * (texels * texelWorld);
    vec4 clip = lightViewProjection * vec4(pushed, 1.0);
    vec3 p = clip.xyz / clip.w * 0.5 + 0.5;
    return shadow2D(shadowMap, p).r;
    // END SOLUTION
    // STUB: // TODO: push the point looked up along N by (minOffset + normalOffset * (1 - N.L))
    // STUB: // texels, a texel being here.w * texelPerDepth wide in the world; project the pushed
    // STUB: // point with lightViewProjection into the map's [0,1] cube and compare it there once.
    // STUB: return 1.0;
}

void main()
{
    vec3 N = normalize(worldNormal);
    vec3 L = normalize(lightPosition - worldPosition);
    gl_FragColor = shade(worldPosition, worldNormal, litFraction(N, L), shadowCoord.z / shadowCoord.w);
}
