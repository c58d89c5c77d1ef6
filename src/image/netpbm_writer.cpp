// Netpbm's grey and colour maps, each in two forms: PGM, binary (P5, "raw": a
// short text header, then one byte a pixel) and plain (P2: the grey levels as
// decimal numbers); PPM, binary (P6: three bytes r, g, b a pixel) and plain
// (P3: the same as decimal numbers). All use maxval 255 and store the samples
// exactly as given, top row first. A grey image written as PPM has r = g = b.
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "image/image_writer.hpp"
#include "util/output_file.hpp"

namespace promyk {
namespace {

// Netpbm: "No line should be longer than 70 characters."
constexpr std::size_t plain_line_limit = 70;

class NetpbmWriter final : public ImageWriter {
public:
    // `colour`: PPM (3 samples a pixel in the file), else PGM (1).
    NetpbmWriter(OutputFile& file, int width, int height, int channels, bool colour, bool plain)
        : ImageWriter(width, height, channels), file_(file), file_samples_(colour ? 3 : 1), plain_(plain) {
        const char* magic = colour ? (plain ? "P3" : "P6") : (plain ? "P2" : "P5");
        file_.write(fmt::format("{}\n{} {}\n255\n", magic, width, height));
    }

    void write_rows(const std::uint8_t* rows, int count) override {
        take_rows(count);
        const std::size_t pixels = static_cast<std::size_t>(width()) * static_cast<std::size_t>(count);
        const auto in = static_cast<std::size_t>(channels());
        const std::uint8_t* samples = rows;
        if (in != file_samples_) {  // grey to PPM: r = g = b
            expanded_.resize(pixels * file_samples_);
            for (std::size_t p = 0; p < pixels; ++p) {
                for (std::size_t c = 0; c < file_samples_; ++c) expanded_[p * file_samples_ + c] = rows[p];
            }
            samples = expanded_.data();
        }
        if (!plain_) {
            file_.write(std::string_view(reinterpret_cast<const char*>(samples), pixels * file_samples_));
            return;
        }
        // Each image row starts a line, so the text shows the image's rows;
        // a long row wraps before the 71st character, between pixels, so a
        // pixel's r g b stay on one line.
        const auto w = static_cast<std::size_t>(width());
        std::string text;
        for (int r = 0; r < count; ++r) {
            std::size_t line_start = text.size();
            for (std::size_t j = 0; j < w; ++j) {
                const std::uint8_t* pixel = samples + (static_cast<std::size_t>(r) * w + j) * file_samples_;
                char numbers[12];  // "255 255 255"
                std::size_t length = 0;
                for (std::size_t c = 0; c < file_samples_; ++c) {
                    length +=
                        static_cast<std::size_t>(std::snprintf(numbers + length, sizeof numbers - length,
                                                               c > 0 ? " %u" : "%u", static_cast<unsigned>(pixel[c])));
                }
                if (j > 0) {
                    if (text.size() - line_start + 1 + length > plain_line_limit) {
                        text += '\n';
                        line_start = text.size();
                    } else {
                        text += ' ';
                    }
                }
                text.append(numbers, length);
            }
            text += '\n';
        }
        file_.write(text);
    }

    void finish() override { require_complete(); }

private:
    OutputFile& file_;
    std::size_t file_samples_;
    bool plain_;
    std::vector<std::uint8_t> expanded_;  // grey rows widened to r, g, b
};

}  // namespace

std::unique_ptr<ImageWriter> open_pgm_writer(OutputFile& file, int width, int height, bool plain, int channels) {
    check_image_format(plain ? ImageFormat::pgm_plain : ImageFormat::pgm, channels, file.display_name());
    return std::make_unique<NetpbmWriter>(file, width, height, channels, false, plain);
}

std::unique_ptr<ImageWriter> open_ppm_writer(OutputFile& file, int width, int height, bool plain, int channels) {
    return std::make_unique<NetpbmWriter>(file, width, height, channels, true, plain);
}

}  // namespace promyk
