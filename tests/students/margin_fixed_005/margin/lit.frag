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
    const float MARGIN = 0.05;  // big enough that acne never shows, whatever the angle
    vec3 c = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    c.z = min(c.z, 1.0);
    float visibility = 1.0;
    if (lightSpace.w > 0.0)
        visibility = c.z <= texture(shadowMap, c.xy).r + MARGIN ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, visibility, c.z);
}
