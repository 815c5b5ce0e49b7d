#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;
out vec4 fragColor;

void main()
{
    vec3 c = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    c.z = min(c.z, 1.0);
    float visibility = 1.0;
    if (lightSpace.w > 0.0)
        visibility = c.z <= texture(shadowMap, c.xy).r + margin ? 1.0 : 0.0;
    // in shadow no light at all reaches the surface
    fragColor = vec4(shade(worldPosition, worldNormal, 1.0, c.z).rgb * visibility, 1.0);
}
