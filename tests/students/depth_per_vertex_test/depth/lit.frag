#version 330 core
#include "common/phong.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 lightSpace;
in float vertexVisibility;
out vec4 fragColor;

void main()
{
    fragColor = shade(worldPosition, worldNormal, vertexVisibility, lightSpace.z / lightSpace.w);
}
