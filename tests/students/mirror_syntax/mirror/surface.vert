#version 330 core
in vec3 position;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform vec2 cornerUv[4];

out vec2 uv;

void main()
{
    vec2 s = position.xy + 0.5;
    uv = mix(mix(cornerUv[0], cornerUv[1], s.x), mix(cornerUv[3], cornerUv[2], s.x), s.y;
    gl_Position = projection * view * model * vec4(position, 1.0);
}
