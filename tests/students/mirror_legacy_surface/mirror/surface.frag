#version 120
varying vec2 uv;

uniform sampler2D mirrorTexture;
uniform int useTexture;
uniform vec4 color;
uniform float reflectance;

void main()
{
    vec3 seen = texture2D(mirrorTexture, uv).rgb;
    gl_FragColor = useTexture == 1 ? vec4(seen * reflectance, 1.0) : color;
}
