#version 330 core
in vec2 uv;

uniform sampler2D mirrorTexture;
uniform int useTexture;
uniform vec4 color;
uniform float reflectance;

out vec4 outColor;

void main()
{
    vec4 c = color;
    if (useTexture != 0) c = vec4(texture(mirrorTexture, uv).rgb * reflectance, 1.0);
    outColor = c;
}
