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
    vec3 sc = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    float mapDepth = texture(shadowMap, sc.xy).a;   // the depth value
    float visibility = sc.z <= mapDepth + margin ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, visibility, sc.z);
}
