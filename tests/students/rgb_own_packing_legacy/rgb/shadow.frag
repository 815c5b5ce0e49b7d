#version 120
// Depth into the colour map. Packed: red = whole 8-bit steps, green and blue the remainders.
uniform int packedDepth;

void main()
{
    float d = gl_FragCoord.z;
    if (packedDepth == 0) {
        gl_FragColor = vec4(d, d, d, 1.0);
        return;
    }
    float hi = floor(d * 255.0) / 255.0;
    float restA = (d - hi) * 255.0;                 // in [0,1)
    float mid = floor(restA * 255.0) / 255.0;
    float lo = (restA - mid) * 255.0;
    gl_FragColor = vec4(hi, mid, lo, 1.0);
}
