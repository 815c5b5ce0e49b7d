#version 330 core
// Store the depth a little in front of the surface, to be safe.
uniform int packedDepth;
out vec4 fragColor;

void main()
{
    float d = gl_FragCoord.z - 0.005;
    if (packedDepth == 1) {
        vec3 enc = fract(d * vec3(1.0, 255.0, 65025.0));
        enc.rg -= enc.gb / 255.0;
        fragColor = vec4(enc, 1.0);
    } else {
        fragColor = vec4(d, d, d, 1.0);
    }
}
