// The scene's report (render's warnings, scene check) probes a 64 × 64 pane
// against every sphere and light before anything is drawn: for a scene of
// thousands of them that takes a while (1,500 spheres and 1,500 lights:
// 15 ms, 1.5 s under the sanitizers), so it must honour an interrupt, as
// the render after it does. In a child process, since the flag stays set.
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <csignal>

#include "child_process.hpp"
#include "render/scene_report.hpp"
#include "scene/scene.hpp"
#include "util/errors.hpp"
#include "util/interrupt.hpp"

using namespace promyk;
using promyk::testing::child_status;
using promyk::testing::interrupted_code;

TEST_CASE("a signal received before a scene's report stops its probe", "[scene-report][interrupt]") {
    for (const int signal : interrupt_signals) {
        INFO("signal " << signal);
        const int status = child_status([signal] {
            install_interrupt_handlers();
            std::raise(signal);  // the handler has run: the flag is set
            return interrupted_code(signal, [] { report_scene(article_scene()); });
        });
        REQUIRE(WIFEXITED(status));
        CHECK(WEXITSTATUS(status) == 0);
    }
}
