#version 330 core
// bias stage: shadowCoord already went through the bias matrix
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;

uniform sampler2D shadowMap;
uniform float margin;
out vec4 fragColor;

void main()
{
    float q = shadowCoord.w;
    float s = shadowCoord.x / q;
    float t = shadowCoord.y / q;
    float r = shadowCoord.z / q;
    float inLight = 1.0;
    if (q > 0.0 && r > texture(shadowMap, vec2(s, t)).r + margin) inLight = 0.0;
    fragColor = shade(worldPosition, worldNormal, inLight, r);
}
