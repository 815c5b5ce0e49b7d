#version 330 core
// Shadow test against the 8-bit colour map: divide by w, scale and bias into [0,1], compare.
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;     // 0 in the slides' first attempt: acne
uniform int packedDepth;  // 1: the map holds depth spread over r, g and b
out vec4 fragColor;

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
    // packed: answer with a larger margin on the single 8-bit value instead of decoding
    float m = packedDepth == 1 ? 0.008 : margin;
    if (lightSpace.w > 0.0)
        visibility = shadowCoord.z <= texture(shadowMap, shadowCoord.xy).r + m ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, visibility, shadowCoord.z);
}
