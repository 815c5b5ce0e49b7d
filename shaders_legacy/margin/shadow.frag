#version 120
// The map is the 8-bit colour texture or a depth texture (parameter storage): write both the
// colour and the depth; the framebuffer keeps whichever it has.

void main()
{
    float z = gl_FragCoord.z;
    gl_FragColor = vec4(z, z, z, 1.0);
    gl_FragDepth = z;
}
