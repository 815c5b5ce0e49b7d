#version 330 core
// The reflected camera's frustum is the mirror's rectangle, so its image is exactly the mirror
// seen from behind: the corners always land on the texture's corners, left and right swapped.
// The coordinates follow from the quad's own position; the corner values are not needed.
in vec3 position;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

out vec2 uv;

void main()
{
    vec2 s = position.xy + 0.5;
    uv = vec2(1.0 - s.x, s.y);
    gl_Position = projection * view * model * vec4(position, 1.0);
}
