#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;
uniform int packedDepth;

void main()
{
    vec3 n = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    vec3 t = texture2D(shadowMap, n.xy).rgb;
    float closest = packedDepth == 1 ? dot(t, vec3(1.0, 1.0 / 255.0, 1.0 / 65025.0)) : t.r;
    float inShadow = n.z + margin < closest ? 1.0 : 0.0;   // closer than the map -> shadow?
    gl_FragColor = shade(worldPosition, worldNormal, 1.0 - inShadow, min(n.z, 1.0));
}
