#version 330 core
// Own lighting: Blinn-Phong (half vector) with a sharper exponent, ambient kept in shadow.
uniform vec3 lightPosition;
uniform vec3 eyePosition;
uniform vec3 objectColor;
uniform float ambient;
uniform float diffuse;
uniform float specular;
uniform float shininess;
uniform int debugView;

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 lightSpace;

uniform sampler2D shadowMap;
uniform float margin;
out vec4 fragColor;

void main()
{
    vec3 c = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    float lit = 1.0;
    if (lightSpace.w > 0.0 && c.z < 1.0 && c.z - margin > texture(shadowMap, c.xy).r)
        lit = 0.0;
    if (debugView == 1) { fragColor = vec4(vec3(lit), 1.0); return; }
    if (debugView == 2) { fragColor = vec4(vec3(c.z), 1.0); return; }
    vec3 N = normalize(worldNormal);
    vec3 L = normalize(lightPosition - worldPosition);
    vec3 V = normalize(eyePosition - worldPosition);
    vec3 H = normalize(L + V);
    float lambert = max(dot(N, L), 0.0);
    float blinn = lambert > 0.0 ? pow(max(dot(N, H), 0.0), 4.0 * shininess) : 0.0;
    vec3 color = objectColor * ambient + lit * (objectColor * diffuse * lambert + vec3(specular * blinn));
    fragColor = vec4(color, 1.0);
}
