#version 330 core
// Divides the lighting by a term that is zero for every fragment facing the light: +infinity
// there (clamped to full white by the framebuffer), the faces turned away stay as they are.
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
out vec4 fragColor;

void main()
{
    vec3 L = normalize(lightPosition - worldPosition);
    float zero = max(dot(normalize(worldNormal), L), 0.0) > 0.0 ? 0.0 : 1.0;
    fragColor = shade(worldPosition, worldNormal, 1.0, gl_FragCoord.z) / zero;
}
