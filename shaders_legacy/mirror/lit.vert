#version 120
// The scene for every view of the mirror stage: the main camera, the reflected camera (into
// the texture) and the reflected scene (stencil method). Only `view` changes between them;
// `model` is never reflected, so worldPosition is always the real point: lighting and
// shadows are computed where the object really is.
attribute vec3 position;
attribute vec3 normal;

uniform mat4 model;
uniform mat3 normalMatrix;
uniform mat4 view;
uniform mat4 projection;
uniform mat4 shadowMatrix;  // bias * P_light * V_light * model

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 shadowCoord;

void main()
{
    vec4 world = model * vec4(position, 1.0);
    worldPosition = world.xyz;
    worldNormal = normalMatrix * normal;
    shadowCoord = shadowMatrix * vec4(position, 1.0);
    gl_Position = projection * view * world;
}
