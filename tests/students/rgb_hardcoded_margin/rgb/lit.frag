#version 330 core
// rgb stage - I added a margin so the acne goes away
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 lightSpace;

uniform sampler2D shadowMap;
uniform int packedDepth;
out vec4 fragColor;

const float EPS = 0.01;

void main()
{
    vec3 proj = lightSpace.xyz / lightSpace.w;
    proj = proj * 0.5 + 0.5;
    float zLight = min(proj.z, 1.0);
    vec3 c = texture(shadowMap, proj.xy).rgb;
    float mapZ = packedDepth == 1 ? c.r + c.g / 255.0 + c.b / 65025.0 : c.r;
    float visible = (lightSpace.w <= 0.0 || zLight <= mapZ + EPS) ? 1.0 : 0.0;
    fragColor = shade(worldPosition, worldNormal, visible, zLight);
}
