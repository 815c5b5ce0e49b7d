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
    vec3 c = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    c.z = min(c.z, 1.0);
    float stored = texture2D(shadowMap, c.xy).r;
    if (packedDepth == 1) stored = dot(texture2D(shadowMap, c.xy).rgb, vec3(1.0, 1.0 / 255.0, 1.0 / 65025.0));
    float visibility = 1.0;
    if (lightSpace.w > 0.0)
        visibility = c.z + margin <= stored ? 1.0 : 0.0;  // keep a margin away from the stored depth
    gl_FragColor = shade(worldPosition, worldNormal, visibility, c.z);
}
