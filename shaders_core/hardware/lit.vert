#version 330 core
// Hardware compare: shadowCoord = bias * P_light * V_light * model, built on the CPU.
in vec3 position;
in vec3 normal;

uniform mat4 model;
uniform mat3 normalMatrix;
uniform mat4 view;
uniform mat4 projection;
uniform mat4 shadowMatrix;

out vec3 worldPosition;
out vec3 worldNormal;
out vec4 shadowCoord;  // divided by w in the fragment shader

void main()
{
    vec4 world = model * vec4(position, 1.0);
    worldPosition = world.xyz;
    worldNormal = normalMatrix * normal;
    shadowCoord = shadowMatrix * vec4(position, 1.0);
    gl_Position = projection * view * world;
}
