#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 shadowCoord;

uniform sampler2D shadowMap;
uniform float margin;

void main()
{
    vec3 stu = shadowCoord.xyz / shadowCoord.w;
    float visibility = 1.0;
    if (shadowCoord.w > 0.0)
        visibility = stu.z <= texture2D(shadowMap, vec2(stu.y, stu.x)).r + margin ? 1.0 : 0.0;
    gl_FragColor = shade(worldPosition, worldNormal, visibility, stu.z);
}
