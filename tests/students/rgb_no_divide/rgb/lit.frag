#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;
uniform int packedDepth;
out vec4 fragColor;

void main()
{
    // to texture space
    vec3 tc = lightSpace.xyz * 0.5 + 0.5;
    float z = clamp(tc.z, 0.0, 1.0);
    float m = texture(shadowMap, tc.xy).r;
    float v = z <= m + margin ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, v, z);
}
