#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 lightSpace;

uniform sampler2D shadowMap;
uniform int marginKind;
uniform float margin;
uniform float slopeK;
uniform float slopeMin;
uniform float slopeMax;

void main()
{
    vec3 nrm = normalize(worldNormal);
    vec3 dirL = normalize(lightPosition - worldPosition);
    float cosA = clamp(dot(nrm, dirL), 0.001, 1.0);
    float bias = margin;
    if (marginKind != 0) {
        float sinA = sqrt(1.0 - cosA * cosA);
        bias = min(max(slopeK * sinA / cosA, slopeMin), slopeMax);
    }
    vec3 q = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    float stored = texture2D(shadowMap, q.xy).r;
    float light = 1.0;
    if (lightSpace.w > 0.0 && q.z <= 1.0 && q.z > stored + bias) light = 0.0;
    gl_FragColor = shade(worldPosition, worldNormal, light, q.z);
}
