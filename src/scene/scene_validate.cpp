// A JSON value to a Scene (the second half of reading a scene): every field
// checked against what the engine of this version relies on. Every fault is
// collected, each with its pointer, and reported at once in document order,
// so a scene with three mistakes needs one run, not three.

#include "scene/scene_validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include <fmt/format.h>

#include "geometry/unit_normal.hpp"
#include "math/vec3.hpp"
#include "scene/json_pointer.hpp"
#include "scene/scene_hints.hpp"
#include "trace/messages.hpp"
#include "util/interrupt.hpp"
#include "util/printable.hpp"

namespace promyk::scene_detail {

namespace {

constexpr std::size_t max_name_chars = 200;
// A material's exponent n (Phong's shininess): a whole number in this range.
constexpr int min_exponent = 1;
constexpr int max_exponent = 10000;

// One fault, thrown by a check and caught where the reading can go on
// (the next field, the next element).
struct Fault {
    std::string where, what;
};

// Thrown when max_collected_faults are found: the reading stops.
struct Enough {};

std::string number(double value) { return fmt::format("{}", value); }

// "1 element", "2 elements"; in Polish 1 element, 2–4 elementy, 5 elementów.
std::string element_count(std::size_t n) {
    const std::size_t last = n % 10, tens = n % 100 / 10;
    const char* form = n == 1                                    ? "scene_elements_one"
                       : last >= 2 && last <= 4 && tens != 1      ? "scene_elements_few"
                                                                  : "scene_elements_many";
    return ui_message(form, {{"n", std::to_string(n)}});
}

class SceneReader {
public:
    explicit SceneReader(const ParsedJson& parsed) : parsed_(parsed) {}

    // Reads what it can of every field, each fault recorded; the caller
    // reports them. A root that is not an object stops at once.
    Scene read(const Json& root) {
        if (!root.is_object()) fail("", ui_message("scene_not_object", {{"example", "{...}"}, {"type", type_of(root)}}));
        check_keys("", scene_level());

        Scene scene;
        if (const auto it = root.find("name"); it != root.end()) attempt([&] { scene.name = read_name(*it, "/name"); });
        if (const auto it = root.find("z_E"); it != root.end()) attempt([&] {
                scene.z_E = read_length(*it, "/z_E", "z_E");
                if (!(scene.z_E > 0)) fail("/z_E", ui_message("scene_z_E", {{"value", number(scene.z_E)}}));
            });
        if (const auto it = root.find("background"); it != root.end())
            attempt([&] { scene.background = read_background(*it); });
        if (const auto it = root.find("shadows"); it != root.end()) attempt([&] {
                if (!it->is_boolean()) fail("/shadows", ui_message("scene_shadows", {{"type", type_of(*it)}}));
                scene.shadows = it->get<bool>();
            });
        // Every element is read (a faulty one as far as it goes), so that the
        // objects' material indices are checked against the file's count.
        if (const Json* materials = find_array(root, "materials", "scene_nouns_materials"))
            for (std::size_t k = 0; k < materials->size(); ++k)
                scene.materials.push_back(read_material((*materials)[k], child("/materials", k)));
        const Json* spheres = find_array(root, "spheres", "scene_nouns_spheres");
        if (spheres)
            for (std::size_t k = 0; k < spheres->size(); ++k)
                scene.spheres.push_back(read_sphere((*spheres)[k], child("/spheres", k), scene.materials.size()));
        const Json* planes = find_array(root, "planes", "scene_nouns_planes");
        if (planes)
            for (std::size_t k = 0; k < planes->size(); ++k)
                scene.planes.push_back(read_plane((*planes)[k], child("/planes", k), scene.materials.size()));
        // "No objects" only when no object was written: a faulty one was reported.
        const bool objects_written = (spheres && !spheres->empty()) || (planes && !planes->empty()) ||
                                     (!spheres && root.contains("spheres")) || (!planes && root.contains("planes"));
        if (!objects_written) attempt([&] { fail("/spheres", ui_message("scene_no_objects")); });
        attempt([&] {
            const Json* lights = find_array(root, "lights", "scene_nouns_lights");
            if (!lights && !root.contains("lights"))
                fail("/lights", ui_message("scene_missing_key",
                                           {{"key", "lights"}, {"meaning", ui_message("scene_meaning_lights")}}));
            if (lights && lights->empty()) fail("/lights", ui_message("scene_no_lights"));
            if (lights)
                for (std::size_t k = 0; k < lights->size(); ++k)
                    scene.lights.push_back(read_light((*lights)[k], child("/lights", k)));
        });
        return scene;
    }

    std::vector<SceneFault>& faults() { return faults_; }

private:
    [[noreturn]] static void fail(const std::string& where, const std::string& what) { throw Fault{where, what}; }

    // Runs one check; a fault is recorded and the reading goes on.
    template <class Check>
    bool attempt(Check&& check) {
        try {
            check();
            return true;
        } catch (const Fault& fault) {
            faults_.push_back({printable(fault.where), printable(fault.what)});
            if (faults_.size() + parsed_.faults.size() >= max_collected_faults) throw Enough{};
            return false;
        }
    }

    static std::string type_of(const Json& value) {
        return ui_message(value.is_number()    ? "scene_type_number"
                          : value.is_object()  ? "scene_type_object"
                          : value.is_array()   ? "scene_type_array"
                          : value.is_string()  ? "scene_type_string"
                          : value.is_boolean() ? "scene_type_boolean"
                                               : "scene_type_null");
    }

    // Every unknown key of the object, in file order, as the parser recorded them.
    void check_keys(const std::string& pointer, const Level& level) {
        const auto it = parsed_.unknown_keys.find(pointer);
        if (it == parsed_.unknown_keys.end()) return;
        for (const std::string& key : it->second)
            attempt([&] {
                fail(child(pointer, key), ui_message("scene_unknown_key",
                                                     {{"key", shown_key(key)}, {"hint", unknown_key_hint(key, level)}}));
            });
    }

    // A number other than 0 smaller than min_scene_magnitude: refused.
    static void require_not_tiny(double x, const std::string& pointer, std::string_view what) {
        if (x != 0 && std::fabs(x) < min_scene_magnitude)
            fail(pointer, ui_message("scene_tiny", {{"what", std::string(what)},
                                                    {"value", number(x)},
                                                    {"limit", number(min_scene_magnitude)}}));
    }

    // A length (z_E, r): a finite number, not tiny.
    static double read_length(const Json& value, const std::string& pointer, std::string_view what) {
        const double x = read_number(value, pointer, what);
        require_not_tiny(x, pointer, what);
        return x;
    }

    // A position (S, Q, L): three finite numbers, none tiny.
    static Vec3d read_position(const Json& value, const std::string& pointer, std::string_view what) {
        const Vec3d p = read_vec3(value, pointer, what);
        static const char* axes[3] = {"x", "y", "z"};
        const double xyz[3] = {p.x, p.y, p.z};
        for (std::size_t k = 0; k < 3; ++k)
            require_not_tiny(xyz[k], child(pointer, k), fmt::format("{}[{}] ({})", what, k, axes[k]));
        return p;
    }

    static double read_number(const Json& value, const std::string& pointer, std::string_view what) {
        if (!value.is_number())
            fail(pointer, ui_message("scene_number", {{"what", std::string(what)}, {"type", type_of(value)}}));
        const double x = value.get<double>();
        if (!std::isfinite(x)) fail(pointer, ui_message("scene_finite", {{"what", std::string(what)}, {"value", number(x)}}));
        return x;
    }

    // Three numbers: a point or vector [x, y, z] or a colour [r, g, b].
    static Vec3d read_triple(const Json& value, const std::string& pointer, std::string_view what,
                             const std::string& form, const std::string (&names)[3]) {
        if (!value.is_array())
            fail(pointer, ui_message("scene_triple_type",
                                     {{"what", std::string(what)}, {"form", form}, {"type", type_of(value)}}));
        if (value.size() != 3)
            fail(pointer, ui_message("scene_triple_size",
                                     {{"what", std::string(what)}, {"form", form}, {"count", element_count(value.size())}}));
        double xyz[3];
        for (std::size_t k = 0; k < 3; ++k)
            xyz[k] = read_number(value[k], child(pointer, k), fmt::format("{}[{}] ({})", what, k, names[k]));
        return {xyz[0], xyz[1], xyz[2]};
    }

    static Vec3d read_vec3(const Json& value, const std::string& pointer, std::string_view what) {
        static const std::string axes[3] = {"x", "y", "z"};
        return read_triple(value, pointer, what, ui_message("scene_form_point"), axes);
    }

    // [r, g, b], each channel from 0 to 1.
    static Colour read_colour(const Json& value, const std::string& pointer, std::string_view what) {
        const std::string channels[3] = {ui_message("scene_channel_red"), ui_message("scene_channel_green"),
                                         ui_message("scene_channel_blue")};
        const Colour colour = read_triple(value, pointer, what, ui_message("scene_form_colour"), channels);
        const double rgb[3] = {colour.x, colour.y, colour.z};
        for (std::size_t k = 0; k < 3; ++k)
            if (!(rgb[k] >= 0 && rgb[k] <= 1))
                fail(child(pointer, k), ui_message("scene_channel_range", {{"what", std::string(what)},
                                                                          {"k", std::to_string(k)},
                                                                          {"channel", channels[k]},
                                                                          {"value", number(rgb[k])}}));
        return colour;
    }

    // A grey level (a number) or a colour [r, g, b].
    static Colour read_background(const Json& value) {
        if (value.is_array()) return read_colour(value, "/background", "background");
        if (!value.is_number()) fail("/background", ui_message("scene_background_type", {{"type", type_of(value)}}));
        const double grey = read_number(value, "/background", "background");
        if (!(grey >= 0 && grey <= 1))
            fail("/background", ui_message("scene_background_range", {{"value", number(grey)}}));
        return {grey, grey, grey};
    }

    static std::string read_name(const Json& value, const std::string& pointer) {
        if (!value.is_string()) fail(pointer, ui_message("scene_name_type", {{"type", type_of(value)}}));
        const std::string& name = value.get_ref<const std::string&>();
        if (name.empty()) fail(pointer, ui_message("scene_name_empty"));
        std::size_t chars = 0;
        for (std::size_t k = 0; k < name.size();) {  // valid UTF-8: nlohmann checked it
            const auto lead = static_cast<unsigned char>(name[k]);
            std::size_t length = lead < 0x80u ? 1 : lead < 0xE0u ? 2 : lead < 0xF0u ? 3 : 4;
            std::uint32_t code = length == 1   ? lead
                                 : length == 2 ? (lead & 0x1Fu)
                                 : length == 3 ? (lead & 0x0Fu)
                                               : (lead & 0x07u);
            for (std::size_t m = 1; m < length && k + m < name.size(); ++m)
                code = (code << 6) | (static_cast<unsigned char>(name[k + m]) & 0x3Fu);
            if (code < 0x20u || (code >= 0x7Fu && code <= 0x9Fu))
                fail(pointer, ui_message("scene_name_control",
                                         {{"code", fmt::format("{:04X}", code)}, {"at", std::to_string(chars + 1)}}));
            k += length;
            ++chars;
        }
        if (chars > max_name_chars)
            fail(pointer, ui_message("scene_name_long",
                                     {{"chars", std::to_string(chars)}, {"max", std::to_string(max_name_chars)}}));
        return name;
    }

    // One of the top level's arrays; nullptr when the key is absent or is
    // not an array (a fault, recorded).
    const Json* find_array(const Json& root, const char* key, const char* nouns_id) {
        const auto it = root.find(key);
        if (it == root.end()) return nullptr;
        if (!it->is_array()) {
            attempt([&] {
                fail(child("", key), ui_message("scene_array_of", {{"key", key},
                                                                   {"nouns", ui_message(nouns_id)},
                                                                   {"type", type_of(*it)}}));
            });
            return nullptr;
        }
        return &*it;
    }

    static const Json& require(const Json& object, const char* key, const std::string& pointer) {
        const auto it = object.find(key);
        if (it == object.end())
            fail(child(pointer, key),
                 ui_message("scene_missing_key", {{"key", key}, {"meaning", ui_message(std::string("scene_meaning_") + key)}}));
        return *it;
    }

    // An element of spheres, planes, lights or materials: an object (else
    // nothing more of it is read) whose unknown keys are recorded.
    bool check_element(const Json& value, const std::string& pointer, const Level& level, const char* example) {
        throw_if_interrupted();  // once an element: a scene may hold thousands
        const bool object = attempt([&] {
            if (!value.is_object())
                fail(pointer, ui_message("scene_element_" + std::string(level.id),
                                         {{"example", example}, {"type", type_of(value)}}));
        });
        if (object) check_keys(pointer, level);
        return object;
    }

    // An object's "material": the index of an element of "materials".
    static int read_material_index(const Json& object, const std::string& pointer, std::size_t materials) {
        const auto it = object.find("material");
        if (it == object.end()) return no_material;
        const std::string where = child(pointer, "material");
        const std::string meaning = ui_message("scene_material_meaning");
        if (!it->is_number()) fail(where, ui_message("scene_material_type", {{"meaning", meaning}, {"type", type_of(*it)}}));
        const double index = read_number(*it, where, "material");
        if (std::floor(index) != index)
            fail(where, ui_message("scene_material_whole", {{"meaning", meaning}, {"value", number(index)}}));
        if (index < 0) fail(where, ui_message("scene_material_negative", {{"meaning", meaning}, {"value", number(index)}}));
        if (!(index < static_cast<double>(materials))) {
            const std::size_t last = materials == 0 ? 0 : materials - 1;
            const MessageArgs count = {{"count", std::to_string(materials)}, {"last", std::to_string(last)}};
            const std::size_t tail = materials % 10, tens = materials % 100 / 10;
            const std::string have = materials == 0   ? ui_message("scene_have_none")
                                     : materials == 1 ? ui_message("scene_have_one")
                                     : materials == 2 ? ui_message("scene_have_two")
                                     : tail >= 2 && tail <= 4 && tens != 1 ? ui_message("scene_have_few", count)
                                                                           : ui_message("scene_have_many", count);
            fail(where, ui_message("scene_material_missing", {{"index", number(index)}, {"have", have}}));
        }
        return static_cast<int>(index);
    }

    Sphere read_sphere(const Json& value, const std::string& pointer, std::size_t materials) {
        Sphere sphere;
        if (!check_element(value, pointer, sphere_level(), "{\"S\": [x, y, z], \"r\": r}")) return sphere;
        const bool S = attempt([&] { sphere.S = read_position(require(value, "S", pointer), child(pointer, "S"), "S"); });
        const bool r = attempt([&] {
            sphere.r = read_length(require(value, "r", pointer), child(pointer, "r"), "r");
            if (!(sphere.r > 0)) fail(child(pointer, "r"), ui_message("scene_radius", {{"value", number(sphere.r)}}));
        });
        attempt([&] { sphere.material = read_material_index(value, pointer, materials); });
        // Computed as the article's program computes it: S := x_S² + y_S² + z_S², then S − r².
        if (S && r && !std::isfinite(length_squared(sphere.S) - sphere.r * sphere.r))
            attempt([&] { fail(pointer, ui_message("scene_sphere_far")); });
        return sphere;
    }

    Plane read_plane(const Json& value, const std::string& pointer, std::size_t materials) {
        Plane plane;
        if (!check_element(value, pointer, plane_level(), "{\"Q\": [x, y, z], \"n\": [x, y, z]}")) return plane;
        const bool Q = attempt([&] { plane.Q = read_position(require(value, "Q", pointer), child(pointer, "Q"), "Q"); });
        const std::string n_pointer = child(pointer, "n");
        const bool n = attempt([&] {
            plane.n = read_vec3(require(value, "n", pointer), n_pointer, "n");
            // Any other finite n has a direction: unit_normal scales it first.
            if (plane.n == Vec3d{0, 0, 0}) fail(n_pointer, ui_message("scene_normal_zero"));
            // A component far smaller than the largest would make n̂'s own
            // products with Q and E underflow (a plane through the eye to
            // within 1e-300, its hits' |K|² 0): the same bound, relative.
            const double parts[3] = {plane.n.x, plane.n.y, plane.n.z};
            const double largest = std::max({std::fabs(parts[0]), std::fabs(parts[1]), std::fabs(parts[2])});
            for (std::size_t k = 0; k < 3; ++k)
                if (parts[k] != 0 && std::fabs(parts[k]) < min_scene_magnitude * largest)
                    fail(child(n_pointer, k), ui_message("scene_normal_tiny_part",
                                                         {{"what", fmt::format("n[{}]", k)},
                                                          {"value", number(parts[k])},
                                                          {"ratio", number(1 / min_scene_magnitude)},
                                                          {"largest", number(largest)}}));
        });
        attempt([&] { plane.material = read_material_index(value, pointer, materials); });
        // The engine's n̂·Q.
        if (Q && n && !std::isfinite(dot(unit_normal<double>(plane.n), plane.Q)))
            attempt([&] { fail(pointer, ui_message("scene_plane_far")); });
        return plane;
    }

    Light read_light(const Json& value, const std::string& pointer) {
        Light light;
        if (!check_element(value, pointer, light_level(), "{\"L\": [x, y, z], \"I\": I}")) return light;
        attempt([&] { light.L = read_position(require(value, "L", pointer), child(pointer, "L"), "L"); });
        if (const auto it = value.find("I"); it != value.end()) attempt([&] {
                light.I = read_number(*it, child(pointer, "I"), "I");
                if (!(light.I >= 0)) fail(child(pointer, "I"), ui_message("scene_intensity", {{"value", number(light.I)}}));
            });
        if (const auto it = value.find("colour"); it != value.end())
            attempt([&] { light.colour = read_colour(*it, child(pointer, "colour"), "colour"); });
        return light;
    }

    // ambient, diffuse, specular: a finite number >= 0.
    void read_coefficient(const Json& object, const std::string& pointer, const char* key, double& target) {
        const auto it = object.find(key);
        if (it == object.end()) return;
        attempt([&] {
            const double value = read_number(*it, child(pointer, key), key);
            if (!(value >= 0))
                fail(child(pointer, key), ui_message("scene_coefficient", {{"key", key},
                                                                          {"meaning", ui_message(std::string("scene_meaning_") + key)},
                                                                          {"value", number(value)}}));
            target = value;
        });
    }

    Material read_material(const Json& value, const std::string& pointer) {
        Material material;
        if (!check_element(value, pointer, material_level(), "{\"diffuse\": 0.7, \"specular\": 0.5, \"exponent\": 20}"))
            return material;
        read_coefficient(value, pointer, "ambient", material.ambient);
        read_coefficient(value, pointer, "diffuse", material.diffuse);
        read_coefficient(value, pointer, "specular", material.specular);
        if (const auto it = value.find("exponent"); it != value.end()) attempt([&] {
                const std::string where = child(pointer, "exponent");
                const double exponent = read_number(*it, where, "exponent");
                if (!(exponent >= min_exponent && exponent <= max_exponent && std::floor(exponent) == exponent))
                    fail(where, ui_message("scene_exponent", {{"min", std::to_string(min_exponent)},
                                                              {"max", std::to_string(max_exponent)},
                                                              {"value", number(exponent)}}));
                material.exponent = static_cast<int>(exponent);
            });
        if (const auto it = value.find("colour"); it != value.end())
            attempt([&] { material.colour = read_colour(*it, child(pointer, "colour"), "colour"); });
        return material;
    }

    const ParsedJson& parsed_;
    std::vector<SceneFault> faults_;
};

// The place in the file of the value at `pointer`; for a value the file
// lacks (a missing key), the end of its nearest ancestor that it has.
std::size_t place_in_file(const ParsedJson& parsed, std::string pointer) {
    if (const auto it = parsed.order.find(pointer); it != parsed.order.end()) return it->second;
    for (;;) {
        const std::size_t slash = pointer.rfind('/');
        if (slash == std::string::npos) return parsed.order.size() + parsed.ends.size();
        pointer.resize(slash);
        if (const auto it = parsed.ends.find(pointer); it != parsed.ends.end()) return it->second;
    }
}

}  // namespace

Scene validate_scene(const ParsedJson& parsed, const std::string& source) {
    SceneReader reader(parsed);
    std::vector<SceneFault> faults = parsed.faults;
    bool counted = !parsed.faults_cut;
    Scene scene;
    try {
        if (counted) scene = reader.read(parsed.root);
    } catch (const Fault& fault) {  // the root is not an object
        reject(source, fault.where, fault.what);
    } catch (const Enough&) {
        counted = false;
    }
    for (SceneFault& fault : reader.faults()) faults.push_back(std::move(fault));
    if (faults.empty()) {
        scene.source = source;
        return scene;
    }
    // Document order; faults at one place keep the order they were found in.
    std::vector<std::pair<std::size_t, std::size_t>> order;  // (place, index)
    for (std::size_t k = 0; k < faults.size(); ++k) order.emplace_back(place_in_file(parsed, faults[k].where), k);
    std::stable_sort(order.begin(), order.end());
    std::vector<SceneFault> sorted;
    for (std::size_t k = 0; k < order.size() && k < max_reported_faults; ++k) sorted.push_back(faults[order[k].second]);
    // Counted before `sorted` is moved: the order in which a call's arguments
    // are evaluated is unspecified (clang moves it first, GCC last).
    const std::size_t more = faults.size() - sorted.size();
    throw SceneErrors(source, std::move(sorted), more, counted);
}

}  // namespace promyk::scene_detail
