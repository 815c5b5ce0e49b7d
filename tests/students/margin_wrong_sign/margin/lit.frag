#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 lightSpace;

uniform sampler2D shadowMap;
uniform int marginKind;
uniform float margin;
uniform float slopeK;
uniform float slopeMin;
uniform float slopeMax;
out vec4 fragColor;

void main()
{
    vec3 N = normalize(worldNormal);
    vec3 L = normalize(lightPosition - worldPosition);
    float c = clamp(dot(N, L), 0.001, 1.0);
    float eps = marginKind == 1 ? clamp(slopeK * sqrt(1.0 - c * c) / c, slopeMin, slopeMax) : margin;
    vec3 sc = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    sc.z = min(sc.z, 1.0);
    // move the fragment a bit toward the light... 
    float v = (lightSpace.w > 0.0 && sc.z + eps > texture(shadowMap, sc.xy).r) ? 0.0 : 1.0;
    fragColor = shade(worldPosition, worldNormal, v, sc.z);
}
