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

// own lighting so the shadow can be applied where it matters
void main()
{
    vec3 N = normalize(worldNormal);
    vec3 L = normalize(lightPosition - worldPosition);
    vec3 V = normalize(eyePosition - worldPosition);
    float m = margin;
    if (marginKind == 1) {
        float c = clamp(dot(N, L), 0.001, 1.0);
        m = clamp(slopeK * sqrt(1.0 - c * c) / c, slopeMin, slopeMax);
    }
    vec3 sc = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    sc.z = min(sc.z, 1.0);
    float v = (lightSpace.w > 0.0 && sc.z > texture(shadowMap, sc.xy).r + m) ? 0.0 : 1.0;
    if (debugView == 1) { fragColor = vec4(vec3(v), 1.0); return; }
    if (debugView == 2) { fragColor = vec4(vec3(sc.z), 1.0); return; }
    float d = max(dot(N, L), 0.0);
    float sp = d > 0.0 ? pow(max(dot(reflect(-L, N), V), 0.0), shininess) : 0.0;
    vec3 col = objectColor * (ambient + diffuse * d) + vec3(v * specular * sp);
    fragColor = vec4(col, 1.0);
}
