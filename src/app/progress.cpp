#include "app/progress.hpp"

#include <unistd.h>
#include <cstdio>

#include <fmt/format.h>

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
    fmt::print(stderr, "\r{}: {:3d}% ({} of {} {}), {:.1f} s", what_, percent, done, total, unit_, seconds);
    std::fflush(stderr);
}

}  // namespace promyk::app
