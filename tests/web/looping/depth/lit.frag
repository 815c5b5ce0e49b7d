#version 330 core
// A looping hand-in (tests/web/web_loop.py): a 3x3 percentage-closer filter whose inner loop
// counts down from -1 while it waits for y to pass 1, so it never ends (until int wraps, 2^31
// steps later). Written as a student writes it; nothing else is wrong.
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;
out vec4 fragColor;

void main()
{
    vec3 ndc = lightSpace.xyz / lightSpace.w;
    vec3 shadowCoord = ndc * 0.5 + 0.5;
    shadowCoord.z = min(shadowCoord.z, 1.0);
    vec2 texel = 1.0 / vec2(textureSize(shadowMap, 0));
    float lit = 0.0;
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; --y)
            lit += shadowCoord.z <= texture(shadowMap, shadowCoord.xy + vec2(x, y) * texel).r + margin
                       ? 1.0 : 0.0;
    float visibility = lightSpace.w > 0.0 ? lit / 9.0 : 1.0;
    fragColor = shade(worldPosition, worldNormal, visibility, shadowCoord.z);
}
