#version 330 core
// Lit pass: besides the usual transform, carry the vertex as the light sees it.
in vec3 position;
in vec3 normal;

uniform mat4 model;
uniform mat3 normalMatrix;
uniform mat4 view;
uniform mat4 projection;
uniform mat4 lightViewProjection;  // P_light * V_light, the same matrices as the shadow pass

out vec3 worldPosition;
out vec3 worldNormal;
out vec4 lightSpace;  // clip coordinates from the light; w is not 1 (perspective)

void main()
{
    vec4 world = model * vec4(position, 1.0);
    worldPosition = world.xyz;
    worldNormal = normalMatrix * normal;
    lightSpace = lightViewProjection * world;
    gl_Position = projection * view * world;
}
