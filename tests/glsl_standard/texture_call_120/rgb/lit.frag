#version 120
// GLSL 1.30's texture() in a #version 120 shader (texture2D there): NVIDIA takes it, the
// standard does not.
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;     // 0 in the slides' first attempt: acne
uniform int packedDepth;  // 1: the map holds depth spread over r, g and b

float storedDepth(vec2 uv)
{
    vec3 texel = texture(shadowMap, uv).rgb;
    return packedDepth == 1 ? dot(texel, vec3(1.0, 1.0 / 255.0, 1.0 / 65025.0)) : texel.r;
}

void main()
{
    vec3 ndc = lightSpace.xyz / lightSpace.w;  // perspective divide
    vec3 shadowCoord = ndc * 0.5 + 0.5;        // [-1,1] -> [0,1]: s, t and the depth u
    shadowCoord.z = min(shadowCoord.z, 1.0);   // beyond the light's far plane: as far as can be stored
    float visibility = 1.0;
    if (lightSpace.w > 0.0)  // behind the light: lit
        visibility = shadowCoord.z <= storedDepth(shadowCoord.xy) + margin ? 1.0 : 0.0;
    gl_FragColor = shade(worldPosition, worldNormal, visibility, shadowCoord.z);
}
