#version 120
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
out vec4 fragColor;

void main()
{
    fragColor = shade(worldPosition, worldNormal, 1.0, gl_FragCoord.z);
}
