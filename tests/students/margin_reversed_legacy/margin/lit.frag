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
    vec3 sc = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    float eps = margin;
    if (marginKind == 1) {
        float c = clamp(dot(normalize(worldNormal), normalize(lightPosition - worldPosition)), 0.001, 1.0);
        eps = clamp(slopeK * sqrt(1.0 - c * c) / c, slopeMin, slopeMax);
    }
    float v = sc.z + eps < texture2D(shadowMap, sc.xy).r ? 0.0 : 1.0;
    gl_FragColor = shade(worldPosition, worldNormal, v, sc.z);
}
