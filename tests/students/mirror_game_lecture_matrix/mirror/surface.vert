#version 330 core
// The mirror's texture coordinates: each vertex projected by the reflected camera, P' V', with
// the matrices `shadowlab render --stage mirror --explain` prints (copied in, column by column).
in vec3 position;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

out vec2 uv;

const mat4 reflectedView = mat4(-1.0, 0.0, 0.0, 0.0,
                                0.0, 1.0, 0.0, 0.0,
                                0.0, 0.0, -1.0, 0.0,
                                -0.6, -2.6, -6.2, 1.0);
const mat4 reflectedProjection = mat4(3.2, 0.0, 0.0, 0.0,
                                      0.0, 8.727273, 0.0, 0.0,
                                      -0.4, -3.727273, -3.698806, -1.0,
                                      0.0, 0.0, -22.554268, 0.0);

void main()
{
    vec4 world = model * vec4(position, 1.0);
    vec4 clip = reflectedProjection * reflectedView * world;
    uv = 0.5 * clip.xy / clip.w + 0.5;
    gl_Position = projection * view * world;
}
