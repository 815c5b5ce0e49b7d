#version 330 core
// Mirror quad: texture coordinates are the corners' positions in the reflected image,
// blended bilinearly across the quad.
in vec3 position;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform vec2 cornerUv[4];   // BL, BR, TR, TL

out vec2 uv;

void main()
{
    float a = position.x + 0.5;
    float b = position.y + 0.5;
    vec2 bottom = (1.0 - a) * cornerUv[0] + a * cornerUv[1];
    vec2 top = (1.0 - a) * cornerUv[3] + a * cornerUv[2];
    uv = (1.0 - b) * bottom + b * top;
    gl_Position = projection * (view * (model * vec4(position, 1.0)));
}
