#version 330 core
// The mirror's colour from the texture. Worked out once on the lecture's picture (640x480):
// where the mirror's corners land on screen, and from them the matrix that takes a pixel back
// to its place on the mirror (s: 0..1 across, 0..1 up). No need for the corner coordinates.
in vec2 uv;

uniform sampler2D mirrorTexture;
uniform int useTexture;
uniform vec4 color;
uniform float reflectance;

out vec4 fragColor;

// pixel (x, y, 1) -> (s.x, s.y, 1) up to a scale, fitted to the corners (168.4, 323.7),
// (486.9, 339.4), (509.7, 457.0), (146.6, 445.2)
const mat3 screenToMirror = mat3(0.00449873294, -0.000697596826, -0.000295137119,
                                 0.000806633635, 0.014112697, 0.0017357939,
                                 -1.01877728, -4.45061144, 1.0);

void main()
{
    if (useTexture == 1) {
        vec3 q = screenToMirror * vec3(gl_FragCoord.xy, 1.0);
        vec2 s = q.xy / q.z;
        vec2 lookup = vec2(1.0 - s.x, s.y);  // the reflected camera sees the mirror from behind
        fragColor = vec4(reflectance * texture(mirrorTexture, lookup).rgb, 1.0);
    } else {
        fragColor = color;
    }
}
