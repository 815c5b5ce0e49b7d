#version 330 core
// The mirror's quad. Its texture coordinates are where its corners landed in the reflected
// camera's image. That camera looks straight at the mirror, so the mirror is parallel to its
// image plane and texture coordinates vary linearly across the mirror: interpolating the
// corners' values is exact. The left-right flip is in the corner values themselves.
in vec3 position;  // the unit quad, [-0.5, 0.5]^2 in z = 0

uniform mat4 model;  // unit quad -> the mirror (x along its right, y along its up)
uniform mat4 view;
uniform mat4 projection;
uniform vec2 cornerUv[4];  // bottom-left, bottom-right, top-right, top-left (seen from the front)

out vec2 uv;

void main()
{
    vec2 s = position.xy + 0.5;
    // BEGIN SOLUTION
    uv = mix(mix(cornerUv[0], cornerUv[1], s.x), mix(cornerUv[3], cornerUv[2], s.x), s.y);
    // END SOLUTION
    // STUB: // TODO: uv at this corner of the quad (s: (0,0) bottom-left .. (1,1) top-right),
    // STUB: // blended from the four cornerUv values (bilinear: mix along x, then along y).
    // STUB: uv = s;
    gl_Position = projection * view * model * vec4(position, 1.0);
}
