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
    // margin as a fraction of the depth: the stored depth scaled up by 1 + margin
    if (lightSpace.w > 0.0 && c.z > texture(shadowMap, c.xy).r * (1.0 + margin))
        visibility = 0.0;
    fragColor = shade(worldPosition, worldNormal, visibility, c.z);
}
