#version 330 core
// Patches carry linear radiance L = B / pi per vertex; the rasterizer interpolates it (smooth mode), or
// every vertex of a patch carries the patch's own value (flat mode). On a textured surface the vertex value
// is irradiance / pi instead, and the fragment multiplies it by the texel's albedo.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 radiance;
layout(location = 2) in vec2 texcoord;

uniform mat4 view_projection;

out vec3 vertex_radiance;
out vec2 vertex_texcoord;

void main() {
    vertex_radiance = radiance;
    vertex_texcoord = texcoord;
    gl_Position = view_projection * vec4(position, 1.0);
}
