#version 330 core
#include "common/a.glsl"
out vec4 fragColor;
void main()
{
    fragColor = vec4(1.0);
}
