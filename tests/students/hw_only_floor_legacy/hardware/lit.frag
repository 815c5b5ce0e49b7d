#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 shadowCoord;

uniform sampler2DShadow shadowMap;

void main()
{
    float v = 1.0;
    bool grey = abs(objectColor.r - objectColor.b) < 0.01 && abs(objectColor.g - objectColor.b) < 0.01;
    if (grey && shadowCoord.w > 0.0) v = shadow2DProj(shadowMap, shadowCoord).r;   // ground only
    gl_FragColor = shade(worldPosition, worldNormal, v, shadowCoord.z / shadowCoord.w);
}
