// The reader of `promyk bench accuracy --json` files that `promyk export
// --bench` embeds (app/accuracy_file.hpp): any bytes are the checked JSON or
// an InputError (exit 3) with a message in the run's language, never a
// crash, an undefined behaviour or another exception; what is accepted has
// what the page's plot reads (a non-empty list of scenes, each with its
// results).
#include <string>

#include "app/accuracy_file.hpp"
#include "fuzz_check.hpp"
#include "util/errors.hpp"

using namespace promyk;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    set_ui_language(fuzz::language_of(size));
    const std::string text(fuzz::bytes_of(data, size));
    try {
        const nlohmann::json file = app::read_accuracy_file(text, "bench.json");
        const auto scenes = file.find("scenes");
        if (scenes == file.end() || !scenes->is_array() || scenes->empty())
            fuzz::broken("a bench file without scenes is accepted");
        for (const nlohmann::json& scene : *scenes)
            if (!scene.is_object()) fuzz::broken("a scene that is not an object is accepted");
    } catch (const InputError& e) {
        if (std::string(e.what()).empty()) fuzz::broken("a refusal without a message");
    }
    return 0;
}
