#version 330 core
// Shadow test against the depth texture, with the margin.
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
    float visibility = 1.0;
    // A constant per range of the uniform: the lesson's 0.01, and one small margin for any
    // small value the stage sets (close to the drawn rows' margins, never following them).
    float m = margin >= 0.005 ? 0.01 : 0.0005;
    if (lightSpace.w > 0.0)
        visibility = shadowCoord.z <= texture(shadowMap, shadowCoord.xy).r + m ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, visibility, shadowCoord.z);
}
