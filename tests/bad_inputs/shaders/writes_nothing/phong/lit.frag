#version 330 core
// writes no colour at all: the result is undefined but the program must not crash
in vec3 worldPosition;
in vec3 worldNormal;
out vec4 fragColor;
void main()
{
}
