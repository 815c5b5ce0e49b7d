#version 120
// Debug view: the shadow map as grey, near the light dark. Depth is non-linear in z, so it is
// turned back into distance between the light's near and far planes before it is shown.
varying vec2 uv;
uniform sampler2D shadowMap;
uniform int encoding;  // 0 depth texture, 1 one 8-bit value in red, 2 packed over r, g, b
uniform float lightNear;
uniform float lightFar;

void main()
{
    vec4 texel = texture2D(shadowMap, uv);
    float depth = encoding == 2 ? dot(texel.rgb, vec3(1.0, 1.0 / 255.0, 1.0 / 65025.0)) : texel.r;
    float ndc = depth * 2.0 - 1.0;
    float distance = 2.0 * lightNear * lightFar / (lightFar + lightNear - ndc * (lightFar - lightNear));
    float grey = depth >= 1.0 ? 1.0 : (distance - lightNear) / (lightFar - lightNear);
    gl_FragColor = vec4(vec3(grey), 1.0);
}
