#include "ply_check.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "rad/error.hpp"
#include "scene_limits.hpp"
#include "text_file.hpp"

namespace rad {

namespace {

enum class Format { ascii, binary_little_endian, binary_big_endian };

struct Property {
    std::string name;
    std::string type;        // value type (for lists, of the items)
    std::string count_type;  // empty unless a list
};

struct Element {
    std::string name;
    std::uint64_t count = 0;
    std::vector<Property> properties;
};

struct Header {
    Format format = Format::ascii;
    std::vector<Element> elements;
    std::size_t body_offset = 0;  // first byte after "end_header\n"
    std::size_t body_line = 0;    // line number of the first body line (ASCII)
};

std::size_t type_size(const std::string& type) {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "int32" || type == "uint32") return 4;
    if (type == "float" || type == "float32") return 4;
    if (type == "double" || type == "float64") return 8;
    return 0;
}

bool is_float_type(const std::string& type) {
    return type == "float" || type == "float32" || type == "double" || type == "float64";
}

[[noreturn]] void fail_at(const std::string& path, std::size_t line, const std::string& what) {
    throw InputError(path + ":" + std::to_string(line) + ": " + what);
}

// The fewest bytes an element can take in the body, so a count can be checked against the file's size.
double min_element_bytes(const Element& e, Format format) {
    if (format == Format::ascii) return 2.0 * static_cast<double>(e.properties.size());  // "0 " per value
    double bytes = 0.0;
    for (const Property& p : e.properties)
        bytes += static_cast<double>(type_size(p.count_type.empty() ? p.type : p.count_type));
    return bytes;
}

Format parse_format(const std::string& path, std::size_t line, const std::vector<std::string_view>& words) {
    if (words.size() < 2)
        fail_at(path, line, "'format' needs ascii, binary_little_endian or binary_big_endian");
    if (words[1] == "ascii") return Format::ascii;
    if (words[1] == "binary_little_endian") return Format::binary_little_endian;
    if (words[1] == "binary_big_endian") return Format::binary_big_endian;
    fail_at(path, line, "unknown PLY format '" + std::string(words[1]) + "'");
}

Property parse_property(const std::string& path, std::size_t line,
                        const std::vector<std::string_view>& words) {
    Property p;
    if (words.size() == 3 && type_size(std::string(words[1])) > 0) {
        p.type = words[1];
        p.name = words[2];
        return p;
    }
    if (words.size() == 5 && words[1] == "list" && type_size(std::string(words[2])) > 0 &&
        type_size(std::string(words[3])) > 0 && !is_float_type(std::string(words[2]))) {
        p.count_type = words[2];
        p.type = words[3];
        p.name = words[4];
        return p;
    }
    fail_at(path, line, "malformed property declaration");
}

// OpenMesh reads faces against the vertices read before them, and one list of each.
void check_new_element(const std::string& path, std::size_t line, const Header& header,
                       std::string_view name) {
    bool has_vertex = false;
    for (const Element& e : header.elements) {
        if (e.name == name) fail_at(path, line, "a second '" + std::string(name) + "' element");
        has_vertex |= e.name == "vertex";
    }
    if (name == "face" && !has_vertex) fail_at(path, line, "'face' element before the 'vertex' element");
}

Header parse_header(const std::string& path, const std::string& bytes) {
    if (bytes.compare(0, 3, "ply") != 0)
        throw InputError(path + ": not a PLY file (it does not start with 'ply')");
    Header header;
    std::size_t pos = 0;
    std::size_t line = 0;
    bool ended = false;
    while (!ended && pos < bytes.size()) {
        const std::size_t end = std::min(bytes.find('\n', pos), bytes.size());
        const std::string_view text(bytes.data() + pos, end - pos);
        pos = end + 1;
        ++line;
        const std::vector<std::string_view> words = split_words(text);
        if (words.empty()) continue;
        if (words[0] == "format") {
            header.format = parse_format(path, line, words);
        } else if (words[0] == "element") {
            long long count = 0;
            if (words.size() != 3 || !parse_integer(words[2], count) || count < 0) {
                fail_at(path, line, "malformed element declaration");
            }
            check_new_element(path, line, header, words[1]);
            header.elements.push_back({std::string(words[1]), static_cast<std::uint64_t>(count), {}});
        } else if (words[0] == "property") {
            if (header.elements.empty()) fail_at(path, line, "'property' before any 'element'");
            header.elements.back().properties.push_back(parse_property(path, line, words));
        } else if (words[0] == "end_header") {
            ended = true;
        }
    }
    if (!ended) throw InputError(path + ": not a PLY file (no 'end_header')");
    header.body_offset = std::min(pos, bytes.size());
    header.body_line = line + 1;
    return header;
}

void check_limit(const std::string& path, const Element& e, std::size_t limit, const char* kind) {
    if (e.count > limit) {
        throw InputError(path + ": header declares " + std::to_string(e.count) + " " + kind +
                         "; the limit for one "
                         "scene file is " +
                         std::to_string(limit));
    }
}

void check_counts(const std::string& path, const Header& header, std::size_t body_bytes,
                  const SceneFileLimits& limits) {
    for (const Element& e : header.elements) {
        if (e.name == "vertex") check_limit(path, e, limits.vertices, "vertices");
        if (e.name == "face") check_limit(path, e, limits.faces, "faces");
        if (static_cast<double>(e.count) * min_element_bytes(e, header.format) >
            static_cast<double>(body_bytes)) {
            throw InputError(path + ": header declares " + std::to_string(e.count) + " '" + e.name +
                             "' elements, more than the file's " + std::to_string(body_bytes) +
                             " bytes of data can hold");
        }
    }
}

// What the checks need to know about a value as they walk the elements.
struct Checks {
    std::uint64_t vertex_count = 0;
    std::size_t face_corners = 0;  // so far
    std::size_t max_face_corners = 0;
};

bool is_coordinate(const Element& e, const Property& p) {
    return e.name == "vertex" && (p.name == "x" || p.name == "y" || p.name == "z");
}
bool is_face_index_list(const Element& e, const Property& p) {
    return e.name == "face" && !p.count_type.empty() &&
           (p.name == "vertex_indices" || p.name == "vertex_index");
}

// Reads values from the body: whitespace-separated words (ASCII) or fixed-size binary fields.
class BodyReader {
  public:
    BodyReader(const std::string& path, const std::string& bytes, const Header& header)
        : path_(path),
          bytes_(bytes),
          format_(header.format),
          pos_(header.body_offset),
          line_(header.body_line) {}

    // Starts element `index` of `name`: in ASCII, one element is one line.
    void begin_element(const std::string& name, std::uint64_t index) {
        where_ = name + " " + std::to_string(index);
        if (format_ != Format::ascii) return;
        skip_blank_lines();
        if (pos_ >= bytes_.size()) fail("the file ends before " + where_);
        const std::size_t end = std::min(bytes_.find('\n', pos_), bytes_.size());
        words_ = split_words(std::string_view(bytes_.data() + pos_, end - pos_));
        word_ = 0;
        pos_ = end + 1;
        ++line_;
    }
    void end_element() {
        if (format_ == Format::ascii && word_ != words_.size()) fail("more values than the header declares");
    }

    double value(const std::string& type) {
        if (format_ == Format::ascii) {
            if (word_ >= words_.size()) fail("fewer values than the header declares");
            double v = 0.0;
            const std::string_view w = words_[word_++];
            if (!parse_number(w, v)) fail(bad_number_message(w));
            if (!is_float_type(type) && v != std::floor(v))
                fail("'" + std::string(w) + "' is not an integer");
            return v;
        }
        return binary_value(type);
    }

    [[noreturn]] void fail(const std::string& what) const {
        if (format_ == Format::ascii) fail_at(path_, line_ - 1, what);
        throw InputError(path_ + ": " + where_ + ": " + what);
    }

    void expect_end() {
        if (format_ == Format::ascii) skip_blank_lines();
        if (pos_ < bytes_.size() && format_ == Format::ascii)
            fail_at(path_, line_, "data after the last element");
    }

  private:
    void skip_blank_lines() {
        while (pos_ < bytes_.size()) {
            const std::size_t end = std::min(bytes_.find('\n', pos_), bytes_.size());
            if (!split_words(std::string_view(bytes_.data() + pos_, end - pos_)).empty()) return;
            pos_ = end + 1;
            ++line_;
        }
    }

    double binary_value(const std::string& type) {
        const std::size_t size = type_size(type);
        if (pos_ + size > bytes_.size()) fail("the file ends inside " + where_);
        unsigned char raw[8];
        std::memcpy(raw, bytes_.data() + pos_, size);
        pos_ += size;
        const bool swap = (format_ == Format::binary_big_endian) != (std::endian::native == std::endian::big);
        if (swap) std::reverse(raw, raw + size);
        return decode(raw, type);
    }

    static double decode(const unsigned char* raw, const std::string& t) {
        auto as = [raw]<typename T>(T) {
            T v;
            std::memcpy(&v, raw, sizeof v);
            return static_cast<double>(v);
        };
        if (t == "char" || t == "int8") return as(std::int8_t{});
        if (t == "uchar" || t == "uint8") return as(std::uint8_t{});
        if (t == "short" || t == "int16") return as(std::int16_t{});
        if (t == "ushort" || t == "uint16") return as(std::uint16_t{});
        if (t == "int" || t == "int32") return as(std::int32_t{});
        if (t == "uint" || t == "uint32") return as(std::uint32_t{});
        if (t == "float" || t == "float32") return as(float{});
        return as(double{});
    }

    const std::string& path_;
    const std::string& bytes_;
    Format format_;
    std::size_t pos_;
    std::size_t line_;
    std::string where_;
    std::vector<std::string_view> words_;
    std::size_t word_ = 0;
};

void check_property(BodyReader& body, const Element& e, const Property& p, Checks& checks) {
    if (p.count_type.empty()) {
        const double v = body.value(p.type);
        if (is_coordinate(e, p) && !std::isfinite(v)) body.fail("coordinate " + p.name + " is not finite");
        return;
    }
    const double count = body.value(p.count_type);
    if (count < 0 || count > static_cast<double>(kMaxFaceCorners)) {
        body.fail("list '" + p.name + "' of " + std::to_string(static_cast<long long>(count)) +
                  " items; the limit is " + std::to_string(kMaxFaceCorners));
    }
    if (is_face_index_list(e, p)) {
        checks.face_corners += static_cast<std::size_t>(count);
        if (checks.face_corners > checks.max_face_corners) {
            body.fail("more than " + std::to_string(checks.max_face_corners) +
                      " face corners; the limit for one scene file");
        }
    }
    for (int i = 0; i < static_cast<int>(count); ++i) {
        const double v = body.value(p.type);
        if (is_face_index_list(e, p) && !(v >= 0 && v < static_cast<double>(checks.vertex_count))) {
            body.fail("vertex index " + std::to_string(static_cast<long long>(v)) + " is out of range (" +
                      std::to_string(checks.vertex_count) + " vertices)");
        }
    }
}

}  // namespace

void check_ply(const std::string& path, const std::string& bytes, const SceneFileLimits& limits) {
    const Header header = parse_header(path, bytes);
    check_counts(path, header, bytes.size() - header.body_offset, limits);
    Checks checks;
    checks.max_face_corners = limits.face_corners;
    for (const Element& e : header.elements) {
        if (e.name == "vertex") checks.vertex_count = e.count;
    }
    BodyReader body(path, bytes, header);
    for (const Element& e : header.elements) {
        for (std::uint64_t i = 0; i < e.count; ++i) {
            body.begin_element(e.name, i);
            for (const Property& p : e.properties) check_property(body, e, p, checks);
            body.end_element();
        }
    }
    body.expect_end();
}

}  // namespace rad
