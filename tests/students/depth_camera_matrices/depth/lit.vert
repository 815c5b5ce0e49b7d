#version 330 core
in vec3 position;
in vec3 normal;

uniform mat4 model;
uniform mat3 normalMatrix;
uniform mat4 view;
uniform mat4 projection;

out vec3 worldPosition;
out vec3 worldNormal;
out vec4 lightSpace;

void main()
{
    vec4 w = model * vec4(position, 1.0);
    worldPosition = w.xyz;
    worldNormal = normalMatrix * normal;
    gl_Position = projection * view * w;
    lightSpace = gl_Position;   // the position "as seen" for the shadow lookup
}
