#version 330 core
// Writes radiance scaled by 2^exposure. Offscreen targets are float and take exposure 0 (linear images
// are radiance in scene units); the window's sRGB framebuffer applies the display curve.
in vec3 vertex_radiance;

uniform float exposure_scale;

out vec4 colour;

void main() {
    colour = vec4(vertex_radiance * exposure_scale, 1.0);
}
