// The lit pass's vertex stage, shared by the three methods: world position and normal, and
// shadowCoord = bias * P_light * V_light * model * position (the map's [0,1] coordinates, times w).
in vec3 position;
in vec3 normal;

uniform mat4 model;
uniform mat3 normalMatrix;
uniform mat4 view;
uniform mat4 projection;
uniform mat4 shadowMatrix;

out vec3 worldPosition;
out vec3 worldNormal;
out vec4 shadowCoord;

void main()
{
    vec4 world = model * vec4(position, 1.0);
    worldPosition = world.xyz;
    worldNormal = normalMatrix * normal;
    shadowCoord = shadowMatrix * vec4(position, 1.0);
    gl_Position = projection * view * world;
}
