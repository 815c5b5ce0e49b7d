#version 330 core
// uses none of the uniforms the stage sets (lightPosition, objectColor, ...): still renders
in vec3 worldPosition;
in vec3 worldNormal;
out vec4 fragColor;
void main()
{
    fragColor = vec4(normalize(worldNormal) * 0.5 + 0.5, 1.0);
}
