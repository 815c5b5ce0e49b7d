#version 120
// Phong with the hardware stage's shadow test, so shadows are reflected too.
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 shadowCoord;

uniform sampler2DShadow shadowMap;
uniform int shadows;  // 0: no shadow map, every fragment lit

void main()
{
    float visibility = 1.0;
    if (shadows == 1 && shadowCoord.w > 0.0) visibility = shadow2DProj(shadowMap, shadowCoord).r;
    gl_FragColor = shade(worldPosition, worldNormal, visibility, shadowCoord.z / shadowCoord.w);
}
