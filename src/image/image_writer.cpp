// Choosing the image format and the row bookkeeping every format shares.
#include "image/image_writer.hpp"

#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "util/errors.hpp"
#include "util/output_file.hpp"

namespace promyk {
namespace {

// ASCII only: a locale must not change which files are PNG.
std::string lowercase(std::string text) {
    for (char& c : text) {
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    }
    return text;
}

void check_size(int width, int height) {
    if (width <= 0 || height <= 0) {
        throw std::invalid_argument(fmt::format("image size {}x{} is not positive", width, height));
    }
}

void check_channels(int channels) {
    if (channels != 1 && channels != 3) {
        throw std::invalid_argument(fmt::format("an image has 1 or 3 channels, not {}", channels));
    }
}

}  // namespace

ImageFormat image_format_for_path(const std::string& path) {
    // The extension of the last path component, so "out.d/image" has none.
    const auto slash = path.find_last_of('/');
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    const auto dot = name.find_last_of('.');
    const std::string extension = dot == std::string::npos ? "" : lowercase(name.substr(dot + 1));
    if (extension == "png") return ImageFormat::png;
    if (extension == "pgm") return ImageFormat::pgm;
    if (extension == "ppm") return ImageFormat::ppm;
    throw UsageError(fmt::format("unsupported image extension '{}': use .png, .pgm or .ppm", path));
}

void check_image_format(ImageFormat format, int channels, const std::string& path) {
    check_channels(channels);
    if (channels == 3 && (format == ImageFormat::pgm || format == ImageFormat::pgm_plain)) {
        throw UsageError(
            fmt::format("{}: PGM holds grey levels only and this scene is coloured; write .png or .ppm", path));
    }
}

std::unique_ptr<ImageWriter> open_image_writer(OutputFile& file, ImageFormat format, int width, int height,
                                               int channels) {
    check_image_format(format, channels, file.display_name());
    switch (format) {
        case ImageFormat::png:
            return open_png_writer(file, width, height, channels);
        case ImageFormat::pgm:
            return open_pgm_writer(file, width, height, false, channels);
        case ImageFormat::pgm_plain:
            return open_pgm_writer(file, width, height, true, channels);
        case ImageFormat::ppm:
            return open_ppm_writer(file, width, height, false, channels);
        case ImageFormat::ppm_plain:
            return open_ppm_writer(file, width, height, true, channels);
    }
    throw std::logic_error("unknown ImageFormat");
}

std::unique_ptr<ImageWriter> open_image_writer(const std::string& path, int width, int height, int channels) {
    // All checked before the file (its temporary) is created.
    const ImageFormat format = image_format_for_path(path);
    check_image_format(format, channels, path);
    check_size(width, height);
    auto file = std::make_unique<OutputFile>(path);
    std::unique_ptr<ImageWriter> writer = open_image_writer(*file, format, width, height, channels);
    writer->adopt(std::move(file));
    return writer;
}

ImageWriter::ImageWriter(int width, int height, int channels) : width_(width), height_(height), channels_(channels) {
    check_size(width, height);
    check_channels(channels);
}

ImageWriter::~ImageWriter() = default;

void ImageWriter::adopt(std::unique_ptr<OutputFile> file) { owned_file_ = std::move(file); }

void ImageWriter::commit() {
    if (!owned_file_) throw std::logic_error("image writer: commit() on a writer that does not own its file");
    finish();
    owned_file_->commit();
}

void ImageWriter::take_rows(int count) {
    if (count < 0 || count > height_ - rows_written_) {
        throw std::logic_error(fmt::format("image writer: {} more rows after {} of {}", count, rows_written_, height_));
    }
    rows_written_ += count;
}

void ImageWriter::require_complete() const {
    if (rows_written_ != height_) {
        throw std::logic_error(fmt::format("image writer: commit after {} of {} rows", rows_written_, height_));
    }
}

}  // namespace promyk
