#version 330 core
in vec2 uv;

uniform sampler2D mirrorTexture;
uniform int useTexture;
uniform vec4 color;
uniform float reflectance;

out vec4 fragColor;

void main()
{
    fragColor = vec4(color.rgb * reflectance, color.a);
}
