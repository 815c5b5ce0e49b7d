#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 shadowCoord;

uniform sampler2DShadow shadowMap;

void main()
{
    float v = textureProj(shadowMap, shadowCoord);
    gl_FragColor = shade(worldPosition, worldNormal, v, shadowCoord.z / shadowCoord.w);
}
