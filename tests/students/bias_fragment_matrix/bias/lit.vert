#version 330 core
// I only pass the object-space position; the shadow matrix is applied per fragment.
in vec3 position;
in vec3 normal;

uniform mat4 model;
uniform mat3 normalMatrix;
uniform mat4 view;
uniform mat4 projection;

out vec3 worldPosition;
out vec3 worldNormal;
out vec3 objectPosition;

void main()
{
    objectPosition = position;
    vec4 wp = model * vec4(position, 1.0);
    worldPosition = wp.xyz;
    worldNormal = normalMatrix * normal;
    gl_Position = projection * view * wp;
}
