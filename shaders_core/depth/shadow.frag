#version 330 core
// The depth texture is the depth attachment: writing gl_FragDepth stores the fragment's depth
// with the texture's full precision (16, 24 or 32 bits), no colour needed.
void main()
{
    gl_FragDepth = gl_FragCoord.z;
}
