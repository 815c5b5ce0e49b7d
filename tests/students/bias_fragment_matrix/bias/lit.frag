#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec3 objectPosition;

uniform mat4 shadowMatrix;   // bias * P_light * V_light * model
uniform sampler2D shadowMap;
uniform float margin;
out vec4 fragColor;

void main()
{
    vec4 h = shadowMatrix * vec4(objectPosition, 1.0);
    vec3 stp = h.xyz / h.w;
    float lightVis = (h.w > 0.0 && stp.z > texture(shadowMap, stp.xy).r + margin) ? 0.0 : 1.0;
    fragColor = shade(worldPosition, worldNormal, lightVis, stp.z);
}
