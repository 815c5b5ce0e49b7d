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
    // BEGIN SOLUTION
    if (lightSpace.w > 0.0)
        visibility = shadowCoord.z <= texture2D(shadowMap, shadowCoord.xy).r + margin ? 1.0 : 0.0;
    // END SOLUTION
    // STUB: // TODO: the shadow test against the depth texture: visibility 0.0 where shadowCoord.z lies
    // STUB: // behind the stored depth (shadowMap's .r at shadowCoord.xy) plus `margin` (lightSpace.w > 0.0).
    gl_FragColor = shade(worldPosition, worldNormal, visibility, shadowCoord.z);
}
