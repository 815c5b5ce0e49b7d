#version 330 core
// store a linear depth: better spread over the 256 levels than gl_FragCoord.z
in float lightDistance;
uniform int packedDepth;
out vec4 fragColor;

void main()
{
    float d = clamp(lightDistance / 4.0, 0.0, 1.0);
    fragColor = vec4(d, d, d, 1.0);
}
