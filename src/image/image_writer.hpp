// Image output: pixels written row by row as they are rendered, so a render
// never holds the whole image. A pixel is one 8-bit grey level (channels = 1)
// or three bytes r, g, b (channels = 3). PNG (8-bit greyscale or 8-bit RGB),
// PGM (grey only: binary P5, "raw" in Netpbm's words, or plain P2, text) or
// PPM (RGB: binary P6 or plain P3, text; a grey image written as PPM has
// r = g = b). Into an OutputFile: a regular file is written completely, when
// its owner commits it, or not at all; a device, a FIFO or standard output
// receives the bytes as produced.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace promyk {

class OutputFile;

enum class ImageFormat {
    png,        // 8-bit greyscale, or 8-bit RGB for 3 channels
    pgm,        // binary PGM, P5: grey only
    pgm_plain,  // plain PGM, P2: ASCII numbers, lines of at most 70 characters; grey only
    ppm,        // binary PPM, P6
    ppm_plain,  // plain PPM, P3: ASCII numbers, lines of at most 70 characters
};

// The format named by the extension (.png, .pgm or .ppm, any case; .pgm means
// P5, .ppm means P6); UsageError for any other:
// "unsupported image extension 'x.jpg': use .png, .pgm or .ppm".
ImageFormat image_format_for_path(const std::string& path);

// Whether `format` can hold an image of `channels` (1 grey, 3 RGB) channels;
// call it before creating any output or rendering anything. PGM holds grey
// levels only, so a coloured (3-channel) image as .pgm is UsageError:
// "x.pgm: PGM holds grey levels only and this scene is coloured; write .png
// or .ppm" (`path` as given, for the message). Every other pair passes; a
// grey image written as PPM gets r = g = b. std::invalid_argument unless
// channels is 1 or 3.
void check_image_format(ImageFormat format, int channels, const std::string& path);

class ImageWriter {
public:
    virtual ~ImageWriter();
    ImageWriter(const ImageWriter&) = delete;
    ImageWriter& operator=(const ImageWriter&) = delete;

    // Appends `count` rows, top row first, stored one after another: each
    // row is width() pixels of channels() bytes (a grey level, or r, g, b),
    // width() * channels() bytes in all. OutputError (BrokenPipe for EPIPE) if
    // writing fails, after which the writer may only be destroyed;
    // std::logic_error beyond height() rows.
    virtual void write_rows(const std::uint8_t* rows, int count) = 0;

    // Writes what follows the last row (PNG's closing chunks) into the
    // output; the output file itself is committed by its owner (see
    // commit_together). std::logic_error unless exactly height() rows were
    // written; OutputError if writing fails.
    virtual void finish() = 0;

    // For a writer that owns its file (open_image_writer(path, ...)):
    // finish(), then commit the file. A writer destroyed without a
    // successful commit leaves no file behind. std::logic_error if the
    // writer does not own its file.
    void commit();

    int width() const noexcept { return width_; }
    int height() const noexcept { return height_; }
    // 1 (a grey level a pixel) or 3 (r, g, b a pixel): what write_rows takes,
    // whatever the file stores.
    int channels() const noexcept { return channels_; }
    // The bytes of one row passed to write_rows: width() * channels().
    std::size_t row_bytes() const noexcept {
        return static_cast<std::size_t>(width_) * static_cast<std::size_t>(channels_);
    }
    int rows_written() const noexcept { return rows_written_; }

    // Gives the writer the file it writes into, to close with it.
    void adopt(std::unique_ptr<OutputFile> file);

protected:
    // std::invalid_argument unless width and height are positive and
    // channels is 1 or 3.
    ImageWriter(int width, int height, int channels = 1);
    // Counts `count` more rows; std::logic_error if that exceeds height().
    void take_rows(int count);
    // std::logic_error unless all height() rows were written.
    void require_complete() const;

private:
    int width_;
    int height_;
    int channels_;
    int rows_written_ = 0;
    std::unique_ptr<OutputFile> owned_file_;  // destroyed after the derived writer
};

// Opens `path` as an OutputFile and a writer that owns it, in the format its
// extension names, for rows of `channels` (1 grey, 3 RGB) bytes a pixel.
// UsageError for an unknown extension or a coloured image as .pgm (see
// check_image_format); nothing is created then.
std::unique_ptr<ImageWriter> open_image_writer(const std::string& path, int width, int height, int channels = 1);

// A writer into `file`, which must outlive it and which the caller commits.
// check_image_format(format, channels, file's display name) first: the
// UsageError comes before anything is written.
std::unique_ptr<ImageWriter> open_image_writer(OutputFile& file, ImageFormat format, int width, int height,
                                               int channels = 1);

// The factory's halves, for a format chosen otherwise. PNG: greyscale for 1
// channel, RGB for 3. PGM: 1 channel only (UsageError as check_image_format
// for 3). PPM: 3 channels, or 1 written as r = g = b.
std::unique_ptr<ImageWriter> open_png_writer(OutputFile& file, int width, int height, int channels = 1);
std::unique_ptr<ImageWriter> open_pgm_writer(OutputFile& file, int width, int height, bool plain, int channels = 1);
std::unique_ptr<ImageWriter> open_ppm_writer(OutputFile& file, int width, int height, bool plain, int channels = 1);

// The largest side of an image promyk writes, scaled or not.
constexpr int max_image_side = 32768;

// The side of a w x w pane drawn with each pixel as a scale x scale block,
// and with `grid`, 1-pixel lines between the blocks: w·scale + (w − 1).
long scaled_side(int w, int scale, bool grid);

// Wraps `inner`, whose side must be scaled_side(w, scale, grid): takes rows of
// w pixels and writes each pixel as a scale x scale block, with grid lines
// between blocks if asked: each line pixel a grey (r = g = b in RGB) that
// contrasts with the squares it borders (image/grid_contrast.hpp). The
// pixels have inner's channels (channels() is
// inner->channels()): a grey pane makes grey blocks, an RGB pane RGB blocks.
// Streams: holds one output row, not the image. finish() finishes `inner`.
std::unique_ptr<ImageWriter> scale_image_writer(std::unique_ptr<ImageWriter> inner, int w, int scale, bool grid);

}  // namespace promyk
