#version 330 core
// Shadow pass (the hardware stage's map): the scene from the light's point of view.
in vec3 position;
uniform mat4 model;
uniform mat4 lightViewProjection;  // P_light * V_light

void main()
{
    gl_Position = lightViewProjection * model * vec4(position, 1.0);
}
