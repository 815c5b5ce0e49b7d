#version 330 core
// Cg's saturate() (HLSL), which NVIDIA's GLSL compiler takes: GLSL has clamp(x, 0.0, 1.0).
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 lightSpace;

uniform sampler2D shadowMap;  // a depth texture: .r is the stored depth
uniform float margin;
out vec4 fragColor;

void main()
{
    vec3 ndc = lightSpace.xyz / lightSpace.w;
    vec3 shadowCoord = ndc * 0.5 + 0.5;
    shadowCoord.z = min(shadowCoord.z, 1.0);  // beyond the far plane: as far as can be stored
    float visibility = 1.0;
    if (lightSpace.w > 0.0)
        visibility = saturate(shadowCoord.z <= texture(shadowMap, shadowCoord.xy).r + margin ? 1.0 : 0.0);
    fragColor = shade(worldPosition, worldNormal, visibility, shadowCoord.z);
}
