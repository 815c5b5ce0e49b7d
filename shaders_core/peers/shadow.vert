#version 330 core
// Shadow pass: the scene from the light, depth only (every peer draws its map the same way).
in vec3 position;
uniform mat4 model;
uniform mat4 lightViewProjection;  // P_light * V_light

void main()
{
    gl_Position = lightViewProjection * model * vec4(position, 1.0);
}
