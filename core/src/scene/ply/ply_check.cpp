#include "scene/ply/ply_check.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "rad/util/error.hpp"
#include "scene/scene_limits.hpp"
#include "scene/text_file.hpp"

namespace rad {

namespace {

// OpenMesh's reader (9.0) reads only a subset of PLY faithfully. It takes the header word by word, skips an
// unknown property by one value even when it is a list, reads coordinates as float, cannot read double
// colours or list counts other than uchar, uint8, uint16 and int, and stores the colour of a face it could
// not add at index -1. Outside the subset it reads other bytes than those checked here, or writes out of
// bounds, so the header must keep to it: the checks below say where.

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
    std::size_t line = 0;  // of its declaration, for messages
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

bool is_double_type(const std::string& type) {
    return type == "double" || type == "float64";
}

// The values an integer type holds; OpenMesh reads an ASCII value that does not fit wrapped or not at all.
struct IntegerRange {
    double min = 0.0;
    double max = 0.0;
};

IntegerRange integer_range(const std::string& type) {
    if (type == "char" || type == "int8") return {-128.0, 127.0};
    if (type == "uchar" || type == "uint8") return {0.0, 255.0};
    if (type == "short" || type == "int16") return {-32768.0, 32767.0};
    if (type == "ushort" || type == "uint16") return {0.0, 65535.0};
    if (type == "int" || type == "int32") return {-2147483648.0, 2147483647.0};
    return {0.0, 4294967295.0};
}

bool is_one_of(std::string_view word, std::initializer_list<std::string_view> words) {
    return std::find(words.begin(), words.end(), word) != words.end();
}

// The vertex properties OpenMesh reads as float (in binary files only from float or double).
bool is_vertex_float(const Element& e, const Property& p) {
    return e.name == "vertex" && is_one_of(p.name, {"x", "y", "z", "nx", "ny", "nz", "u", "s", "v", "t"});
}
bool is_colour(const Element& e, const Property& p) {
    if (e.name == "vertex") {
        return is_one_of(p.name,
                         {"red", "green", "blue", "alpha", "diffuse_red", "diffuse_green", "diffuse_blue"});
    }
    return e.name == "face" && is_one_of(p.name, {"red", "green", "blue", "alpha"});
}
bool is_coordinate(const Element& e, const Property& p) {
    return e.name == "vertex" && is_one_of(p.name, {"x", "y", "z"});
}
bool is_face_indices(const Element& e, const Property& p) {
    return e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index");
}

[[noreturn]] void fail_at(const std::string& path, std::size_t line, const std::string& what) {
    throw InputError(path + ":" + std::to_string(line) + ": " + what);
}

// The fewest bytes an element can take in the body, so a count can be checked against the file's size.
double min_element_bytes(const Element& e, Format format) {
    if (format == Format::ascii) return 2.0 * static_cast<double>(e.properties.size());  // "0 " per value
    double bytes = 0.0;
    for (const Property& p : e.properties) {
        bytes += static_cast<double>(type_size(p.count_type.empty() ? p.type : p.count_type));
    }
    return bytes;
}

// OpenMesh takes the three words after "ply" as the format line, whatever they are, and loops for ever on
// a version it cannot read as a float.
Format parse_format(const std::string& path, std::size_t line, const std::vector<std::string_view>& words) {
    double version = 0.0;
    if (words[0] != "format" || words.size() != 3 || !parse_number(words[2], version) || version != 1.0) {
        fail_at(path, line,
                "the line after 'ply' must be 'format ascii|binary_little_endian|binary_big_endian 1.0'");
    }
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
    } else if (words.size() == 5 && words[1] == "list" && type_size(std::string(words[2])) > 0 &&
               type_size(std::string(words[3])) > 0 && !is_float_type(std::string(words[2]))) {
        p.count_type = words[2];
        p.type = words[3];
        p.name = words[4];
    } else {
        fail_at(path, line, "malformed property declaration");
    }
    // OpenMesh tells type from name by the type names, in either order.
    if (type_size(p.name) > 0) fail_at(path, line, "a property named '" + p.name + "', a type name");
    return p;
}

// The declarations OpenMesh reads as they are meant.
void check_declaration(const std::string& path, std::size_t line, const Element& e, const Property& p) {
    const bool list = !p.count_type.empty();
    if (is_face_indices(e, p)) {
        if (!list) fail_at(path, line, "'" + p.name + "' must be a list");
        if (!is_one_of(p.count_type, {"uchar", "uint8", "uint16", "int"})) {
            fail_at(path, line,
                    "list count type '" + p.count_type + "': OpenMesh reads uchar, uint8, uint16 or int");
        }
        if (is_float_type(p.type))
            fail_at(path, line, "vertex indices of type '" + p.type + "'; want an integer type");
        return;
    }
    if (list)
        fail_at(path, line,
                "list property '" + p.name + "': the only list read is the face's vertex_indices");
    if (is_vertex_float(e, p) && !is_float_type(p.type)) {
        fail_at(path, line,
                "vertex property '" + p.name + "' of type '" + p.type + "'; want float or double");
    }
    if (is_colour(e, p) && is_double_type(p.type)) {
        fail_at(path, line,
                "colour '" + p.name + "' of type '" + p.type + "'; want an integer type or float");
    }
}

// A line OpenMesh skips word by word, as unknown keywords: one of these words in it would start a declaration
// that this check does not see.
void check_skipped_line(const std::string& path, std::size_t line,
                        const std::vector<std::string_view>& words) {
    for (const std::string_view word : words) {
        if (is_one_of(word, {"element", "property", "end_header"})) {
            fail_at(path, line, "'" + std::string(word) + "' inside a '" + std::string(words[0]) + "' line");
        }
    }
}

// OpenMesh finds a binary body 12 bytes (14 with CRLF) after the last header word before end_header.
void check_binary_body_start(const std::string& path, std::size_t line, std::string_view header_text) {
    const auto ends_directly_with = [&](std::string_view tail) {
        return header_text.ends_with(tail) && header_text.size() > tail.size() &&
               !std::isspace(static_cast<unsigned char>(header_text[header_text.size() - tail.size() - 1]));
    };
    if (!ends_directly_with("\nend_header\n") && !ends_directly_with("\r\nend_header\r\n")) {
        fail_at(
            path, line,
            "in a binary PLY file 'end_header' must follow the last declaration on the next line, alone, and "
            "end with one newline");
    }
}

class HeaderParser {
  public:
    HeaderParser(const std::string& path, const std::string& bytes) : path_(path), bytes_(bytes) {}

    Header parse() {
        std::vector<std::string_view> words;
        if (!next_line(words) || words.size() != 1 || words[0] != "ply") {
            throw InputError(path_ + ": not a PLY file (it does not start with a line 'ply')");
        }
        bool more = next_line(words);
        while (more && words.empty()) more = next_line(words);
        if (!more) throw InputError(path_ + ": not a PLY file (no 'end_header')");
        header_.format = parse_format(path_, line_, words);
        while (next_line(words)) {
            if (words.empty() || words[0] == "comment") continue;
            if (words[0] == "end_header") return finish(words);
            declare(words);
        }
        throw InputError(path_ + ": not a PLY file (no 'end_header')");
    }

  private:
    bool next_line(std::vector<std::string_view>& words) {
        if (pos_ >= bytes_.size()) return false;
        const std::size_t end = std::min(bytes_.find('\n', pos_), bytes_.size());
        words = split_whitespace(std::string_view(bytes_.data() + pos_, end - pos_));
        pos_ = end + 1;
        ++line_;
        return true;
    }

    void declare(const std::vector<std::string_view>& words) {
        if (words[0] == "format") fail_at(path_, line_, "a second 'format' line");
        if (words[0] == "element") {
            long long count = 0;
            if (words.size() != 3 || !parse_integer(words[2], count) || count < 0) {
                fail_at(path_, line_, "malformed element declaration");
            }
            header_.elements.push_back({std::string(words[1]), static_cast<std::uint64_t>(count), {}, line_});
        } else if (words[0] == "property") {
            if (header_.elements.empty()) fail_at(path_, line_, "'property' before any 'element'");
            Element& element = header_.elements.back();
            element.properties.push_back(parse_property(path_, line_, words));
            check_declaration(path_, line_, element, element.properties.back());
        } else {
            check_skipped_line(path_, line_, words);
        }
    }

    Header finish(const std::vector<std::string_view>& words) {
        if (words.size() != 1) fail_at(path_, line_, "'end_header' must stand alone on its line");
        header_.body_offset = std::min(pos_, bytes_.size());
        header_.body_line = line_ + 1;
        if (header_.format != Format::ascii) {
            check_binary_body_start(path_, line_, std::string_view(bytes_).substr(0, header_.body_offset));
        }
        return header_;
    }

    const std::string& path_;
    const std::string& bytes_;
    std::size_t pos_ = 0;
    std::size_t line_ = 0;
    Header header_;
};

std::size_t count_named(const Element& e, bool (*matches)(const Element&, const Property&)) {
    return static_cast<std::size_t>(std::count_if(e.properties.begin(), e.properties.end(),
                                                  [&](const Property& p) { return matches(e, p); }));
}

// One vertex element with x, y and z, then one face element with one index list: OpenMesh adds vertices and
// faces in the order of the elements, and a face it cannot add gets its colour stored out of bounds.
void check_elements(const std::string& path, const Header& header) {
    bool seen_vertex = false;
    bool seen_face = false;
    for (const Element& e : header.elements) {
        if (e.count > 0 && e.properties.empty())
            fail_at(path, e.line, "element '" + e.name + "' has no properties");
        if (e.name == "vertex") {
            if (seen_vertex) fail_at(path, e.line, "a second 'vertex' element");
            for (const char* name : {"x", "y", "z"}) {
                const auto named = [name](const Property& p) { return p.name == name; };
                if (std::count_if(e.properties.begin(), e.properties.end(), named) != 1) {
                    fail_at(path, e.line,
                            std::string("the vertex element needs one property '") + name + "'");
                }
            }
            seen_vertex = true;
        } else if (e.name == "face") {
            if (seen_face) fail_at(path, e.line, "a second 'face' element");
            if (!seen_vertex) fail_at(path, e.line, "the face element comes before the vertex element");
            if (count_named(e, is_face_indices) != 1) {
                fail_at(path, e.line, "the face element needs one list 'vertex_indices'");
            }
            seen_face = true;
        }
    }
}

void check_limit(const std::string& path, const Element& e, std::size_t limit, const char* kind) {
    if (e.count > limit) {
        throw InputError(path + ": header declares " + std::to_string(e.count) + " " + kind +
                         "; the limit for one scene file is " + std::to_string(limit));
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
    bool degenerate_face = false;  // the face just read has fewer than 3 corners or a corner repeated
};

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
        if (format_ != Format::ascii) {
            element_start_ = pos_;
            return;
        }
        skip_blank_lines();
        element_start_ = pos_;
        if (pos_ >= bytes_.size()) fail("the file ends before " + where_);
        const std::size_t end = std::min(bytes_.find('\n', pos_), bytes_.size());
        words_ = split_whitespace(std::string_view(bytes_.data() + pos_, end - pos_));
        word_ = 0;
        pos_ = end + 1;
        ++line_;
    }
    void end_element() {
        if (format_ == Format::ascii && word_ != words_.size()) fail("more values than the header declares");
    }
    // The bytes of the element last begun, once it has been read.
    std::pair<std::size_t, std::size_t> element_span() const {
        return {element_start_, std::min(pos_, bytes_.size())};
    }

    double value(const std::string& type) {
        if (format_ != Format::ascii) return binary_value(type);
        if (word_ >= words_.size()) fail("fewer values than the header declares");
        const std::string_view w = words_[word_++];
        return is_float_type(type) ? ascii_number(w) : ascii_integer(w, type);
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
            if (!split_whitespace(std::string_view(bytes_.data() + pos_, end - pos_)).empty()) return;
            pos_ = end + 1;
            ++line_;
        }
    }

    double ascii_number(std::string_view w) const {
        double v = 0.0;
        if (!parse_number(w, v)) fail(bad_number_message(w));
        return v;
    }

    // Plain digits only: OpenMesh reads "1.0" or "1e2" as 1 and the rest as the next value.
    double ascii_integer(std::string_view w, const std::string& type) const {
        long long v = 0;
        if (!parse_integer(w, v)) fail("'" + std::string(w.substr(0, 40)) + "' is not an integer");
        const IntegerRange range = integer_range(type);
        if (static_cast<double>(v) < range.min || static_cast<double>(v) > range.max) {
            fail("'" + std::string(w) + "' does not fit the type " + type);
        }
        return static_cast<double>(v);
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
    std::size_t element_start_ = 0;
    std::vector<std::string_view> words_;
    std::size_t word_ = 0;
};

// OpenMesh reads floating-point values as float: beyond its range they become infinite, or in ASCII stop the
// stream; and it scales a float colour by 255 into an int.
void check_scalar(const BodyReader& body, const Element& e, const Property& p, double v) {
    const bool coordinate = is_coordinate(e, p);
    if (is_float_type(p.type)) {
        if (!std::isfinite(v)) body.fail((coordinate ? "coordinate " : "") + p.name + " is not finite");
        if (std::abs(v) > static_cast<double>(std::numeric_limits<float>::max())) {
            body.fail(p.name + " is beyond the range of float");
        }
    }
    if (coordinate && std::abs(v) > kMaxCoordinate) body.fail("coordinate " + p.name + " is beyond ±1e30");
    if (is_colour(e, p)) {
        const double max = is_float_type(p.type) ? 1.0 : 255.0;
        if (!(v >= 0.0 && v <= max)) {
            body.fail("colour " + p.name + " outside [0, " + (max == 1.0 ? "1]" : "255]"));
        }
    }
}

void check_face_indices(BodyReader& body, const Property& p, double count, Checks& checks) {
    // OpenMesh cannot add a face of fewer than 3 corners or with a corner repeated (see check_elements):
    // such faces are cut from the bytes it reads.
    checks.degenerate_face = count < 3;
    std::vector<double> corners;
    for (int i = 0; i < static_cast<int>(count); ++i) {
        const double v = body.value(p.type);
        if (!(v >= 0 && v < static_cast<double>(checks.vertex_count))) {
            body.fail("vertex index " + std::to_string(static_cast<long long>(v)) + " is out of range (" +
                      std::to_string(checks.vertex_count) + " vertices)");
        }
        corners.push_back(v);
    }
    std::sort(corners.begin(), corners.end());
    if (std::adjacent_find(corners.begin(), corners.end()) != corners.end()) checks.degenerate_face = true;
}

// The file's bytes without the faces at `spans` (in order), the header's face count lowered to match.
std::string without_faces(const std::string& bytes, const Header& header,
                          const std::vector<std::pair<std::size_t, std::size_t>>& spans) {
    const auto face = std::find_if(header.elements.begin(), header.elements.end(),
                                   [](const Element& e) { return e.name == "face"; });
    // The face element's declaration line (lines count from 1).
    std::size_t line_start = 0;
    for (std::size_t line = 1; line < face->line; ++line) line_start = bytes.find('\n', line_start) + 1;
    const std::size_t line_end = bytes.find('\n', line_start);
    std::string out = bytes.substr(0, line_start) + "element face " +
                      std::to_string(face->count - spans.size()) +
                      bytes.substr(line_end, header.body_offset - line_end);
    std::size_t from = header.body_offset;
    for (const auto& [begin, end] : spans) {
        out.append(bytes, from, begin - from);
        from = end;
    }
    out.append(bytes, from, std::string::npos);
    return out;
}

void check_property(BodyReader& body, const Element& e, const Property& p, Checks& checks) {
    if (p.count_type.empty()) {
        check_scalar(body, e, p, body.value(p.type));
        return;
    }
    // The only list check_declaration lets through: the face's corners.
    const double count = body.value(p.count_type);
    if (count < 0 || count > static_cast<double>(kMaxFaceCorners)) {
        body.fail("list '" + p.name + "' of " + std::to_string(static_cast<long long>(count)) +
                  " items; the limit is " + std::to_string(kMaxFaceCorners));
    }
    checks.face_corners += static_cast<std::size_t>(count);
    if (checks.face_corners > checks.max_face_corners) {
        body.fail("more than " + std::to_string(checks.max_face_corners) +
                  " face corners; the limit for one scene file");
    }
    check_face_indices(body, p, count, checks);
}

}  // namespace

PlyCheck check_ply(const std::string& path, const std::string& bytes, const SceneFileLimits& limits) {
    const Header header = HeaderParser(path, bytes).parse();
    check_elements(path, header);
    check_counts(path, header, bytes.size() - header.body_offset, limits);
    Checks checks;
    checks.max_face_corners = limits.face_corners;
    for (const Element& e : header.elements) {
        if (e.name == "vertex") checks.vertex_count = e.count;
    }
    BodyReader body(path, bytes, header);
    std::vector<std::pair<std::size_t, std::size_t>> degenerate;
    for (const Element& e : header.elements) {
        for (std::uint64_t i = 0; i < e.count; ++i) {
            body.begin_element(e.name, i);
            checks.degenerate_face = false;
            for (const Property& p : e.properties) check_property(body, e, p, checks);
            body.end_element();
            if (checks.degenerate_face) degenerate.push_back(body.element_span());
        }
    }
    body.expect_end();
    PlyCheck result;
    result.skipped_faces = degenerate.size();
    if (!degenerate.empty()) result.repaired = without_faces(bytes, header, degenerate);
    return result;
}

}  // namespace rad
