#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 mapPos;

uniform sampler2D shadowMap;
uniform float margin;
uniform int packedDepth;

void main()
{
    vec3 t = texture2DProj(shadowMap, mapPos).rgb;
    float nearestDepth = t.r;
    if (packedDepth == 1) nearestDepth = t.r + t.g / 255.0 + t.b / 65025.0;
    float myDepth = min(mapPos.z / mapPos.w, 1.0);
    float lightFactor = 1.0;
    if (mapPos.w > 0.0 && myDepth > nearestDepth + margin) lightFactor = 0.0;
    gl_FragColor = shade(worldPosition, worldNormal, lightFactor, myDepth);
}
