#include "rad/io/image_file.hpp"

#include "rad/io/output_path.hpp"

#include <stb_image.h>
#include <stb_image_write.h>
#include <tinyexr.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "rad/io/atomic_file.hpp"
#include "rad/util/error.hpp"
#include "rad/util/file_names.hpp"
#include "rad/util/srgb.hpp"

namespace rad {

namespace {

void write_png(const std::string& path, const Image& image, double exposure) {
    const float scale = static_cast<float>(std::exp2(exposure));
    std::vector<unsigned char> bytes(image.pixels.size() * 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            bytes[3 * i + c] = srgb_byte(image.pixels[i][c] * scale);
        }
    }
    if (!stbi_write_png(path.c_str(), image.width, image.height, 3, bytes.data(), image.width * 3)) {
        throw std::runtime_error(path + ": cannot write PNG");
    }
}

void write_exr(const std::string& path, const Image& image) {
    const char* error = nullptr;
    if (SaveEXR(&image.pixels[0].x, image.width, image.height, 3, 0, path.c_str(), &error) < 0) {
        const std::string why = error ? error : "unknown error";
        FreeEXRErrorMessage(error);
        throw std::runtime_error(path + ": cannot write EXR: " + why);
    }
}

// PFM: a three-line text header, then little-endian float RGB rows from the bottom row up.
void write_pfm(const std::string& path, const Image& image) {
    std::ofstream out(path, std::ios::binary);
    out << "PF\n" << image.width << ' ' << image.height << "\n-1.0\n";
    for (int y = image.height - 1; y >= 0; --y) {
        out.write(reinterpret_cast<const char*>(&image.pixels[image.index(0, y)]),
                  static_cast<std::streamsize>(image.width * sizeof(glm::vec3)));
    }
    if (!out) throw std::runtime_error(path + ": cannot write PFM");
}

Image read_pfm(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    Image image;
    double scale = 0.0;
    in >> magic >> image.width >> image.height >> scale;
    in.get();
    if (magic != "PF" || image.width <= 0 || image.height <= 0 || scale >= 0.0) {
        throw InputError(path + ": not a little-endian RGB PFM image");
    }
    // The header's size is checked against the file's before anything is allocated for it.
    std::error_code ec;
    const std::uintmax_t file_bytes = std::filesystem::file_size(path, ec);
    const double pixel_bytes = static_cast<double>(image.width) * image.height * sizeof(glm::vec3);
    if (ec || pixel_bytes > static_cast<double>(file_bytes)) {
        throw InputError(path + ": PFM header declares " + std::to_string(image.width) + "x" +
                         std::to_string(image.height) + " pixels, more than the file holds");
    }
    image.pixels.resize(image.pixel_count());
    for (int y = image.height - 1; y >= 0; --y) {
        in.read(reinterpret_cast<char*>(&image.pixels[image.index(0, y)]),
                static_cast<std::streamsize>(image.width * sizeof(glm::vec3)));
    }
    if (!in) throw InputError(path + ": truncated PFM image");
    return image;
}

Image read_png(const std::string& path) {
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 3);
    if (!data) throw InputError(path + ": cannot read PNG");
    Image image = filled_image(w, h);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        image.pixels[i] = glm::vec3(data[3 * i], data[3 * i + 1], data[3 * i + 2]) / 255.0f;
    }
    stbi_image_free(data);
    return image;
}

}  // namespace

void check_image_path(const std::string& path) {
    const std::string ext = lowercase_extension(path);
    if (ext != ".png" && ext != ".exr" && ext != ".pfm") {
        throw SettingError("image_path",
                           path + ": unknown image format '" + ext + "' (use .png, .exr or .pfm)");
    }
    require_output_folder("image_path", path);
}

void write_image(const std::string& path, const Image& image, double exposure) {
    check_image_path(path);
    const std::string ext = lowercase_extension(path);
    replace_file_atomically(path, [&](const std::filesystem::path& temporary_path) {
        const std::string temporary = temporary_path.string();
        if (ext == ".png") write_png(temporary, image, exposure);
        if (ext == ".exr") write_exr(temporary, image);
        if (ext == ".pfm") write_pfm(temporary, image);
    });
}

Image read_image(const std::string& path) {
    const std::string ext = lowercase_extension(path);
    if (ext == ".pfm") return read_pfm(path);
    if (ext == ".png") return read_png(path);
    throw InputError(path + ": can only read .pfm and .png images");
}

}  // namespace rad
