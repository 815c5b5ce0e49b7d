#version 120
// GLSL 1.30's `in` in a #version 120 shader: NVIDIA's driver takes it, the standard does not.
in vec3 position;
attribute vec3 normal;

uniform mat4 model;
uniform mat3 normalMatrix;
uniform mat4 view;
uniform mat4 projection;

varying vec3 worldPosition;
varying vec3 worldNormal;

void main()
{
    vec4 world = model * vec4(position, 1.0);
    worldPosition = world.xyz;
    worldNormal = normalMatrix * normal;
    gl_Position = projection * view * world;
}
