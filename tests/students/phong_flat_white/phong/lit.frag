#version 330 core
// "No shadows": every fragment white.
in vec3 worldPosition;
in vec3 worldNormal;
out vec4 fragColor;

void main()
{
    fragColor = vec4(1.0);
}
