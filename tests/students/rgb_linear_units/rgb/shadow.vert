#version 330 core
// Store the distance along the light's axis (clip w), linear, scaled into [0,1].
in vec3 position;
uniform mat4 model;
uniform mat4 lightViewProjection;
out float lightDistance;

void main()
{
    gl_Position = lightViewProjection * model * vec4(position, 1.0);
    lightDistance = gl_Position.w / 5.0;  // the whole scene is within 5 units of the light
}
