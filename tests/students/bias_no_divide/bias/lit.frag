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
    // s, t, r are in [0,1] after the bias matrix
    float stored = texture(shadowMap, shadowCoord.xy).r;
    float v = shadowCoord.z <= stored + margin ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, v, shadowCoord.z);
}
