#version 330 core
// Only the ambient term: the scene and its reflection are flat and dim, no diffuse, no highlight,
// no shadows.
in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;

uniform vec3 objectColor;
uniform float ambient;
out vec4 fragColor;

void main()
{
    fragColor = vec4(objectColor * ambient, 1.0);
}
