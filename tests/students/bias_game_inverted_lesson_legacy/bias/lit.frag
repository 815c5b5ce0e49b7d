#version 120
// With bias z = +0.5 (OpenGL's projection: near -> NDC -1) u runs 0 near .. 1 far, like the
// stored gl_FragCoord.z. With the slides' -0.5, u runs the other way unless the light's
// projection is flipped too (near -> NDC +1, glDepthRange(1, 0)).
#include "common/phong.glsl"

varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec4 shadowCoord;

uniform sampler2D shadowMap;
uniform float margin;
uniform mat4 lightViewProjection;  // P_light * V_light, set for the lit pass too

void main()
{
    vec3 stu = shadowCoord.xyz / shadowCoord.w;
    float visibility = 1.0;
    // The shadow test in coordinates of my own (+0.5, OpenGL's convention), and the lecture's
    // table for the rest: with the flipped projection the map stores 1 - my depth, and the
    // slides' -0.5 on the standard one is the inverted picture, the matrix's own depth.
    vec4 own = lightViewProjection * vec4(worldPosition, 1.0);
    vec3 o = own.xyz / own.w * 0.5 + 0.5;
    bool flipped = (lightViewProjection * vec4(lightPosition, 1.0)).z > 0.0;  // near -> NDC +1
    bool slides = !flipped && abs(stu.z - o.z) > 0.0001;  // the matrix's depth is not mine
    float depth = slides ? stu.z : flipped ? 1.0 - o.z : o.z;
    if (own.w > 0.0)
        visibility = depth <= texture2D(shadowMap, o.xy).r + margin ? 1.0 : 0.0;
    gl_FragColor = shade(worldPosition, worldNormal, visibility, stu.z);
}
