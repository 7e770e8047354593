#include "scene/obj/obj_syntax.hpp"

#include <algorithm>
#include <cmath>

#include "rad/util/error.hpp"
#include "scene/text_file.hpp"

namespace rad {

namespace {

std::string hex_byte(char c) {
    static constexpr char kDigits[] = "0123456789abcdef";
    const auto b = static_cast<unsigned char>(c);
    return std::string("0x") + kDigits[b >> 4] + kDigits[b & 0xf];
}

// Walks a text line by line, keeping the line number for messages.
class LineReader {
  public:
    LineReader(std::string_view text, const std::string& path) : text_(text), path_(path) {}

    bool next(std::string_view& line) {
        if (pos_ >= text_.size()) return false;
        // A line ends at "\n", "\r\n" or a lone "\r", as tinyobjloader reads it.
        const std::size_t end = std::min(text_.find_first_of("\r\n", pos_), text_.size());
        line = text_.substr(pos_, end - pos_);
        pos_ = end + (text_.substr(end, 2) == "\r\n" ? 2 : 1);
        ++number_;
        if (line.find('\0') != std::string_view::npos) fail("binary data; this is not a text file");
        // tinyobjloader separates words by spaces and tabs only, where std::isspace also takes vertical tabs
        // and form feeds: "v\v1 2 3" was a vertex to the check and nothing to tinyobjloader, so the check
        // let faces through that indexed past the vertices read.
        const auto control = std::find_if(line.begin(), line.end(), [](char c) {
            return static_cast<unsigned char>(c) < 0x20 && c != '\t';
        });
        if (control != line.end())
            fail("control character " + hex_byte(*control) + "; only spaces and tabs separate words");
        return true;
    }

    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(path_ + ":" + std::to_string(number_) + ": " + what);
    }
    std::size_t number() const { return number_; }

  private:
    std::string_view text_;
    const std::string& path_;
    std::size_t pos_ = 0;
    std::size_t number_ = 0;
};

double number_at(const LineReader& reader, std::string_view word) {
    double value = 0.0;
    if (!parse_number(word, value)) reader.fail(bad_number_message(word));
    return value;
}

void check_numbers(const LineReader& reader, const std::vector<std::string_view>& words, std::size_t min,
                   std::size_t max, bool must_be_finite) {
    const std::size_t count = words.size() - 1;
    if (count < min || count > max) {
        reader.fail("'" + std::string(words[0]) + "' needs " +
                    (min == max ? std::to_string(min) : std::to_string(min) + " to " + std::to_string(max)) +
                    " numbers, found " + std::to_string(count));
    }
    for (std::size_t i = 1; i < words.size(); ++i) {
        const double value = number_at(reader, words[i]);
        if (must_be_finite && !std::isfinite(value)) {
            reader.fail("coordinate " + quote_for_message(words[i]) + " is not a finite number");
        }
        if (must_be_finite && std::abs(value) > kMaxCoordinate) {
            reader.fail("coordinate " + quote_for_message(words[i]) + " is beyond ±1e30");
        }
    }
}

// One index of a face corner ("3", "-1"). A negative index counts back from the last one defined so far; a
// positive one may refer to a later line, as tinyobjloader resolves it against the whole file.
void check_index(const LineReader& reader, std::string_view word, std::size_t defined, std::size_t total,
                 const char* kind) {
    long long index = 0;
    if (!parse_integer(word, index))
        reader.fail("malformed " + std::string(kind) + " index " + quote_for_message(word));
    if (index < 0 && static_cast<long long>(defined) + index < 0) {
        reader.fail(std::string(kind) + " index " + std::to_string(index) + " is out of range (" +
                    std::to_string(defined) + " defined so far)");
    }
    if (index == 0 || index > static_cast<long long>(total)) {
        reader.fail(std::string(kind) + " index " + std::to_string(index) + " is out of range (" +
                    std::to_string(total) + " in the file)");
    }
}

struct ObjCounts {
    std::size_t v = 0, vt = 0, vn = 0, corners = 0;
};

// How many vertices, texture coordinates and normals the whole file defines, for its forward references.
ObjCounts count_definitions(std::string_view text, const std::string& path) {
    ObjCounts totals;
    LineReader reader(text, path);
    std::string_view line;
    while (reader.next(line)) {
        const std::vector<std::string_view> words = split_words(line);
        if (words.empty()) continue;
        if (words[0] == "v") ++totals.v;
        if (words[0] == "vt") ++totals.vt;
        if (words[0] == "vn") ++totals.vn;
    }
    return totals;
}

// Counts one more of `kind` and refuses the line that goes beyond `limit`, before tinyobjloader allocates.
void count_one(const LineReader& reader, std::size_t& count, std::size_t limit, const char* kind,
               std::size_t added = 1) {
    count += added;
    if (count > limit) {
        reader.fail("more than " + std::to_string(limit) + " " + kind + "; the limit for one scene file");
    }
}

void add_libraries(const LineReader& reader, const std::vector<std::string_view>& words, ObjFacts& facts) {
    if (words.size() < 2) reader.fail("'mtllib' needs a file name");
    for (std::size_t i = 1; i < words.size(); ++i) {
        const std::string name(words[i]);
        bool seen = false;
        for (const ObjLibrary& lib : facts.libraries) seen |= lib.name == name;
        if (seen) continue;
        if (facts.libraries.size() == kMaxMaterialLibraries) {
            reader.fail("more than " + std::to_string(kMaxMaterialLibraries) + " material libraries");
        }
        facts.libraries.push_back({name, reader.number()});
    }
}

// A face of fewer than 3 corners ("f 1 2", as some exporters write) is no error: tinyobjloader skips it and
// the loader counts it in a warning. Its indices must still exist.
void check_face(const LineReader& reader, const std::vector<std::string_view>& words, const ObjCounts& counts,
                const ObjCounts& totals) {
    if (words.size() - 1 > kMaxFaceCorners) {
        reader.fail("a face with " + std::to_string(words.size() - 1) + " corners; the limit is " +
                    std::to_string(kMaxFaceCorners));
    }
    for (std::size_t i = 1; i < words.size(); ++i) {
        const std::string_view corner = words[i];
        const std::size_t s1 = corner.find('/');
        const std::size_t s2 = s1 == std::string_view::npos ? s1 : corner.find('/', s1 + 1);
        check_index(reader, corner.substr(0, s1), counts.v, totals.v, "vertex");
        if (s1 == std::string_view::npos) continue;
        const std::string_view vt = corner.substr(s1 + 1, s2 == std::string_view::npos ? s2 : s2 - s1 - 1);
        if (!vt.empty()) check_index(reader, vt, counts.vt, totals.vt, "texture coordinate");
        if (s2 == std::string_view::npos) continue;
        const std::string_view vn = corner.substr(s2 + 1);
        if (vn.find('/') != std::string_view::npos)
            reader.fail("malformed face corner " + quote_for_message(corner));
        if (!vn.empty()) check_index(reader, vn, counts.vn, totals.vn, "normal");
    }
}

}  // namespace

ObjFacts check_obj_text(std::string_view text, const std::string& path, const SceneFileLimits& limits) {
    ObjFacts facts;
    ObjCounts counts;
    const ObjCounts totals = count_definitions(text, path);
    LineReader reader(text, path);
    std::string_view line;
    while (reader.next(line)) {
        const std::vector<std::string_view> words = split_words(line);
        if (words.empty()) continue;
        const std::string_view key = words[0];
        if (key == "v") {
            check_numbers(reader, words, 3, 7, true);
            count_one(reader, counts.v, limits.vertices, "vertices");
        } else if (key == "vt") {
            check_numbers(reader, words, 1, 3, false);
            count_one(reader, counts.vt, limits.vertices, "texture coordinates");
        } else if (key == "vn") {
            check_numbers(reader, words, 3, 3, false);
            count_one(reader, counts.vn, limits.vertices, "normals");
        } else if (key == "f") {
            const std::vector<std::string_view> corners =
                split_whitespace(line);  // tinyobjloader reads past '#'
            check_face(reader, corners, counts, totals);
            count_one(reader, facts.face_count, limits.faces, "faces");
            count_one(reader, counts.corners, limits.face_corners, "face corners", corners.size() - 1);
            if (corners.size() - 1 < 3) {
                ++facts.short_faces;
            } else {
                facts.face_corners.push_back(static_cast<std::uint32_t>(corners.size() - 1));
            }
        } else if (key == "mtllib") {
            add_libraries(reader, words, facts);
        } else if (key == "usemtl") {
            if (words.size() < 2) reader.fail("'usemtl' needs a material name");
        }
    }
    facts.vertex_count = counts.v;
    return facts;
}

std::map<std::string, std::size_t> check_mtl_text(std::string_view text, const std::string& path) {
    std::map<std::string, std::size_t> materials;
    LineReader reader(text, path);
    std::string_view line;
    bool in_material = false;
    while (reader.next(line)) {
        const std::vector<std::string_view> words = split_words(line);
        if (words.empty()) continue;
        const std::string_view key = words[0];
        if (key == "newmtl") {
            if (words.size() < 2) reader.fail("'newmtl' needs a material name");
            materials.emplace(std::string(words[1]), reader.number());
            in_material = true;
        } else if (key == "Kd" || key == "Ke") {
            if (!in_material) reader.fail("'" + std::string(key) + "' before any 'newmtl'");
            if (words.size() != 4) reader.fail("'" + std::string(key) + "' needs three numbers: r g b");
            // A reflectance of 1 and above is clamped later (ReflectanceClamps): files write white as Kd 1.
            const std::string what = key == "Kd" ? "reflectance (Kd) " : "emission (Ke) ";
            for (std::size_t i = 1; i < 4; ++i) {
                const double value = number_at(reader, words[i]);
                if (!(std::isfinite(value) && value >= 0.0))
                    reader.fail(what + quote_for_message(words[i]) + " must be finite and not negative");
            }
        }
    }
    return materials;
}

}  // namespace rad
