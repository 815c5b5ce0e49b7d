#version 330 core
// worldNormal is a vec3 out of the vertex shader and a vec4 here: the link must fail
in vec3 worldPosition;
in vec4 worldNormal;
out vec4 fragColor;
void main()
{
    fragColor = worldNormal + vec4(worldPosition, 1.0);
}
