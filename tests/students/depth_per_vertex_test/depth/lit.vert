#version 330 core
// The shadow test done once per vertex and interpolated: cheaper than per fragment.
in vec3 position;
in vec3 normal;

uniform mat4 model;
uniform mat3 normalMatrix;
uniform mat4 view;
uniform mat4 projection;
uniform mat4 lightViewProjection;
uniform sampler2D shadowMap;
uniform float margin;

out vec3 worldPosition;
out vec3 worldNormal;
out vec4 lightSpace;
out float vertexVisibility;

void main()
{
    vec4 world = model * vec4(position, 1.0);
    worldPosition = world.xyz;
    worldNormal = normalMatrix * normal;
    lightSpace = lightViewProjection * world;
    vec3 c = lightSpace.xyz / lightSpace.w * 0.5 + 0.5;
    vertexVisibility = 1.0;
    if (lightSpace.w > 0.0 && c.z < 1.0)
        vertexVisibility = c.z <= textureLod(shadowMap, c.xy, 0.0).r + margin ? 1.0 : 0.0;
    gl_Position = projection * view * world;
}
