#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 smCoord;

uniform sampler2D shadowMap;
uniform float margin;

void main()
{
    float visibility = 1.0;
    vec3 stu = smCoord.xyz / smCoord.w;
    if (smCoord.w > 0.0 && stu.z < 1.0) {
        if (texture2D(shadowMap, stu.xy).x + margin < stu.z) visibility = 0.0;
    }
    gl_FragColor = shade(worldPosition, worldNormal, visibility, stu.z);
}
