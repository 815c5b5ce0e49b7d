#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
out vec4 fragColor;

void main()
{
    vec3 n = normalize(worldNormal);
    vec3 l = normalize(lightPosition - worldPosition);
    vec3 r = reflect(-l, n);
    vec3 v = normalize(eyePosition - worldPosition);
    float s = pow(max(dot(r, v), 0.0), shininess);
    fragColor = vec4(objectColor * ambient + vec3(specular * s), 1.0);
}
