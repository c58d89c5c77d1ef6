// Image output: grey pixels written row by row as they are rendered, so a
// render never holds the whole image. PNG (8-bit greyscale), binary PGM (P5,
// "raw" in Netpbm's words) or plain PGM (P2, text), into an OutputFile: a
// regular file is written completely, when its owner commits it, or not at
// all; a device, a FIFO or standard output receives the bytes as produced.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

namespace promyk {

class OutputFile;

enum class ImageFormat {
    png,
    pgm,        // binary PGM, P5
    pgm_plain,  // plain PGM, P2: ASCII numbers, lines of at most 70 characters
};

// The format named by the extension (.png or .pgm, any case; .pgm means P5);
// UsageError for any other: "unsupported image extension 'x.jpg': use .png or .pgm".
ImageFormat image_format_for_path(const std::string& path);

class ImageWriter {
public:
    virtual ~ImageWriter();
    ImageWriter(const ImageWriter&) = delete;
    ImageWriter& operator=(const ImageWriter&) = delete;

    // Appends `count` rows of width() 8-bit grey levels each, top row first,
    // stored one after another. OutputError (BrokenPipe for EPIPE) if
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
    int rows_written() const noexcept { return rows_written_; }

    // Gives the writer the file it writes into, to close with it.
    void adopt(std::unique_ptr<OutputFile> file);

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
    std::unique_ptr<OutputFile> owned_file_;  // destroyed after the derived writer
};

// Opens `path` as an OutputFile and a writer that owns it, in the format its
// extension names. UsageError for an unknown extension (nothing created).
std::unique_ptr<ImageWriter> open_image_writer(const std::string& path, int width, int height);

// A writer into `file`, which must outlive it and which the caller commits.
std::unique_ptr<ImageWriter> open_image_writer(OutputFile& file, ImageFormat format, int width, int height);

// The factory's halves, for a format chosen otherwise.
std::unique_ptr<ImageWriter> open_png_writer(OutputFile& file, int width, int height);
std::unique_ptr<ImageWriter> open_pgm_writer(OutputFile& file, int width, int height, bool plain);

// The largest side of an image promyk writes, scaled or not.
constexpr int max_image_side = 32768;

// The side of a w x w pane drawn with each pixel as a scale x scale block,
// and with `grid`, 1-pixel lines between the blocks: w·scale + (w − 1).
long scaled_side(int w, int scale, bool grid);

// The grey level of the grid lines: darker than the background (128), lighter
// than the dark side (0), so blocks of either stay apart.
constexpr std::uint8_t grid_grey = 64;

// Wraps `inner`, whose side must be scaled_side(w, scale, grid): takes rows of
// w pixels and writes each pixel as a scale x scale block, with grid lines
// between blocks if asked. Streams: holds one output row, not the image.
// finish() finishes `inner`.
std::unique_ptr<ImageWriter> scale_image_writer(std::unique_ptr<ImageWriter> inner, int w, int scale, bool grid);

}  // namespace promyk
