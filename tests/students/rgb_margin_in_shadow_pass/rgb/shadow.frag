#version 330 core
// Render-to-texture: each fragment's depth, gl_FragCoord.z (0 near .. 1 far), written as a
// colour into an 8-bit RGB texture. One 8-bit value has only 256 depth planes.
uniform int packedDepth;  // 0: the slides' single value; 1: spread over r, g and b
uniform float margin;     // push the stored depth back once, here, instead of per lookup
out vec4 fragColor;

// 24 bits: r holds the coarse part, g and b the next 8 bits each.
vec3 packDepth(float z)
{
    vec3 parts = fract(z * vec3(1.0, 255.0, 65025.0));
    parts.rg -= parts.gb / 255.0;
    return parts;
}

void main()
{
    float z = min(gl_FragCoord.z + margin, 1.0);
    fragColor = packedDepth == 1 ? vec4(packDepth(z), 1.0) : vec4(z, z, z, 1.0);
}
