#version 120
attribute vec3 position;
attribute vec3 normal;

uniform mat4 model;
uniform mat3 normalMatrix;
uniform mat4 view;
uniform mat4 projection;
uniform mat4 lightViewProjection;

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 lightSpace;

void main()
{
    vec4 wp = model * vec4(position, 1.0);
    worldPosition = wp.xyz;
    worldNormal = normalMatrix * normal;
    mat4 camera = projection * view;
    lightSpace = camera * wp;
    gl_Position = camera * wp;
}
