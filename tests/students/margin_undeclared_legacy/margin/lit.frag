#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;

void main()
{
    vec3 sc = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    float v = sc.z <= texture2D(shadowMap, sc.xy).r + margin ? 1.0 : 0.0;
    gl_FragColor = shade(worldPosition, worldNormal, visibilty, sc.z);
}
