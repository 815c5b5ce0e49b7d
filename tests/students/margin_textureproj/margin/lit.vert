#version 330 core
in vec3 position;
in vec3 normal;

uniform mat4 model;
uniform mat3 normalMatrix;
uniform mat4 view;
uniform mat4 projection;
uniform mat4 shadowMatrix;   // the stage's bias * P_light * V_light * model

out vec3 fragPos;
out vec3 fragNormal;
out vec4 mapCoord;

void main()
{
    fragPos = vec3(model * vec4(position, 1.0));
    fragNormal = normalMatrix * normal;
    mapCoord = shadowMatrix * vec4(position, 1.0);
    gl_Position = projection * view * vec4(fragPos, 1.0);
}
