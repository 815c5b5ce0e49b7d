#version 330 core
// Each object in its own colour at full strength: no lighting at all.
in vec3 worldPosition;
in vec3 worldNormal;
uniform vec3 objectColor;
out vec4 fragColor;

void main()
{
    fragColor = vec4(objectColor, 1.0);
}
