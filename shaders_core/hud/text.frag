#version 330 core
uniform vec4 textColor;
out vec4 fragColor;
void main()
{
    fragColor = textColor;
}
