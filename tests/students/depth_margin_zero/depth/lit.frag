#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 lightSpace;

uniform sampler2D shadowMap;
out vec4 fragColor;

void main()
{
    vec3 sc = (lightSpace.xyz / lightSpace.w + 1.0) * 0.5;
    sc.z = min(sc.z, 1.0);
    float shadowed = sc.z > texture(shadowMap, sc.xy).r ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, 1.0 - shadowed, sc.z);
}
