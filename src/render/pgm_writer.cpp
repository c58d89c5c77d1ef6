// Binary PGM (P5, maxval 255): a short text header, then the grey levels
// exactly as given, one byte a pixel, top row first.
#include <string_view>

#include <fmt/format.h>

#include "render/image_writer.hpp"
#include "util/atomic_file.hpp"

namespace promyk {
namespace {

class PgmWriter final : public ImageWriter {
public:
    PgmWriter(const std::string& path, int width, int height) : ImageWriter(width, height), file_(path) {
        file_.write(fmt::format("P5\n{} {}\n255\n", width, height));
    }

    void write_rows(const std::uint8_t* rows, int count) override {
        take_rows(count);
        const auto size = static_cast<std::size_t>(width()) * static_cast<std::size_t>(count);
        file_.write(std::string_view(reinterpret_cast<const char*>(rows), size));
    }

    void commit() override {
        require_complete();
        file_.commit();
    }

private:
    AtomicFile file_;
};

}  // namespace

std::unique_ptr<ImageWriter> open_pgm_writer(const std::string& path, int width, int height) {
    return std::make_unique<PgmWriter>(path, width, height);
}

}  // namespace promyk
