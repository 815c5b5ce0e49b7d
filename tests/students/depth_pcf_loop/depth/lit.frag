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
    float z = min(c.z, 1.0);
    float visibility = 1.0;
    if (lightSpace.w > 0.0) {
        vec2 texel = 1.0 / vec2(textureSize(shadowMap, 0));
        float sum = 0.0;
        for (int y = -1; y <= 1; ++y)
            for (int x = -1; x <= 1; ++x) {
                float d = texture(shadowMap, c.xy + vec2(x, y) * texel).r;
                sum += (z <= d + margin) ? 1.0 : 0.0;
            }
        visibility = sum / 9.0;
    }
    fragColor = shade(worldPosition, worldNormal, visibility, c.z);
}
