#include "app/progress.hpp"

#include <unistd.h>
#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

#include "trace/messages.hpp"

namespace promyk::app {

Progress::Progress(std::string what, std::string unit)
    : what_(std::move(what)),
      unit_(std::move(unit)),
      start_(std::chrono::steady_clock::now()),
      terminal_(isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() {
    if (shown_) std::fputs("\n", stderr);
}

void Progress::update(long done, long total) {
    if (!terminal_ || total <= 0) return;
    const auto elapsed = std::chrono::steady_clock::now() - start_;
    if (!shown_ && elapsed < std::chrono::seconds(1)) return;
    const int percent = static_cast<int>(100 * done / total);
    if (percent == last_percent_) return;
    last_percent_ = percent;
    shown_ = true;
    const double seconds = std::chrono::duration<double>(elapsed).count();
    std::string tenths = fmt::format("{:.1f}", seconds);
    if (ui_language() == Language::pl) std::replace(tenths.begin(), tenths.end(), '.', ',');  // decimal comma
    const std::string line = ui_message("progress_line", {{"what", what_},
                                                          {"percent", fmt::format("{:3d}", percent)},
                                                          {"done", std::to_string(done)},
                                                          {"total", std::to_string(total)},
                                                          {"unit", unit_},
                                                          {"seconds", tenths}});
    fmt::print(stderr, "\r{}", line);
    std::fflush(stderr);
}

}  // namespace promyk::app
