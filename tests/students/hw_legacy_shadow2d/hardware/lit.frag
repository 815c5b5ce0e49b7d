#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 shadowCoord;

uniform sampler2DShadow shadowMap;

void main()
{
    float lightAmount = 1.0;
    if (shadowCoord.w > 0.0)
        lightAmount = shadow2D(shadowMap, shadowCoord.xyz / shadowCoord.w).r;
    gl_FragColor = shade(worldPosition, worldNormal, lightAmount, shadowCoord.z / shadowCoord.w);
}
