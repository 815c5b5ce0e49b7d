#version 330 core
#include "common/no_such_file.glsl"
in vec3 worldPosition;
in vec3 worldNormal;
out vec4 fragColor;
void main()
{
    fragColor = vec4(1.0);
}
