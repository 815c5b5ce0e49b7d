#version 120
// Hardware compare: shadowCoord = bias * P_light * V_light * model, built on the CPU.
attribute vec3 position;
attribute vec3 normal;

uniform mat4 model;
uniform mat3 normalMatrix;
uniform mat4 view;
uniform mat4 projection;
uniform mat4 shadowMatrix;

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 shadowCoord;  // divided by w in the fragment shader

void main()
{
    vec4 world = model * vec4(position, 1.0);
    worldPosition = world.xyz;
    worldNormal = normalMatrix * normal;
    shadowCoord = shadowMatrix * vec4(position, 1.0);
    gl_Position = projection * view * world;
}
