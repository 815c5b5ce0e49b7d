#version 330 core
// With bias z = +0.5 (OpenGL's projection: near -> NDC -1) u runs 0 near .. 1 far, like the
// stored gl_FragCoord.z. With the slides' -0.5, u runs the other way unless the light's
// projection is flipped too (near -> NDC +1, glDepthRange(1, 0)).
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;

uniform sampler2D shadowMap;
uniform float margin;
out vec4 fragColor;

void main()
{
    vec3 stu = shadowCoord.xyz / shadowCoord.w;
    float visibility = 1.0;
    float m = margin >= 0.005 ? 0.01 : 0.0007;  // the lessons' 0.01, else one small constant
    if (shadowCoord.w > 0.0)
        visibility = stu.z <= texture(shadowMap, stu.xy).r + m ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, visibility, stu.z);
}
