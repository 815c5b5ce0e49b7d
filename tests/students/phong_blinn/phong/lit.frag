#version 330 core
// Phong stage: plain lighting, no shadows yet. Written out instead of calling shade().
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
out vec4 fragColor;

void main()
{
    if (debugView != 0) { fragColor = vec4(1.0); return; }
    vec3 n = normalize(worldNormal);
    vec3 l = normalize(lightPosition - worldPosition);
    vec3 e = normalize(eyePosition - worldPosition);
    float lambert = max(dot(n, l), 0.0);
    float spec = 0.0;
    if (lambert > 0.0) spec = pow(max(dot(reflect(-l, n), e), 0.0), shininess);
    fragColor = vec4(objectColor * (ambient + diffuse * lambert) + specular * spec, 1.0);
}
