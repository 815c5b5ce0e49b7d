#version 120
// HUD text: pixel coordinates in, clip space out.
attribute vec3 position;
uniform mat4 projection;
void main()
{
    gl_Position = projection * vec4(position.xy, 0.0, 1.0);
}
