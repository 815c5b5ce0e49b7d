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
    if (lightSpace.w <= 0.0) {            // behind the light: nothing can shadow it
        fragColor = shade(worldPosition, worldNormal, 1.0, 0.0);
        return;
    }
    vec3 uvz = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    if (uvz.z >= 1.0) {                   // past the far plane: nothing stored is farther
        fragColor = shade(worldPosition, worldNormal, 1.0, 1.0);
        return;
    }
    float m = margin;
    if (marginKind == 1) {
        vec3 N = normalize(worldNormal);
        vec3 L = normalize(lightPosition - worldPosition);
        float c = max(dot(N, L), 0.001);
        m = clamp(slopeK * tan(acos(c)), slopeMin, slopeMax);
    }
    float stored = texture(shadowMap, uvz.xy).r;
    if (uvz.z > stored + m) {
        fragColor = shade(worldPosition, worldNormal, 0.0, uvz.z);
        return;
    }
    fragColor = shade(worldPosition, worldNormal, 1.0, uvz.z);
}
