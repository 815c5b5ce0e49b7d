#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 shadowCoord;

uniform sampler2D shadowMap;
uniform float margin;

void main()
{
    float ref = shadowCoord.z / shadowCoord.w;
    float depthInMap = texture2DProj(shadowMap, shadowCoord).r;
    float f = 1.0;
    if (shadowCoord.w > 0.0 && ref - margin > depthInMap) f = 0.0;
    gl_FragColor = shade(worldPosition, worldNormal, f, ref);
}
