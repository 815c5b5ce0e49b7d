#version 120
// nothing to colour: only the depth attachment matters
void main()
{
    gl_FragDepth = gl_FragCoord.z;
}
