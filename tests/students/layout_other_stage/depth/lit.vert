#version 330 core
// Carries the light-space position already scaled and biased into [0,1] (before the divide:
// (clip + w) / 2 is linear, so it can be done per vertex).
in vec3 position;
in vec3 normal;

uniform mat4 model;
uniform mat3 normalMatrix;
uniform mat4 view;
uniform mat4 projection;
uniform mat4 lightViewProjection;

out vec3 worldPosition;
out vec3 worldNormal;
out vec4 texCoordL;

void main()
{
    vec4 w = model * vec4(position, 1.0);
    vec4 c = lightViewProjection * w;
    texCoordL = vec4(0.5 * (c.xyz + c.www), c.w);
    worldPosition = w.xyz;
    worldNormal = normalMatrix * normal;
    gl_Position = projection * view * w;
}
