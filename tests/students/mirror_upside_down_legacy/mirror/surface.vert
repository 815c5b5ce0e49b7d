#version 120
attribute vec3 position;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform vec2 cornerUv[4];

varying vec2 uv;

void main()
{
    vec2 f = position.xy + 0.5;
    // corners: 0 and 1 along the top, 3 and 2 along the bottom
    uv = mix(mix(cornerUv[3], cornerUv[2], f.x), mix(cornerUv[0], cornerUv[1], f.x), f.y);
    gl_Position = projection * view * model * vec4(position, 1.0);
}
