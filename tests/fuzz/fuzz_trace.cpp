// The trace reader (trace/trace_read.hpp): a trace file of `promyk render
// --traces` (JSON Lines) and one trace of `promyk trace --format json`, from
// bytes. Any input is traces or an InputError (exit 3), never a crash, a
// leak or undefined behaviour; a trace read and written again
// (append_trace_json) reads back and writes the same line.
#include "fuzz_check.hpp"
#include "trace/trace.hpp"
#include "trace/trace_read.hpp"
#include "util/errors.hpp"

using namespace promyk;

namespace {

void written_again(const PixelTrace& trace) {
    std::string line;
    append_trace_json(line, trace);
    PixelTrace again;
    try {
        again = read_trace_json(line, "again.json");
    } catch (const InputError& error) {
        std::fprintf(stderr, "%s: %s\n%s\n", error.where.c_str(), error.what(), line.c_str());
        fuzz::broken("a trace written by append_trace_json is refused");
    }
    std::string line_again;
    append_trace_json(line_again, again);
    if (line_again != line) fuzz::broken("a trace written, read and written again differs");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    set_ui_language(fuzz::language_of(size));
    const std::string_view bytes = fuzz::bytes_of(data, size);
    try {
        const TraceFile file = read_trace_file(bytes, "fuzz.jsonl");
        if (file.lines.size() != file.traces.size()) fuzz::broken("a trace file's lines and traces differ in number");
        for (const PixelTrace& trace : file.traces) written_again(trace);
    } catch (const InputError&) {
    }
    try {
        written_again(read_trace_json(bytes, "fuzz.json"));
    } catch (const InputError&) {
    }
    return 0;
}
