#version 330 core
in vec2 uv;

uniform sampler2D mirrorTexture;
uniform int useTexture;
uniform vec4 color;
uniform float reflectance;

out vec4 fragColor;

void main()
{
    // a mirror flips left and right
    vec2 st = vec2(1.0 - uv.x, uv.y);
    if (useTexture == 1)
        fragColor = vec4(reflectance * texture(mirrorTexture, st).rgb, 1.0);
    else
        fragColor = color;
}
