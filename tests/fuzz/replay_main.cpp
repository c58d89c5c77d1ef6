// The fuzz targets as ordinary tests: every input of a target's corpus run
// through its LLVMFuzzerTestOneInput, in the normal builds (release, asan) and
// with no libFuzzer, so every finding kept in the corpus stays a regression
// test of CTest (tests/fuzz/CMakeLists.txt: fuzz.corpus.TARGET).
//
//   promyk_fuzz_replay TARGET FILE_OR_FOLDER ...
#include <cstddef>
#include <cstdint>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#define PROMYK_FUZZ_TARGET(name) extern "C" int promyk_fuzz_##name(const std::uint8_t* data, std::size_t size);
#include "fuzz_targets.inc"
#undef PROMYK_FUZZ_TARGET

namespace {

using Target = int (*)(const std::uint8_t*, std::size_t);

struct Named {
    const char* name;
    Target run;
};

const Named targets[] = {
#define PROMYK_FUZZ_TARGET(name) {#name, promyk_fuzz_##name},
#include "fuzz_targets.inc"
#undef PROMYK_FUZZ_TARGET
};

void run_file(Target target, const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::fprintf(stderr, "%s\n", path.string().c_str());  // the input a crash is about
    target(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: promyk_fuzz_replay TARGET FILE_OR_FOLDER ...\n");
        return 2;
    }
    Target target = nullptr;
    for (const Named& named : targets)
        if (std::string(argv[1]) == named.name) target = named.run;
    if (target == nullptr) {
        std::fprintf(stderr, "promyk_fuzz_replay: no target %s\n", argv[1]);
        return 2;
    }
    std::size_t count = 0;
    for (int k = 2; k < argc; ++k) {
        std::vector<std::filesystem::path> files;
        if (std::filesystem::is_directory(argv[k])) {
            for (const auto& entry : std::filesystem::directory_iterator(argv[k]))
                if (entry.is_regular_file()) files.push_back(entry.path());
        } else {
            files.emplace_back(argv[k]);
        }
        std::sort(files.begin(), files.end());
        for (const auto& file : files) run_file(target, file), ++count;
    }
    std::printf("%s: %zu inputs, none failed\n", argv[1], count);
    return count > 0 ? 0 : 1;
}
