#version 120
attribute vec3 position;
attribute vec3 normal;

uniform mat4 model;
uniform mat3 normalMatrix;
uniform mat4 view;
uniform mat4 projection;
uniform mat4 shadowMatrix;    // bias * P_light * V_light * model, set by the stage

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 mapPos;

void main()
{
    worldPosition = (model * vec4(position, 1.0)).xyz;
    worldNormal = normalMatrix * normal;
    mapPos = shadowMatrix * vec4(position, 1.0);
    gl_Position = projection * view * vec4(worldPosition, 1.0);
}
