#version 330 core
in vec3 position;
uniform mat4 model;
uniform mat4 lightViewProjection;
out float lightDistance;

void main()
{
    gl_Position = lightViewProjection * model * vec4(position, 1.0);
    lightDistance = gl_Position.w;      // eye-space distance along the light's axis
}
