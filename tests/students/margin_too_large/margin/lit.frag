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

const float MARGIN = 0.1;   // big enough to be safe
void main()
{
    vec3 sc = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    sc.z = min(sc.z, 1.0);
    float v = (lightSpace.w > 0.0 && sc.z > texture(shadowMap, sc.xy).r + MARGIN) ? 0.0 : 1.0;
    fragColor = shade(worldPosition, worldNormal, v, sc.z);
}
