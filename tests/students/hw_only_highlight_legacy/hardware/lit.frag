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
    // lit colour with the highlight removed where the light is blocked
    vec3 N = normalize(worldNormal);
    vec3 L = normalize(lightPosition - worldPosition);
    vec3 V = normalize(eyePosition - worldPosition);
    float NdotL = max(dot(N, L), 0.0);
    float spec = NdotL > 0.0 ? pow(max(dot(reflect(-L, N), V), 0.0), shininess) : 0.0;
    vec3 color = objectColor * (ambient + diffuse * NdotL) + vec3(visibility * specular * spec);
    gl_FragColor = debugView == 0 ? vec4(color, 1.0) : shade(worldPosition, worldNormal, visibility, p.z);
}
