#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 shadowCoord;

uniform sampler2DShadow shadowMap;

void main()
{
    vec3 p = shadowCoord.xyz / shadowCoord.w;
    float visibility = shadowCoord.w > 0.0 ? shadow2D(shadowMap, vec3(p.xy, min(p.z, 1.0))).r : 1.0;
    vec4 lit = shade(worldPosition, worldNormal, 1.0, p.z);
    gl_FragColor = vec4(lit.rgb * visibility, 1.0);  // no light, no colour
}
