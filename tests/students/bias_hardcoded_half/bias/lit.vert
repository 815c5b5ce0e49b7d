#version 330 core
in vec3 position;
in vec3 normal;

uniform mat4 model;
uniform mat3 normalMatrix;
uniform mat4 view;
uniform mat4 projection;
uniform mat4 lightViewProjection;

out vec3 worldPosition;
out vec3 worldNormal;
out vec4 shadowCoord;

void main()
{
    vec4 wp = model * vec4(position, 1.0);
    worldPosition = wp.xyz;
    worldNormal = normalMatrix * normal;
    shadowCoord = lightViewProjection * wp;   // I do the 0.5 myself in the fragment shader
    gl_Position = projection * view * wp;
}
