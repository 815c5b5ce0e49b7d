#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 shadowCoord;

uniform sampler2DShadow shadowMap;

void main()
{
    // shadow2DProj gives how much is in shadow
    float sh = shadow2DProj(shadowMap, shadowCoord).r;
    gl_FragColor = shade(worldPosition, worldNormal, 1.0 - sh, shadowCoord.z / shadowCoord.w);
}
