#version 330 core
// With bias z = +0.5 (OpenGL's projection: near -> NDC -1) u runs 0 near .. 1 far, like the
// stored gl_FragCoord.z. With the slides' -0.5, u runs the other way unless the light's
// projection is flipped too (near -> NDC +1, glDepthRange(1, 0)).
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;

uniform sampler2D shadowMap;
uniform float margin;
out vec4 fragColor;

void main()
{
    vec3 stu = shadowCoord.xyz / shadowCoord.w;
    float visibility = 1.0;
    // BEGIN SOLUTION
    if (shadowCoord.w > 0.0)
        visibility = stu.z <= texture(shadowMap, stu.xy).r + margin ? 1.0 : 0.0;
    // END SOLUTION
    // STUB: // TODO: the shadow test in the map's own coordinates. shadowCoord went through the
    // STUB: // scale/bias matrix (shadowMatrix = bias * P_light * V_light * model, built on the CPU
    // STUB: // with the bias-z you set), so after the divide by w, stu.xy is where to look in
    // STUB: // shadowMap and stu.z the fragment's depth as the map stores it: visibility 0.0 where
    // STUB: // stu.z lies behind the stored depth plus `margin` (only where shadowCoord.w > 0.0).
    fragColor = shade(worldPosition, worldNormal, visibility, stu.z);
}
