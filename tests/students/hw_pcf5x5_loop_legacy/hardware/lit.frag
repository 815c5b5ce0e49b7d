#version 120
// 5x5 percentage-closer filtering by hand: 25 hardware compares a texel apart, averaged.
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 shadowCoord;

uniform sampler2DShadow shadowMap;

const float TEXEL = 1.0 / 512.0;  // the map is 512 x 512

void main()
{
    vec3 p = shadowCoord.xyz / shadowCoord.w;
    float ref = min(p.z, 1.0);
    float visibility = 1.0;
    if (shadowCoord.w > 0.0) {
        float sum = 0.0;
        for (int y = -2; y <= 2; y++)
            for (int x = -2; x <= 2; x++)
                sum += shadow2D(shadowMap, vec3(p.xy + vec2(float(x), float(y)) * TEXEL, ref)).r;
        visibility = sum / 25.0;
    }
    gl_FragColor = shade(worldPosition, worldNormal, visibility, p.z);
}
