#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 texCoordL;

uniform sampler2D shadowMap;
uniform float margin;
out vec4 fragColor;

void main()
{
    float fragDepth = min(texCoordL.z / texCoordL.w, 1.0);
    float mapDepth = textureProj(shadowMap, texCoordL).r;   // divides s and t by q for me
    float v = (texCoordL.w <= 0.0 || fragDepth - margin <= mapDepth) ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, v, fragDepth);
}
