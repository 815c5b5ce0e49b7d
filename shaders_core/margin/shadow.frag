#version 330 core
// The map is the 8-bit colour texture or a depth texture (parameter storage): write both the
// colour and the depth; the framebuffer keeps whichever it has.
out vec4 fragColor;

void main()
{
    float z = gl_FragCoord.z;
    fragColor = vec4(z, z, z, 1.0);
    gl_FragDepth = z;
}
