#version 330 core
// Patch edges, drawn over the shaded patches; line_colour is linear, encoded as patch.frag encodes.
uniform vec3 line_colour;
uniform bool encode_srgb;

out vec4 colour;

vec3 srgb_encode(vec3 linear) {
    vec3 c = clamp(linear, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

void main() {
    colour = vec4(encode_srgb ? srgb_encode(line_colour) : line_colour, 1.0);
}
