#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;

void main()
{
    vec4 c = shade(worldPosition, normalize(worldNormal), 1.0, 0.0);
    gl_FragColor = c;
}
