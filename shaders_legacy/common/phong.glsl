// Phong lighting shared by every stage's lit pass (included by the shader loader).
uniform vec3 lightPosition;
uniform vec3 eyePosition;
uniform vec3 objectColor;
uniform float ambient;
uniform float diffuse;
uniform float specular;
uniform float shininess;
uniform int debugView;  // 0 final, 1 visibility only, 2 the fragment's own light-space depth

// Ambient always; diffuse and specular scaled by how much light reaches the fragment
// (visibility: 1 lit, 0 shadowed, in between for filtered compares).
vec4 shade(vec3 P, vec3 N, float visibility, float lightDepth)
{
    if (debugView == 1) return vec4(vec3(visibility), 1.0);
    if (debugView == 2) return vec4(vec3(lightDepth), 1.0);  // the slides' gl_FragCoord.z picture
    N = normalize(N);
    vec3 L = normalize(lightPosition - P);
    vec3 V = normalize(eyePosition - P);
    vec3 R = reflect(-L, N);
    float NdotL = max(dot(N, L), 0.0);
    float highlight = NdotL > 0.0 ? pow(max(dot(R, V), 0.0), shininess) : 0.0;
    vec3 color = objectColor * (ambient + visibility * diffuse * NdotL)
               + vec3(visibility * specular * highlight);
    return vec4(color, 1.0);
}
