#version 330 core
in float lightDistance;
out vec4 fragColor;

void main()
{
    fragColor = vec4(vec3(lightDistance), 1.0);
}
