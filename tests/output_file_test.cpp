// Outputs: the same file by any path is refused, devices and FIFOs are
// written through (never replaced), symbolic links stay links, a directory
// is refused before anything is created, EPIPE is its own error, and files
// committed together appear together or not at all.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <thread>

#include "util/errors.hpp"
#include "temp_dir.hpp"
#include "util/output_file.hpp"

namespace fs = std::filesystem;
using namespace promyk;

namespace {

using testing::TempDir;

using testing::read_bytes;
using testing::write_bytes;

// A device that fails every write with ENOSPC. As root (CI), one made here:
// a bug that replaced the device with a regular file must not hit /dev/full.
std::string full_device(const TempDir& dir) {
    if (::geteuid() != 0) return "/dev/full";
    const std::string full = dir.file("full");
    REQUIRE(::mknod(full.c_str(), S_IFCHR | 0666, ::makedev(1, 7)) == 0);
    return full;
}

bool same(const std::string& a, const std::string& b) {
    return same_destination(inspect_output(a), inspect_output(b));
}

}  // namespace

TEST_CASE("two paths to one file are the same destination", "[output]") {
    TempDir dir;
    fs::create_directory(dir.path / "a");
    const std::string x = dir.file("x.png");

    SECTION("a file that does not exist yet") {
        CHECK(same(x, dir.file("./x.png")));
        CHECK(same(x, dir.file("a/../x.png")));
        CHECK(same(x, dir.file("a//..//x.png")));
        fs::create_directory_symlink(dir.path, dir.path / "a" / "up");
        CHECK(same(x, dir.file("a/up/x.png")));
        fs::create_symlink("x.png", dir.path / "dangling");
        CHECK(same(x, dir.file("dangling")));
        CHECK_FALSE(same(x, dir.file("y.png")));
        CHECK_FALSE(same(x, dir.file("a/x.png")));
        CHECK(dir.entries() == std::set<std::string>{"a", "dangling"});  // nothing created
    }
    SECTION("an existing file, by symbolic and hard links") {
        write_bytes(x, "old");
        CHECK(same(x, dir.file("./x.png")));
        CHECK(same(x, dir.file("a/../x.png")));
        fs::create_symlink(x, dir.path / "link");
        CHECK(same(x, dir.file("link")));
        fs::create_hard_link(x, dir.path / "hard");
        CHECK(same(x, dir.file("hard")));
        CHECK(same(dir.file("link"), dir.file("hard")));
        write_bytes(dir.file("other"), "old");
        CHECK_FALSE(same(x, dir.file("other")));
    }
    SECTION("devices") {
        CHECK(same("/dev/null", "/dev/null"));
        CHECK_FALSE(same("/dev/null", "/dev/zero"));
        CHECK_FALSE(same("/dev/null", x));
    }
}

TEST_CASE("standard output is the file descriptor 1 points at", "[output]") {
    TempDir dir;
    const std::string x = dir.file("out.txt");
    write_bytes(x, "");
    const int saved = ::dup(STDOUT_FILENO);
    REQUIRE(saved >= 0);
    const int fd = ::open(x.c_str(), O_WRONLY);
    REQUIRE(fd >= 0);
    ::dup2(fd, STDOUT_FILENO);
    ::close(fd);
    const OutputTarget out = inspect_output("-");
    const bool same_as_file = same_destination(out, inspect_output(x));
    const bool same_as_proc = same_destination(out, inspect_output("/proc/self/fd/1"));
    ::dup2(saved, STDOUT_FILENO);
    ::close(saved);
    CHECK(out.kind == OutputKind::standard_output);
    CHECK(out.lands_in_regular_file);
    CHECK(same_as_file);
    CHECK(same_as_proc);
    CHECK(same_destination(inspect_output("-"), inspect_output("-")));
}

TEST_CASE("require_distinct_outputs names both options", "[output]") {
    TempDir dir;
    const std::string x = dir.file("x.png");
    CHECK_THROWS_MATCHES(require_distinct_outputs({{"-o", inspect_output(x)}, {"--traces", inspect_output(x)}}),
                         UsageError, Catch::Message("-o and --traces name the same file (" + x + ")"));
    CHECK_NOTHROW(
        require_distinct_outputs({{"-o", inspect_output(x)}, {"--traces", inspect_output(dir.file("t.jsonl"))}}));
}

TEST_CASE("a directory is refused when inspected, before anything is created", "[output]") {
    TempDir dir;
    fs::create_directory(dir.path / "d");
    for (const std::string& path : {dir.file("d"), dir.file("d/"), dir.file("."), dir.file("d/..")}) {
        CAPTURE(path);
        CHECK_THROWS_WITH(inspect_output(path), Catch::Contains("Is a directory"));
        CHECK_THROWS_AS(inspect_output(path), OutputError);
    }
    CHECK_THROWS_MATCHES(inspect_output(dir.file("missing/x")), OutputError,
                         Catch::Message("cannot write " + dir.file("missing/x") + ": No such file or directory"));
    CHECK(dir.entries() == std::set<std::string>{"d"});
    CHECK(fs::is_empty(dir.path / "d"));
}

TEST_CASE("a symbolic link stays a link and its target gets the content", "[output]") {
    TempDir dir;
    fs::create_directory(dir.path / "real");
    const std::string target = dir.file("real/t.txt");
    const bool target_exists = GENERATE(true, false);
    CAPTURE(target_exists);
    if (target_exists) write_bytes(target, "old");
    fs::create_symlink("real/t.txt", dir.path / "link.txt");
    {
        OutputFile file(dir.file("link.txt"));
        CHECK(file.atomic());
        file.write("new");
        // The temporary sits beside the target, so the rename is atomic.
        CHECK(dir.entries("real").size() == (target_exists ? 2u : 1u));
        file.commit();
    }
    CHECK(fs::is_symlink(dir.path / "link.txt"));
    CHECK(read_bytes(target) == "new");
    CHECK(dir.entries() == std::set<std::string>{"link.txt", "real"});
    CHECK(dir.entries("real") == std::set<std::string>{"t.txt"});
}

TEST_CASE("a regular file is replaced by rename, so its other hard links keep the old content", "[output]") {
    // Atomic replacement gives the path a new inode; other hard links keep
    // the old content. That is the price of all-or-nothing, and documented.
    TempDir dir;
    write_bytes(dir.file("a"), "old");
    fs::create_hard_link(dir.path / "a", dir.path / "b");
    OutputFile file(dir.file("a"));
    file.write("new");
    file.commit();
    CHECK(read_bytes(dir.file("a")) == "new");
    CHECK(read_bytes(dir.file("b")) == "old");
}

TEST_CASE("a FIFO is written directly, no temporary, still a FIFO after", "[output]") {
    TempDir dir;
    const std::string fifo = dir.file("f");
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    std::string received;
    std::thread reader([&] { received = read_bytes(fifo); });
    {
        OutputFile file(fifo);  // waits for the reader
        CHECK_FALSE(file.atomic());
        file.write("through the pipe");
        CHECK(dir.entries() == std::set<std::string>{"f"});
        file.commit();
        CHECK(file.bytes_written() == 16);
    }
    reader.join();
    CHECK(received == "through the pipe");
    CHECK(fs::is_fifo(fifo));
    CHECK(dir.entries() == std::set<std::string>{"f"});
}

TEST_CASE("a character device is written through, never replaced", "[output]") {
    TempDir dir;
    std::string null_device = "/dev/null";
    if (::geteuid() == 0) {  // a device of our own, so a bug cannot hurt /dev/null
        null_device = dir.file("null");
        REQUIRE(::mknod(null_device.c_str(), S_IFCHR | 0666, ::makedev(1, 3)) == 0);
    }
    {
        OutputFile file(null_device);
        CHECK_FALSE(file.atomic());
        file.write("discarded");
        file.commit();
    }
    struct stat info {};
    REQUIRE(::stat(null_device.c_str(), &info) == 0);
    CHECK(S_ISCHR(info.st_mode));
    CHECK(dir.entries().size() == (::geteuid() == 0 ? 1u : 0u));

    SECTION("a symbolic link to the device is followed") {
        fs::create_symlink(null_device, dir.path / "link");
        OutputFile file(dir.file("link"));
        CHECK_FALSE(file.atomic());
        file.write("discarded");
        file.commit();
        CHECK(fs::is_symlink(dir.path / "link"));
    }
}

TEST_CASE("/dev/full fails with the errno text", "[output]") {
    TempDir dir;
    const std::string full = full_device(dir);
    OutputFile file(full);
    file.write("x");  // buffered
    CHECK_THROWS_MATCHES(file.finish(), OutputError,
                         Catch::Message("cannot write " + full + ": No space left on device"));
}

TEST_CASE("a write to a pipe whose reader quit is BrokenPipe, not OutputError", "[output]") {
    const auto old_handler = ::signal(SIGPIPE, SIG_IGN);
    int fds[2];
    REQUIRE(::pipe(fds) == 0);
    ::close(fds[0]);
    bool broken = false;
    try {
        OutputFile file("/proc/self/fd/" + std::to_string(fds[1]));
        CHECK_FALSE(file.atomic());
        file.write("nobody reads this");
        file.finish();
    } catch (const BrokenPipe&) {
        broken = true;
    }
    ::close(fds[1]);
    ::signal(SIGPIPE, old_handler);
    CHECK(broken);
    CHECK_THROWS_AS(throw_write_error("x", EPIPE), BrokenPipe);
    CHECK_THROWS_AS(throw_write_error("x", ENOSPC), OutputError);
}

TEST_CASE("files committed together: a failure leaves none of them", "[output]") {
    TempDir dir;
    const std::string image = dir.file("x.png");
    write_bytes(dir.file("t.jsonl"), "old");
    const std::string full = full_device(dir);
    const std::set<std::string> before = dir.entries();
    {
        OutputFile first(image);
        OutputFile second(dir.file("t.jsonl"));
        OutputFile failing(full);
        first.write("image");
        second.write("traces");
        failing.write("x");
        CHECK_THROWS_AS(commit_together({&first, &second, &failing}), OutputError);
    }
    CHECK(dir.entries() == before);
    CHECK(read_bytes(dir.file("t.jsonl")) == "old");

    OutputFile first(image);
    OutputFile second(dir.file("t.jsonl"));
    first.write("image");
    second.write("traces");
    commit_together({&first, nullptr, &second});
    CHECK(read_bytes(image) == "image");
    CHECK(read_bytes(dir.file("t.jsonl")) == "traces");
    CHECK(dir.entries().count("x.png") == 1);
    CHECK(dir.entries().size() == before.size() + 1);
}
