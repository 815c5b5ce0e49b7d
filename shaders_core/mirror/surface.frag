#version 330 core
// As on the slides: the fragment's colour comes either from the texture or from a colour.
in vec2 uv;

uniform sampler2D mirrorTexture;  // what the reflected camera saw
uniform int useTexture;           // 1: the reflection; 0: a flat colour (stencil passes)
uniform vec4 color;
uniform float reflectance;  // a real mirror returns a little less than all light

out vec4 fragColor;

void main()
{
    if (useTexture == 1) {
        // BEGIN SOLUTION
        fragColor = vec4(reflectance * texture(mirrorTexture, uv).rgb, 1.0);
        // END SOLUTION
        // STUB: // TODO: the mirror shows what the reflected camera saw: mirrorTexture at uv, its
        // STUB: // colour scaled by `reflectance`, alpha 1.0. Until then the mirror is flat grey.
        // STUB: fragColor = vec4(0.5, 0.5, 0.5, 1.0);
    } else {
        fragColor = color;
    }
}
