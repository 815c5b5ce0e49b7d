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
    vec3 c = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    float mapVal = texture(shadowMap, c.yx).r;
    float lit = (c.z <= mapVal + margin) ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, lit, c.z);
}
