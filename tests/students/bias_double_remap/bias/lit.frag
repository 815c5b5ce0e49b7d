#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;

uniform sampler2D shadowMap;
uniform float margin;
out vec4 fragColor;

void main()
{
    vec3 c = shadowCoord.xyz / shadowCoord.w;
    c = c * 0.5 + 0.5;                 // NDC -> texture space
    float stored = texture(shadowMap, c.xy).r;
    float lit = (shadowCoord.w > 0.0 && c.z > stored + margin) ? 0.0 : 1.0;
    fragColor = shade(worldPosition, worldNormal, lit, c.z);
}
