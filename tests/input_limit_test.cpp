// cli::read_input_file stops at its limit while reading: a file of exactly
// max_bytes is read whole, one byte more is refused (exit 3, the limit
// named), at every size around the reading's chunk boundaries, and an endless
// input (/dev/zero) ends at once.
#include <catch2/catch.hpp>

#include <chrono>
#include <cstdio>
#include <string>

#include "app/cli_values.hpp"
#include "util/errors.hpp"

using namespace promyk;

namespace {

std::string write_file(std::size_t size) {
    const std::string path = "input_limit_test.tmp";
    std::FILE* f = std::fopen(path.c_str(), "wb");
    REQUIRE(f != nullptr);
    const std::string bytes(size, 'x');
    REQUIRE(std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size());
    std::fclose(f);
    return path;
}

}  // namespace

TEST_CASE("read_input_file: up to the limit is read, one byte past it is refused", "[input-limit]") {
    for (const std::size_t limit : {std::size_t(0), std::size_t(1), std::size_t(1000), std::size_t(65535),
                                    std::size_t(65536), std::size_t(65537), std::size_t(3 * 65536)}) {
        for (const std::size_t size : {limit, limit + 1, limit + 65536}) {
            if (size == 0 && limit == 0) continue;
            const std::string path = write_file(size);
            INFO("limit " << limit << ", size " << size);
            if (size <= limit) {
                CHECK(cli::read_input_file(path, "test reads", limit, "test").size() == size);
            } else {
                try {
                    cli::read_input_file(path, "test reads", limit, "test");
                    FAIL("not refused");
                } catch (const InputError& error) {
                    CHECK(error.file == path);
                    CHECK(std::string(error.what()).find("test reads at most") != std::string::npos);
                }
            }
            std::remove(path.c_str());
        }
    }
}

TEST_CASE("read_input_file: an endless input ends at the limit", "[input-limit]") {
    const auto start = std::chrono::steady_clock::now();
    CHECK_THROWS_AS(cli::read_input_file("/dev/zero", "test reads", std::size_t(1) << 20, "test"), InputError);
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(2));
}
