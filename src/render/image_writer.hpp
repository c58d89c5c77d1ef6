// Image output: grey pixels written row by row as they are rendered, so a
// render never holds the whole image. PNG (8-bit greyscale) or binary PGM,
// chosen by the path's extension. Each file is written through AtomicFile:
// completely, on commit(), or not at all.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

namespace promyk {

enum class ImageFormat { png, pgm };

// The format named by the extension (.png or .pgm, any case); UsageError
// for any other: "unsupported image extension 'x.jpg': use .png or .pgm".
ImageFormat image_format_for_path(const std::string& path);

class ImageWriter {
public:
    virtual ~ImageWriter() = default;
    ImageWriter(const ImageWriter&) = delete;
    ImageWriter& operator=(const ImageWriter&) = delete;

    // Appends `count` rows of width() 8-bit grey levels each, top row first,
    // stored one after another. OutputError if writing fails, after which
    // the writer may only be destroyed; std::logic_error beyond height() rows.
    virtual void write_rows(const std::uint8_t* rows, int count) = 0;

    // Finishes the file and puts it in place. OutputError if writing fails;
    // std::logic_error unless exactly height() rows were written. A writer
    // destroyed without a successful commit leaves no file behind.
    virtual void commit() = 0;

    int width() const noexcept { return width_; }
    int height() const noexcept { return height_; }
    int rows_written() const noexcept { return rows_written_; }

protected:
    // std::invalid_argument unless width and height are positive.
    ImageWriter(int width, int height);
    // Counts `count` more rows; std::logic_error if that exceeds height().
    void take_rows(int count);
    // std::logic_error unless all height() rows were written.
    void require_complete() const;

private:
    int width_;
    int height_;
    int rows_written_ = 0;
};

// Opens a writer for `path` in the format its extension names.
std::unique_ptr<ImageWriter> open_image_writer(const std::string& path, int width, int height);

// The factory's two halves, for a format chosen otherwise.
std::unique_ptr<ImageWriter> open_png_writer(const std::string& path, int width, int height);
std::unique_ptr<ImageWriter> open_pgm_writer(const std::string& path, int width, int height);

}  // namespace promyk
