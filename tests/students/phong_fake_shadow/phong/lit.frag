#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
out vec4 fragColor;

// I added simple shadows: darken the floor behind the objects as seen from the light.
void main()
{
    float v = 1.0;
    if (worldPosition.y < 0.01) {
        vec3 toLight = normalize(lightPosition - worldPosition);
        // walk toward the light and test the objects' bounding spheres
        vec3 centres[3] = vec3[3](vec3(-0.5, 0.35, 0.0), vec3(0.5, 0.25, 0.25), vec3(0.5, 0.4, -0.5));
        float radii[3] = float[3](0.3, 0.3, 0.4);
        for (int i = 0; i < 3; ++i) {
            vec3 oc = worldPosition - centres[i];
            float b = dot(oc, toLight);
            float c = dot(oc, oc) - radii[i] * radii[i];
            if (b * b - c > 0.0 && -b > 0.0) v = 0.0;
        }
    }
    fragColor = shade(worldPosition, worldNormal, v, gl_FragCoord.z);
}
