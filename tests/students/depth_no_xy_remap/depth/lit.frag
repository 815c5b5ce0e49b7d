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
    vec3 ndc = lightSpace.xyz / lightSpace.w;
    float u = ndc.z * 0.5 + 0.5;          // depth to [0,1]
    float stored = texture(shadowMap, ndc.xy).r;   // forgot s,t are in [-1,1]
    float vis = u <= stored + margin ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, vis, u);
}
