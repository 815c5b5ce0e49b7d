#version 330 core
// Slope margin grown as 1/cos(theta): the depth one texel spans on a tilted surface grows like that too.
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
    if (marginKind == 1)
        m = clamp(slopeK / max(dot(N, L), 0.01), slopeMin, slopeMax);
    vec3 q = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    float vis = 1.0;
    if (lightSpace.w > 0.0 && q.z < 1.0 && q.z > texture(shadowMap, q.xy).r + m)
        vis = 0.0;
    fragColor = shade(worldPosition, worldNormal, vis, q.z);
}
