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
    vec3 sc = toShadowSpace(lightSpace);
    float v = sc.z <= texture(shadowMap, sc.xy).r + margin ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, v, sc.z);
}
