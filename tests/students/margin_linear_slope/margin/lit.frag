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

// My slope formula: grows linearly as the light gets more grazing.
//   m = max(slopeMax * (1 - N.L), slopeMin)
void main()
{
    vec3 N = normalize(worldNormal);
    vec3 L = normalize(lightPosition - worldPosition);
    float ndl = clamp(dot(N, L), 0.0, 1.0);
    float m = margin;
    if (marginKind == 1) m = max(slopeMax * (1.0 - ndl), slopeMin);

    vec4 proj = lightSpace / lightSpace.w;
    vec2 uv = proj.xy * 0.5 + 0.5;
    float fragZ = min(proj.z * 0.5 + 0.5, 1.0);
    float vis = 1.0;
    if (lightSpace.w > 0.0 && fragZ > texture(shadowMap, uv).r + m) vis = 0.0;
    fragColor = shade(worldPosition, worldNormal, vis, fragZ);
}
