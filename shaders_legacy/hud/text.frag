#version 120
uniform vec4 textColor;
void main()
{
    gl_FragColor = textColor;
}
