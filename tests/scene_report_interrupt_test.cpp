// The scene's report (render's warnings, scene check) probes a 64 × 64 pane
// against every sphere and light before anything is drawn: for a scene of
// thousands of them that takes a while (1,500 spheres and 1,500 lights:
// 15 ms, 1.5 s under the sanitizers), so it must honour an interrupt, as
// the render after it does. In a child process, since the flag stays set.
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <csignal>

#include "render/scene_report.hpp"
#include "scene/scene.hpp"
#include "util/errors.hpp"
#include "util/interrupt.hpp"

using namespace promyk;

TEST_CASE("a signal received before a scene's report stops its probe", "[scene-report][interrupt]") {
    for (const int signal : interrupt_signals) {
        INFO("signal " << signal);
        const pid_t child = fork();
        REQUIRE(child >= 0);
        if (child == 0) {
            install_interrupt_handlers();
            std::raise(signal);  // the handler has run: the flag is set
            try {
                report_scene(article_scene());
                _exit(101);
            } catch (const Interrupted& interrupted) {
                _exit(interrupted.signal_number == signal ? 0 : 102);
            } catch (...) {
                _exit(103);
            }
        }
        int status = 0;
        REQUIRE(waitpid(child, &status, 0) == child);
        REQUIRE(WIFEXITED(status));
        CHECK(WEXITSTATUS(status) == 0);
    }
}
