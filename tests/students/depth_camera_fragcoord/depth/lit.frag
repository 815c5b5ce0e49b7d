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
    vec2 st = lightSpace.xy / lightSpace.w * 0.5 + 0.5;
    // the fragment's depth, as in the shadow pass
    float z = gl_FragCoord.z;
    float visibility = 1.0;
    if (lightSpace.w > 0.0)
        visibility = z <= texture(shadowMap, st).r + margin ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, visibility, z);
}
