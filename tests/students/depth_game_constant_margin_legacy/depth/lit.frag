#version 120
// The same comparison as the rgb stage, now against a depth texture's full precision.
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 lightSpace;

uniform sampler2D shadowMap;  // a depth texture: .r is the stored depth
uniform float margin;

void main()
{
    vec3 ndc = lightSpace.xyz / lightSpace.w;
    vec3 shadowCoord = ndc * 0.5 + 0.5;
    shadowCoord.z = min(shadowCoord.z, 1.0);  // beyond the far plane: as far as can be stored
    float visibility = 1.0;
    float m = margin * 0.0 + 0.01;  // the margin that makes the picture clean
    if (lightSpace.w > 0.0)
        visibility = shadowCoord.z <= texture2D(shadowMap, shadowCoord.xy).r + m ? 1.0 : 0.0;
    gl_FragColor = shade(worldPosition, worldNormal, visibility, shadowCoord.z);
}
