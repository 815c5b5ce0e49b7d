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
    float m = margin;
    if (marginKind == 1) {
        float c = clamp(dot(N, L), 0.001, 1.0);
        m = clamp(slopeK * sqrt(1.0 - c * c) / c, slopeMin, slopeMax);
    }
    vec3 sc = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    float stored = texture(shadowMap, sc.xy).r;
    int lit = int(stored + m - sc.z);    // positive -> in front -> lit
    fragColor = shade(worldPosition, worldNormal, float(lit), sc.z);
}
