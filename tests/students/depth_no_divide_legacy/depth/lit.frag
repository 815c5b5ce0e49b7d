#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;

void main()
{
    vec3 tex = 0.5 * lightSpace.xyz + vec3(0.5);
    float stored = texture2D(shadowMap, tex.xy).r;
    float visibility = 1.0;
    if (tex.z > stored + margin) visibility = 0.0;
    gl_FragColor = shade(worldPosition, worldNormal, visibility, tex.z);
}
