#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;
uniform int packedDepth;

float unpackDepth(vec3 c)
{
    return c.r + (c.g + c.b / 255.0) / 255.0;
}

void main()
{
    float seen = 1.0;
    vec3 n = lightSpace.xyz / lightSpace.w;
    vec3 tc = n * 0.5 + 0.5;
    tc.z = min(tc.z, 1.0);
    if (lightSpace.w > 0.0) {
        vec3 texel = texture2D(shadowMap, tc.xy).rgb;
        float z = packedDepth == 1 ? unpackDepth(texel) : texel.r;
        seen = tc.z > z + margin ? 0.0 : 1.0;
    }
    gl_FragColor = shade(worldPosition, worldNormal, seen, tc.z);
}
