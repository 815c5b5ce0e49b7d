#version 330 core
// The same linear distance as the map stores, compared in the same units.
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;
out vec4 fragColor;

void main()
{
    vec2 st = lightSpace.xy / lightSpace.w * 0.5 + 0.5;
    float d = lightSpace.w / 5.0;
    float visibility = 1.0;
    if (lightSpace.w > 0.0)
        visibility = d <= texture(shadowMap, st).r + margin ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, visibility, d);
}
