// Waiting on a FIFO loses no interrupt (util/held_signals.hpp): a signal that
// comes at any moment, even just before promyk starts to wait for a FIFO's
// writer (a scene, a trace for diff, answers) or reader (an output), or for
// standard input (diff -, --answers -, lesson --step's Enter), ends the wait
// with Interrupted.
// "Just before" is made certain here: the signal is raised while blocked, so
// it is pending when the load or the open begins (a check of the flag
// followed by a blocking call would wait for ever). In a child process each,
// since the flag stays set, with a watchdog (alarm) that kills a child that
// waits. And the waits still wait: a writer or reader that comes late, and
// a scene given in pieces, are read and written whole.
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <functional>
#include <string>
#include <thread>

#include "app/cli_values.hpp"
#include "child_process.hpp"
#include "scene/scene_json.hpp"
#include "temp_dir.hpp"
#include "util/errors.hpp"
#include "util/interrupt.hpp"
#include "util/output_file.hpp"
#include "util/read_input.hpp"

using namespace promyk;
using promyk::testing::child_status;
using promyk::testing::interrupted_code;
using promyk::testing::TempDir;
using promyk::testing::write_bytes;

namespace {

constexpr const char* scene_json = R"({"spheres": [{"S": [0, 0, 3.2], "r": 1.1}], "lights": [{"L": [-2, 3, 0]}]})";

// Runs `wait_on_fifo` in a child with promyk's handlers and `signal`
// pending; the child's status: exit 0 when it threw Interrupted(signal),
// 101..103 otherwise, killed by SIGALRM if it kept waiting.
int status_of(int signal, const std::function<void()>& wait_on_fifo) {
    return child_status([&] {
        install_interrupt_handlers();
        sigset_t one;
        sigemptyset(&one);
        sigaddset(&one, signal);
        sigprocmask(SIG_BLOCK, &one, nullptr);
        std::raise(signal);  // pending: the handler has not run, the flag is clear
        alarm(20);           // the watchdog
        return interrupted_code(signal, wait_on_fifo);
    });
}

// Each of promyk's interrupt signals, pending, must end wait_on_fifo with
// Interrupted, not the watchdog.
void check_every_signal_ends(const std::function<void()>& wait_on_fifo) {
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
        INFO("signal " << signal);
        const int status = status_of(signal, wait_on_fifo);
        CHECK((WIFEXITED(status) && WEXITSTATUS(status) == 0));
        CHECK_FALSE(WIFSIGNALED(status));  // not the watchdog
    }
}

// Standard input made a pipe with nothing in it and a writer that stays
// (this process), as a terminal where nobody has typed yet.
void quiet_standard_input() {
    int ends[2];
    if (::pipe(ends) != 0 || ::dup2(ends[0], STDIN_FILENO) < 0) _exit(104);
}

// Standard input made a file holding `text` (a pipe holds only 64 KiB).
void standard_input_of(const std::string& text) {
    std::FILE* file = std::tmpfile();
    REQUIRE(file != nullptr);
    REQUIRE(std::fwrite(text.data(), 1, text.size(), file) == text.size());
    REQUIRE(std::fflush(file) == 0);
    std::rewind(file);
    REQUIRE(::dup2(::fileno(file), STDIN_FILENO) >= 0);
    std::fclose(file);
}

}  // namespace

TEST_CASE("a signal pending when a scene FIFO has no writer yet ends the load", "[held-signals]") {
    TempDir dir;
    const std::string fifo = dir.file("scene.json");
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    check_every_signal_ends([&] { load_scene_file(fifo); });
}

TEST_CASE("a signal pending when an output FIFO has no reader yet ends the open", "[held-signals]") {
    TempDir dir;
    const std::string fifo = dir.file("image.png");
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    check_every_signal_ends([&] { OutputFile file(fifo); });
    CHECK(dir.entries() == std::set<std::string>{"image.png"});
}

TEST_CASE("a signal pending when an input FIFO has no writer yet ends the read (diff, answers)", "[held-signals]") {
    TempDir dir;
    const std::string fifo = dir.file("a.jsonl");
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    check_every_signal_ends([&] { cli::read_input_file(fifo, "diff reads", 1 << 20, "diff"); });
}

TEST_CASE("a signal pending while standard input is quiet ends the read (diff -, --answers -)", "[held-signals]") {
    check_every_signal_ends([] {
        quiet_standard_input();
        cli::read_input_file("-", "--answers reads", 1 << 20, "--answers");
    });
}

TEST_CASE("a signal pending while lesson --step waits for Enter ends the wait", "[held-signals]") {
    check_every_signal_ends([] {
        quiet_standard_input();
        read_standard_input_line();
    });
}

TEST_CASE("an Enter is read a line at a time, what follows left unread", "[held-signals]") {
    const int kept = ::dup(STDIN_FILENO);
    REQUIRE(kept >= 0);
    standard_input_of("b\n\nq \nno end");
    CHECK(read_standard_input_line() == std::optional<std::string>("b"));
    CHECK(read_standard_input_line() == std::optional<std::string>(""));
    CHECK(read_standard_input_line() == std::optional<std::string>("q "));
    CHECK(read_standard_input_line() == std::optional<std::string>("no end"));
    CHECK(read_standard_input_line() == std::nullopt);  // closed: the lesson goes on
    // A line longer than the limit: its start kept, the rest read and dropped.
    standard_input_of(std::string(100000, 'x') + "\nq\n");
    CHECK(read_standard_input_line() == std::optional<std::string>(std::string(max_input_line_bytes, 'x')));
    CHECK(read_standard_input_line() == std::optional<std::string>("q"));
    standard_input_of("whole\ninput");
    CHECK(cli::read_input_file("-", "test reads", 1 << 20, "test") == "whole\ninput");
    ::dup2(kept, STDIN_FILENO);
    ::close(kept);
}

TEST_CASE("an input FIFO whose writer comes late and writes in pieces is read whole", "[held-signals]") {
    TempDir dir;
    const std::string fifo = dir.file("answers.txt");
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    const std::string text(200000, 'a');  // more than a pipe holds at once
    std::thread writer([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        const int fd = ::open(fifo.c_str(), O_WRONLY);
        if (fd < 0) return;
        (void)!::write(fd, text.data(), 1000);
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        (void)!::write(fd, text.data() + 1000, text.size() - 1000);
        ::close(fd);
    });
    const std::string read = cli::read_input_file(fifo, "--answers reads", 1 << 20, "--answers");
    writer.join();
    CHECK(read.size() == text.size());
    CHECK(read == text);
}

TEST_CASE("a scene FIFO whose writer comes late and writes in pieces is read whole", "[held-signals]") {
    TempDir dir;
    const std::string fifo = dir.file("scene.json");
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    const std::string text = scene_json;
    std::thread writer([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        const int fd = ::open(fifo.c_str(), O_WRONLY);
        if (fd < 0) return;
        const std::size_t half = text.size() / 2;
        (void)!::write(fd, text.data(), half);
        std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the reader finds the pipe empty
        (void)!::write(fd, text.data() + half, text.size() - half);
        ::close(fd);
    });
    const Scene scene = load_scene_file(fifo);
    writer.join();
    REQUIRE(scene.spheres.size() == 1);
    CHECK(scene.spheres[0].S.z == 3.2);
    CHECK(scene.spheres[0].r == 1.1);
    REQUIRE(scene.lights.size() == 1);
    CHECK(scene.lights[0].L.x == -2);
}

TEST_CASE("an output FIFO whose reader comes late gets every byte, and its writes block again", "[held-signals]") {
    TempDir dir;
    const std::string fifo = dir.file("out");
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    // More than a pipe holds (64 KiB): with O_NONBLOCK left on, a write
    // would fail with EAGAIN while the reader sleeps.
    const std::string bytes(1 << 20, 'x');
    std::string received;
    std::thread reader([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        const int fd = ::open(fifo.c_str(), O_RDONLY);
        if (fd < 0) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        char buffer[4096];
        ssize_t got;
        while ((got = ::read(fd, buffer, sizeof buffer)) > 0) received.append(buffer, static_cast<std::size_t>(got));
        ::close(fd);
    });
    {
        OutputFile file(fifo);  // waits about 100 ms
        file.write(bytes);
        file.commit();
    }
    reader.join();
    CHECK(received.size() == bytes.size());
    CHECK(received == bytes);
}

TEST_CASE("loading a scene leaves the signal mask as it found it", "[held-signals]") {
    TempDir dir;
    const std::string path = dir.file("scene.json");
    write_bytes(path, scene_json);
    for (const bool blocked_before : {false, true}) {
        sigset_t before, after, interrupt;
        sigemptyset(&interrupt);
        sigaddset(&interrupt, SIGINT);
        pthread_sigmask(blocked_before ? SIG_BLOCK : SIG_UNBLOCK, &interrupt, nullptr);
        pthread_sigmask(SIG_SETMASK, nullptr, &before);
        load_scene_file(path);
        pthread_sigmask(SIG_SETMASK, nullptr, &after);
        for (const int signal : {SIGINT, SIGTERM, SIGHUP})
            CHECK(sigismember(&before, signal) == sigismember(&after, signal));
        pthread_sigmask(SIG_UNBLOCK, &interrupt, nullptr);
    }
}
