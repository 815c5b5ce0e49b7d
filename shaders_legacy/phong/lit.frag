#version 120
// No shadows: every fragment facing the light gets full diffuse and specular,
// so the floor is bright exactly where the shadows belong.
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;

void main()
{
    gl_FragColor = shade(worldPosition, worldNormal, 1.0, gl_FragCoord.z);
}
