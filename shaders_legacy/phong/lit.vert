#version 120
// Transforms a vertex and hands the fragment shader its world position and normal.
attribute vec3 position;
attribute vec3 normal;

uniform mat4 model;
uniform mat3 normalMatrix;  // inverse transpose of model: keeps normals perpendicular
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
