#version 120
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;

uniform sampler2D shadowMap;
uniform float margin;

void main()
{
    vec3 c = shadowCoord.xyz / shadowCoord.w;
    float v = c.z <= texture2D(shadowMap, c.xy).r + margin ? 1.0 : 0.0;
    gl_FragColor = shade(worldPosition, worldNormal, v, c.z);
}
