#include "rad/scene/builtin_scenes.hpp"

#include <initializer_list>
#include <numbers>

#include "furnace_name.hpp"
#include "rad/scene/polygon_soup.hpp"
#include "rad/util/error.hpp"

namespace rad {

namespace {

// Collects named groups of polygons given by their corner positions, corners shared within a group.
class SoupWriter {
  public:
    explicit SoupWriter(std::string source) { soup_.source = std::move(source); }

    void begin_surface(const std::string& name, const Material& material) {
        soup_.groups.push_back({name, material});
        first_vertex_of_group_ = soup_.positions.size();
    }

    void add_polygon(std::initializer_list<glm::dvec3> corners) {
        PolygonSoup::Polygon polygon;
        polygon.group = static_cast<std::uint32_t>(soup_.groups.size() - 1);
        for (const glm::dvec3& p : corners) polygon.vertices.push_back(vertex(p));
        soup_.polygons.push_back(std::move(polygon));
    }

    Scene build() { return build_scene(soup_); }

  private:
    std::uint32_t vertex(const glm::dvec3& p) {
        for (std::size_t i = first_vertex_of_group_; i < soup_.positions.size(); ++i) {
            if (soup_.positions[i] == p) return static_cast<std::uint32_t>(i);
        }
        soup_.positions.push_back(p);
        return static_cast<std::uint32_t>(soup_.positions.size() - 1);
    }

    PolygonSoup soup_;
    std::size_t first_vertex_of_group_ = 0;
};

Material make_material(std::string name, glm::dvec3 reflectance, glm::dvec3 emission = glm::dvec3(0.0)) {
    return Material{std::move(name), reflectance, emission};
}

// Emitted radiance that gives an emitted radiosity E = 1.
const glm::dvec3 kUnitRadiosityLe(1.0 / std::numbers::pi);

void add_cornell_ceiling(SoupWriter& w, const Material& white) {
    // The ceiling with the light's opening cut out, as the 3 x 3 grid of rectangles around the opening minus
    // its centre: the eight share corners, so the ceiling stays a conforming mesh.
    const double xs[4] = {556.0, 343.0, 213.0, 0.0};
    const double zs[4] = {0.0, 227.0, 332.0, 559.2};
    const double y = 548.8;
    w.begin_surface("ceiling", white);
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k) {
            if (i == 1 && k == 1) continue;
            w.add_polygon(
                {{xs[i], y, zs[k]}, {xs[i], y, zs[k + 1]}, {xs[i + 1], y, zs[k + 1]}, {xs[i + 1], y, zs[k]}});
        }
    }
}

void add_cornell_blocks(SoupWriter& w, const Material& white) {
    w.begin_surface("short block", white);
    w.add_polygon({{130, 165, 65}, {82, 165, 225}, {240, 165, 272}, {290, 165, 114}});
    w.add_polygon({{290, 0, 114}, {290, 165, 114}, {240, 165, 272}, {240, 0, 272}});
    w.add_polygon({{130, 0, 65}, {130, 165, 65}, {290, 165, 114}, {290, 0, 114}});
    w.add_polygon({{82, 0, 225}, {82, 165, 225}, {130, 165, 65}, {130, 0, 65}});
    w.add_polygon({{240, 0, 272}, {240, 165, 272}, {82, 165, 225}, {82, 0, 225}});

    w.begin_surface("tall block", white);
    w.add_polygon({{423, 330, 247}, {265, 330, 296}, {314, 330, 456}, {472, 330, 406}});
    w.add_polygon({{423, 0, 247}, {423, 330, 247}, {472, 330, 406}, {472, 0, 406}});
    w.add_polygon({{472, 0, 406}, {472, 330, 406}, {314, 330, 456}, {314, 0, 456}});
    w.add_polygon({{314, 0, 456}, {314, 330, 456}, {265, 330, 296}, {265, 0, 296}});
    w.add_polygon({{265, 0, 296}, {265, 330, 296}, {423, 330, 247}, {423, 0, 247}});
}

// The Cornell box's materials, or one white for every surface but the light.
struct CornellMaterials {
    Material white, red, green, light;
};

// The Cornell PCG geometry; `closed` adds a front wall, so no light leaves.
Scene make_cornell_geometry(const std::string& source, const CornellMaterials& m, bool closed) {
    SoupWriter w(source);
    w.begin_surface("floor", m.white);
    w.add_polygon({{552.8, 0, 0}, {0, 0, 0}, {0, 0, 559.2}, {549.6, 0, 559.2}});
    add_cornell_ceiling(w, m.white);
    w.begin_surface("light", m.light);
    w.add_polygon(
        {{343.0, 548.8, 227.0}, {343.0, 548.8, 332.0}, {213.0, 548.8, 332.0}, {213.0, 548.8, 227.0}});
    w.begin_surface("back wall", m.white);
    w.add_polygon({{549.6, 0, 559.2}, {0, 0, 559.2}, {0, 548.8, 559.2}, {556.0, 548.8, 559.2}});
    w.begin_surface("right wall", m.green);
    w.add_polygon({{0, 0, 559.2}, {0, 0, 0}, {0, 548.8, 0}, {0, 548.8, 559.2}});
    w.begin_surface("left wall", m.red);
    w.add_polygon({{552.8, 0, 0}, {549.6, 0, 559.2}, {556.0, 548.8, 559.2}, {556.0, 548.8, 0}});
    if (closed) {
        w.begin_surface("front wall", m.white);
        w.add_polygon({{0, 0, 0}, {552.8, 0, 0}, {556.0, 548.8, 0}, {0, 548.8, 0}});
    }
    add_cornell_blocks(w, m.white);
    return w.build();
}

// The published light; `dimming` scales its emission.
Material cornell_light(double dimming = 1.0) {
    return make_material("light", {0.78, 0.78, 0.78}, dimming * glm::dvec3{17.0, 12.0, 4.0});
}

}  // namespace

const std::vector<BuiltinSceneInfo>& builtin_scenes() {
    static const std::vector<BuiltinSceneInfo> scenes = {
        {"cornell",
         "the Cornell box (Cornell PCG data, millimetres), the light's opening cut out of the ceiling"},
        {"white-room",
         "the Cornell box closed by a front wall, every surface white with reflectance 0.95, the light "
         "dimmed tenfold: a high-albedo closed scene, seen from inside"},
        {"cube",
         "a closed unit cube seen from inside; the top face emits E = 1, every face has reflectance 0.5"},
        {"parallel",
         "two unit squares facing each other at distance 1; the lower emits E = 1, reflectance 0.5"},
        {"perpendicular", "two unit squares sharing an edge at a right angle; the floor emits E = 1"},
        {"furnace",
         "a closed unit room of tessellated balls, about 10 k faces (furnace-N for N faces, 1k to 10m: "
         "furnace-100k, furnace-1m), every face with reflectance 0.5 and E = 1: a furnace, B = E / (1 - "
         "reflectance) = 2 on every face"},
        {"many-lights",
         "the Cornell box lit by 12 x 12 lamps of 20 mm hanging under its whole ceiling instead of its "
         "light, "
         "with the light's power: many small emitter patches"},
    };
    return scenes;
}

Scene make_builtin_scene(const std::string& name) {
    if (name == "cornell") return make_cornell_box();
    if (name == "white-room") return make_white_room();
    if (name == "cube") return make_cube();
    if (name == "parallel") return make_parallel_squares();
    if (name == "perpendicular") return make_perpendicular_squares();
    if (name == "furnace") return make_furnace(kFurnaceDefaultFaces);
    if (name == "many-lights") return make_many_lights_box();
    if (name.starts_with("furnace-")) {
        Scene scene = make_furnace(furnace_faces(name));
        scene.source = "builtin:" + name;  // as it was asked for: furnace-100k, not furnace-100000
        return scene;
    }
    std::string known;
    for (const auto& s : builtin_scenes()) known += (known.empty() ? "" : ", ") + s.name;
    throw InputError("builtin:" + name + ": no such built-in scene (available: " + known + ", furnace-N)");
}

Scene make_cornell_box() {
    const CornellMaterials materials{make_material("white", {0.725, 0.71, 0.68}),
                                     make_material("red", {0.63, 0.065, 0.05}),
                                     make_material("green", {0.14, 0.45, 0.091}), cornell_light()};
    Scene scene = make_cornell_geometry("builtin:cornell", materials, false);
    // 35 mm lens on 25 mm film: a vertical field of view of 2 atan(12.5 / 35).
    scene.camera = Camera{{278, 273, -800}, {278, 273, 0}, {0, 1, 0}, 39.3077};
    return scene;
}

Scene make_many_lights_box() {
    const Material white = make_material("white", {0.725, 0.71, 0.68});
    const Material published = cornell_light();
    SoupWriter w("builtin:many-lights");
    w.begin_surface("floor", white);
    w.add_polygon({{552.8, 0, 0}, {0, 0, 0}, {0, 0, 559.2}, {549.6, 0, 559.2}});
    w.begin_surface("ceiling", white);
    w.add_polygon({{556.0, 548.8, 0}, {556.0, 548.8, 559.2}, {0, 548.8, 559.2}, {0, 548.8, 0}});
    // The published light's power (130 x 105 mm) spread over the lamps, each facing down 10 mm under the
    // ceiling.
    const int lamps = 12;
    const double side = 20.0, y = 538.8;
    const double scale = 130.0 * 105.0 / (lamps * lamps * side * side);
    w.begin_surface("lamps", make_material("lamp", published.reflectance, scale * published.emission));
    for (int i = 0; i < lamps; ++i) {
        for (int k = 0; k < lamps; ++k) {
            const double x = 60.0 + (436.0 - side) * i / (lamps - 1),
                         z = 60.0 + (440.0 - side) * k / (lamps - 1);
            w.add_polygon({{x + side, y, z}, {x + side, y, z + side}, {x, y, z + side}, {x, y, z}});
        }
    }
    w.begin_surface("back wall", white);
    w.add_polygon({{549.6, 0, 559.2}, {0, 0, 559.2}, {0, 548.8, 559.2}, {556.0, 548.8, 559.2}});
    w.begin_surface("right wall", make_material("green", {0.14, 0.45, 0.091}));
    w.add_polygon({{0, 0, 559.2}, {0, 0, 0}, {0, 548.8, 0}, {0, 548.8, 559.2}});
    w.begin_surface("left wall", make_material("red", {0.63, 0.065, 0.05}));
    w.add_polygon({{552.8, 0, 0}, {549.6, 0, 559.2}, {556.0, 548.8, 559.2}, {556.0, 548.8, 0}});
    add_cornell_blocks(w, white);
    Scene scene = w.build();
    scene.camera = Camera{{278, 273, -800}, {278, 273, 0}, {0, 1, 0}, 39.3077};
    return scene;
}

Scene make_white_room() {
    const Material white = make_material("white", glm::dvec3(0.95));
    // Light bounces about 20 times before it is absorbed, so the light is dimmed tenfold to keep the walls'
    // radiance near the open box's.
    Scene scene =
        make_cornell_geometry("builtin:white-room", {white, white, white, cornell_light(0.1)}, true);
    // Inside, just behind the front wall, seeing the back wall, the blocks and the light.
    scene.camera = Camera{{278, 273, 30}, {278, 273, 559.2}, {0, 1, 0}, 70.0};
    return scene;
}

Scene make_cube() {
    const Material wall = make_material("wall", glm::dvec3(0.5));
    const Material emitter = make_material("emitter", glm::dvec3(0.5), kUnitRadiosityLe);
    SoupWriter w("builtin:cube");
    // Each face counter-clockwise seen from inside the cube.
    w.begin_surface("top", emitter);
    w.add_polygon({{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}});
    w.begin_surface("bottom", wall);
    w.add_polygon({{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}});
    w.begin_surface("left", wall);
    w.add_polygon({{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}});
    w.begin_surface("right", wall);
    w.add_polygon({{1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}});
    w.begin_surface("back", wall);
    w.add_polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    w.begin_surface("front", wall);
    w.add_polygon({{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}});
    Scene scene = w.build();
    scene.camera = Camera{{0.5, 0.5, 0.999}, {0.5, 0.5, 0.0}, {0, 1, 0}, 90.0};
    return scene;
}

Scene make_parallel_squares() {
    SoupWriter w("builtin:parallel");
    w.begin_surface("lower", make_material("emitter", glm::dvec3(0.5), kUnitRadiosityLe));
    w.add_polygon({{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}});
    w.begin_surface("upper", make_material("reflector", glm::dvec3(0.5)));
    w.add_polygon({{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}});
    Scene scene = w.build();
    scene.camera = Camera{{0.5, 0.5, 3.0}, {0.5, 0.5, 0.5}, {0, 1, 0}, 45.0};
    return scene;
}

Scene make_perpendicular_squares() {
    SoupWriter w("builtin:perpendicular");
    // Floor y = 0 facing +y and wall x = 0 facing +x, sharing the edge x = y = 0, z in [0, 1].
    w.begin_surface("floor", make_material("emitter", glm::dvec3(0.5), kUnitRadiosityLe));
    w.add_polygon({{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}});
    w.begin_surface("wall", make_material("reflector", glm::dvec3(0.5)));
    w.add_polygon({{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}});
    Scene scene = w.build();
    scene.camera = Camera{{2.5, 1.5, 2.5}, {0.3, 0.3, 0.5}, {0, 1, 0}, 45.0};
    return scene;
}

}  // namespace rad
