#version 120
varying vec2 uv;

uniform sampler2D mirrorTexture;
uniform int useTexture;
uniform vec4 color;
uniform float reflectance;

void main()
{
    // the reflection texture was rendered for the screen, so look it up at the pixel
    vec2 screenUv = gl_FragCoord.xy / vec2(640.0, 480.0);
    screenUv.x = 1.0 - screenUv.x;
    if (useTexture == 1)
        gl_FragColor = vec4(reflectance * texture2D(mirrorTexture, screenUv).rgb, 1.0);
    else
        gl_FragColor = color;
}
