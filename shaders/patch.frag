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
// The false-colour view (rad/display/false_colour.hpp): luminance efficacy · Y(L) in cd/m², its log10 mapped
// from false_low to false_high onto the stops, evenly spaced.
uniform bool false_colour;
uniform float false_efficacy;
uniform float false_low;
uniform float false_high;
uniform vec3 false_stops[6];

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
    if (false_colour) {
        float luminance = false_efficacy * dot(radiance, vec3(0.2126, 0.7152, 0.0722));
        float t = clamp((log(max(luminance, 1e-30)) / log(10.0) - false_low) / (false_high - false_low), 0.0, 1.0);
        float x = t * 5.0;
        int i = min(int(floor(x)), 4);
        value = mix(false_stops[i], false_stops[i + 1], x - float(i));
    }
    colour = vec4(encode_srgb ? srgb_encode(value) : value, 1.0);
}
