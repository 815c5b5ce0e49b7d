#version 120
// light's view of the scene
attribute vec3 position;
uniform mat4 model;
uniform mat4 lightViewProjection;

void main()
{
    vec4 worldPos = model * vec4(position, 1.0);
    gl_Position = lightViewProjection * worldPos;
}
