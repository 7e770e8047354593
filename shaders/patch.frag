#version 330 core
// Writes radiance scaled by 2^exposure. Float targets take exposure 0 (linear images are radiance in scene
// units). For 8-bit display framebuffers (the viewer's window) encode_srgb writes the sRGB code of the
// clamped value itself, so a window without an sRGB framebuffer shows the same colours as the PNGs (and on
// llvmpipe a frame takes about a quarter less time than with the framebuffer's own encoding).
// A textured surface shows emitted_radiance + albedo_scale * texel * (irradiance / pi): the texture is sRGB,
// so sampling it gives linear texels.
in vec3 vertex_radiance;
in vec2 vertex_texcoord;

uniform float exposure_scale;
uniform bool encode_srgb;
uniform bool textured;
uniform sampler2D albedo_texture;
uniform vec3 albedo_scale;
uniform vec3 emitted_radiance;

out vec4 colour;

vec3 srgb_encode(vec3 linear) {
    vec3 c = clamp(linear, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

void main() {
    vec3 radiance = vertex_radiance;
    if (textured)
        radiance = emitted_radiance + albedo_scale * texture(albedo_texture, vertex_texcoord).rgb * radiance;
    vec3 value = radiance * exposure_scale;
    colour = vec4(encode_srgb ? srgb_encode(value) : value, 1.0);
}
