#version 330 core
// As on the slides, then a warm tint "to make the mirror look like bronze", applied after the
// branch: the reflection and the flat colours of the stencil passes alike.
in vec2 uv;

uniform sampler2D mirrorTexture;
uniform int useTexture;
uniform vec4 color;
uniform float reflectance;

out vec4 fragColor;

void main()
{
    if (useTexture == 1)
        fragColor = vec4(reflectance * texture(mirrorTexture, uv).rgb, 1.0);
    else
        fragColor = color;
    fragColor.rgb *= vec3(1.0, 0.75, 0.5);
}
