#version 330 core
// Debug view: a full-screen quad (the unit quad scaled to cover NDC).
in vec3 position;
out vec2 uv;
void main()
{
    uv = position.xy + 0.5;
    gl_Position = vec4(position.xy * 2.0, 0.0, 1.0);
}
