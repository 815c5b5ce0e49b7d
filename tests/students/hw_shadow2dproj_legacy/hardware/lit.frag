#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 shadowCoord;

uniform sampler2DShadow shadowMap;

void main()
{
    float visibility = 1.0;
    if (shadowCoord.w > 0.0)
        visibility = shadow2DProj(shadowMap, shadowCoord).r;  // divides s, t and r by q itself
    gl_FragColor = shade(worldPosition, worldNormal, visibility, shadowCoord.z / shadowCoord.w);
}
