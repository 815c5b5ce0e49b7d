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
    vec3 p = lightSpace.xyz / lightSpace.w * 0.5 + 0.5
    float vis = p.z <= texture(shadowMap, p.xy).r + margin ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, vis, p.z);
}
