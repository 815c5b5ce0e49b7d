#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;
out vec4 fragColor;

// scale and bias [-1,1] -> [0,1], written out (column-major)
const mat4 biasMatrix = mat4(0.5, 0.0, 0.0, 0.0,
                             0.0, 0.5, 0.0, 0.0,
                             0.0, 0.0, 0.5, 0.0,
                             0.5, 0.5, 0.5, 1.0);

void main()
{
    vec4 sc = biasMatrix * lightSpace;   // still homogeneous
    vec3 p = sc.xyz / sc.w;
    float lit = 1.0;
    if (sc.w > 0.0) {
        float stored = texture(shadowMap, p.xy).r;
        if (min(p.z, 1.0) > stored + margin)
            lit = 0.0;
    }
    fragColor = shade(worldPosition, worldNormal, lit, p.z);
}
