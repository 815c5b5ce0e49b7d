#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;
uniform int packedDepth;
out vec4 fragColor;

float storedDepth(vec2 uv)
{
    vec3 texel = texture(shadowMap, uv).rgb;
    return packedDepth == 1 ? dot(texel, vec3(1.0, 1.0 / 255.0, 1.0 / 65025.0)) : texel.r;
}

void main()
{
    vec3 c = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    c.z = min(c.z, 1.0);
    vec2 cell = floor(c.xy * 128.0) / 128.0;  // snap to a cell so neighbouring pixels agree
    float visibility = 1.0;
    if (lightSpace.w > 0.0)
        visibility = c.z <= storedDepth(cell) + margin ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, visibility, c.z);
}
