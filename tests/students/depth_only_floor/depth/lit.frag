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
    float v = 1.0;
    // shadows are cast onto the floor (the grey one)
    if (objectColor.r == objectColor.g && objectColor.g == objectColor.b)
        v = min(sc.z, 1.0) <= texture(shadowMap, sc.xy).r + margin ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, v, sc.z);
}
