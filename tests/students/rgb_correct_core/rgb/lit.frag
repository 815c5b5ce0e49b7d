#version 330 core
// Student: Ana. Shadow test against the colour map.
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;
uniform int packedDepth;
out vec4 fragColor;

float readMap(vec2 st)
{
    vec4 c = texture(shadowMap, st);
    if (packedDepth == 0) return c.r;
    return c.r + c.g / 255.0 + c.b / (255.0 * 255.0);
}

void main()
{
    float lit = 1.0;
    float depthHere = 0.0;
    if (lightSpace.w > 0.0) {
        vec3 p = lightSpace.xyz / lightSpace.w;
        p = p * 0.5 + vec3(0.5);
        depthHere = min(p.z, 1.0);
        float nearest = readMap(p.xy);
        if (depthHere > nearest + margin) lit = 0.0;
    }
    fragColor = shade(worldPosition, worldNormal, lit, depthHere);
}
