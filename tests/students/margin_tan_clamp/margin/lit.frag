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

// Slope-scaled margin: k * tan(theta), theta the angle between N and L, kept in [min, max].
float offsetFor(float cosine)
{
    float c = max(cosine, 1e-3);
    float t = tan(acos(min(c, 1.0)));
    return clamp(slopeK * t, slopeMin, slopeMax);
}

void main()
{
    vec3 n = normalize(worldNormal);
    vec3 toLight = normalize(lightPosition - worldPosition);
    float eps = (marginKind == 1) ? offsetFor(dot(n, toLight)) : margin;

    vec3 texc = 0.5 + 0.5 * (lightSpace.xyz / lightSpace.w);
    texc.z = min(texc.z, 1.0);
    bool shadowed = lightSpace.w > 0.0 && texc.z - eps > texture(shadowMap, texc.xy).r;
    fragColor = shade(worldPosition, worldNormal, shadowed ? 0.0 : 1.0, texc.z);
}
