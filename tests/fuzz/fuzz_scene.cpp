// The scene loader from bytes (scene/scene_json.hpp: load_scene_text): any
// input is a scene or an InputError (exit 3), never a crash, a leak or
// undefined behaviour; an accepted scene written back (scene_to_json) reads
// back to the same scene; and the engine traces one of its pixels.
#include "fuzz_check.hpp"
#include "render/kernel.hpp"
#include "render/trace_pixel.hpp"
#include "scene/scene_json.hpp"
#include "util/errors.hpp"

using namespace promyk;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    set_ui_language(fuzz::language_of(size));
    Scene scene;
    try {
        scene = load_scene_text(fuzz::bytes_of(data, size), "fuzz.json");
    } catch (const InputError&) {
        return 0;
    }
    for (const SceneDefaults defaults : {SceneDefaults::omitted, SceneDefaults::written}) {
        const std::string text = scene_to_json(scene, defaults);
        Scene again;
        try {
            again = load_scene_text(text, "again.json");
        } catch (const InputError& error) {
            std::fprintf(stderr, "%s: %s\n%s\n", error.where.c_str(), error.what(), text.c_str());
            fuzz::broken("a scene written by scene_to_json is refused");
        }
        if (scene_to_json(again, defaults) != text) fuzz::broken("a scene read back differs");
    }
    const std::unique_ptr<Kernel> kernel = make_kernel(scene);
    (void)kernel->trace(trace_header(scene, 8), 3, 4);
    return 0;
}
