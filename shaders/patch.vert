#version 330 core
// Patches carry linear radiance L = B / pi per vertex; the rasterizer interpolates it (smooth mode), or
// every vertex of a patch carries the patch's own value (flat mode).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 radiance;

uniform mat4 view_projection;

out vec3 vertex_radiance;

void main() {
    vertex_radiance = radiance;
    gl_Position = view_projection * vec4(position, 1.0);
}
