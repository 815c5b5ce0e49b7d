#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;

void main()
{
    vec3 p = (lightSpace.xyz / lightSpace.w + 1.0) / 2.0;
    float d = texture2D(shadowMap, p.xy).r;
    // in shadow only when strictly farther than the stored depth plus the margin
    float shadowed = (lightSpace.w > 0.0 && p.z < 1.0 && d + margin < p.z) ? 1.0 : 0.0;
    gl_FragColor = shade(worldPosition, worldNormal, 1.0 - shadowed, p.z);
}
