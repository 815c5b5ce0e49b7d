#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;
out vec4 fragColor;

void main()
{
    vec3 sc = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    ivec2 size = textureSize(shadowMap, 0);
    ivec2 texel = ivec2(sc.xy * vec2(size)) + ivec2(1, 1);   // off by one
    float stored = texelFetch(shadowMap, clamp(texel, ivec2(0), size - 1), 0).r;
    float v = (lightSpace.w <= 0.0 || min(sc.z, 1.0) <= stored + margin) ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, v, sc.z);
}
