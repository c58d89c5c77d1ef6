// PGM in Netpbm's two forms: binary (P5, "raw": a short text header, then one
// byte a pixel) and plain (P2: the grey levels as decimal numbers). Both use
// maxval 255 and store the grey levels exactly as given, top row first.
#include <cstdio>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "render/image_writer.hpp"
#include "util/output_file.hpp"

namespace promyk {
namespace {

// Netpbm: "No line should be longer than 70 characters."
constexpr std::size_t plain_line_limit = 70;

class PgmWriter final : public ImageWriter {
public:
    PgmWriter(OutputFile& file, int width, int height, bool plain)
        : ImageWriter(width, height), file_(file), plain_(plain) {
        file_.write(fmt::format("{}\n{} {}\n255\n", plain ? "P2" : "P5", width, height));
    }

    void write_rows(const std::uint8_t* rows, int count) override {
        take_rows(count);
        const auto w = static_cast<std::size_t>(width());
        if (!plain_) {
            file_.write(std::string_view(reinterpret_cast<const char*>(rows), w * static_cast<std::size_t>(count)));
            return;
        }
        // Each image row starts a line, so the text shows the image's rows;
        // a long row wraps before the 71st character.
        std::string text;
        for (int r = 0; r < count; ++r) {
            std::size_t line_start = text.size();
            for (std::size_t j = 0; j < w; ++j) {
                char number[4];
                const auto length = static_cast<std::size_t>(
                    std::snprintf(number, sizeof number, "%u", static_cast<unsigned>(rows[r * w + j])));
                if (j > 0) {
                    if (text.size() - line_start + 1 + length > plain_line_limit) {
                        text += '\n';
                        line_start = text.size();
                    } else {
                        text += ' ';
                    }
                }
                text.append(number, length);
            }
            text += '\n';
        }
        file_.write(text);
    }

    void finish() override { require_complete(); }

private:
    OutputFile& file_;
    bool plain_;
};

}  // namespace

std::unique_ptr<ImageWriter> open_pgm_writer(OutputFile& file, int width, int height, bool plain) {
    return std::make_unique<PgmWriter>(file, width, height, plain);
}

}  // namespace promyk
