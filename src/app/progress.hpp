// Progress of long work on stderr: shown only when stderr is a terminal and
// the work has already taken about a second, so short runs and pipes stay quiet.
#pragma once

#include <chrono>
#include <string>

namespace promyk::app {

class Progress {
public:
    // `what` names the work, `unit` what `done` and `total` count.
    Progress(std::string what, std::string unit);
    ~Progress();
    void update(long done, long total);

private:
    std::string what_;
    std::string unit_;
    std::chrono::steady_clock::time_point start_;
    bool terminal_;
    bool shown_ = false;
    int last_percent_ = -1;
};

}  // namespace promyk::app
