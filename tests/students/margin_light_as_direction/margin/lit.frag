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

float marginFor(vec3 N)
{
    if (marginKind == 0) return margin;
    vec3 L = normalize(lightPosition);  // the light's direction
    float cosTheta = clamp(dot(N, L), 0.001, 1.0);
    float tanTheta = sqrt(1.0 - cosTheta * cosTheta) / cosTheta;
    return clamp(slopeK * tanTheta, slopeMin, slopeMax);
}

void main()
{
    vec3 N = normalize(worldNormal);
    vec3 c = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    c.z = min(c.z, 1.0);
    float visibility = 1.0;
    if (lightSpace.w > 0.0)
        visibility = c.z <= texture(shadowMap, c.xy).r + marginFor(N) ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, visibility, c.z);
}
