#version 330 core
// No shadows: every fragment facing the light gets full diffuse and specular,
// so the floor is bright exactly where the shadows belong.
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
out vec4 fragColor;

void main()
{
    fragColor = shade(worldPosition, worldNormal, 1.0, gl_FragCoord.z);
}
