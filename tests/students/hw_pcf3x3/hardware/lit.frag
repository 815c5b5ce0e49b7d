#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;

uniform sampler2DShadow shadowMap;
out vec4 fragColor;

// 3x3 percentage-closer filter by hand: nine hardware compares one texel apart, averaged.
float pcf(vec3 stu)
{
    vec2 texel = 1.0 / vec2(textureSize(shadowMap, 0));
    float sum = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            sum += texture(shadowMap, vec3(stu.xy + vec2(dx, dy) * texel, stu.z));
    return sum / 9.0;
}

void main()
{
    float w = shadowCoord.w;
    vec3 stu = shadowCoord.xyz / w;
    float light = w > 0.0 ? pcf(stu) : 1.0;
    fragColor = shade(worldPosition, worldNormal, light, stu.z);
}
