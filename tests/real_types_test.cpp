// --real float|double|long-double|quad: the whole computation in that type.
// Checked against the article's program written out here in the type itself
// (nothing from src/ but the type's square root), and the exact texts
// (real_text) against their own type's reading.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

#include <quadmath.h>

#include "math/real.hpp"
#include "render/kernel.hpp"
#include "render/trace_pixel.hpp"
#include "scene/scene_json.hpp"
#include "trace/trace_compare.hpp"
#include "trace/vocabulary.hpp"

using namespace promyk;

namespace {

// The correctly rounded square root: std::sqrt, and for quad promyk's
// correction of libquadmath's faithful sqrtq (checked against the 4096-bit
// simulation in tests/hard_cases_test.cpp).
template <class T>
T root(T x) {
    if constexpr (std::is_same_v<T, quad>)
        return square_root(x);
    else
        return std::sqrt(x);
}

// The article's `intensity`, line by line, in type T; the scene's numbers are
// the article's doubles converted to T, the pane point computed in T.
template <class T>
T literal_intensity(int w, int i, int j) {
    const T x_S = T(0.0), y_S = T(0.0), z_S = T(3.2), r = T(1.1), x_L = T(1.5), y_L = T(1.0), z_L = T(1.0),
            I = T(1.0), z_E = T(2.0);
    const T x_E = T(2 * j + 1) / T(w) - T(1);
    const T y_E = -T(2 * i + 1) / T(w) + T(1);
    const T E = x_E * x_E + y_E * y_E + z_E * z_E;
    const T S = x_S * x_S + y_S * y_S + z_S * z_S;
    const T C = x_E * x_S + y_E * y_S + z_E * z_S;
    const T Delta = C * C - E * (S - r * r);
    if (Delta <= 0) return T(0.5);
    const T t = (C - root(Delta)) / E;
    const T x_P = t * x_E, y_P = t * y_E, z_P = t * z_E;
    const T x_N = x_P - x_S, y_N = y_P - y_S, z_N = z_P - z_S;
    const T x_K = x_L - x_P, y_K = y_L - y_P, z_K = z_L - z_P;
    const T K = x_K * x_K + y_K * y_K + z_K * z_K;
    const T D = x_N * x_K + y_N * y_K + z_N * z_K;
    if (D <= 0) return T(0);
    return I * D / (r * root(K));
}

// The same value: equal, with the same sign for zeros (not memcmp: an x87
// long double has 6 bytes of padding whose contents are arbitrary).
template <class T>
bool same_real(T a, T b) {
    return a == b && ((a < 0 || 1 / a < 0) == (b < 0 || 1 / b < 0));
}

template <class T>
T read_back(const std::string& text) {
    if constexpr (std::is_same_v<T, float>) return std::strtof(text.c_str(), nullptr);
    if constexpr (std::is_same_v<T, double>) return std::strtod(text.c_str(), nullptr);
    if constexpr (std::is_same_v<T, long double>) return std::strtold(text.c_str(), nullptr);
    if constexpr (std::is_same_v<T, quad>) return strtoflt128(text.c_str(), nullptr);
}

// The number of significant digits in a decimal text: from its first
// non-zero digit to its last (3828521000 has 7).
int digits_of(const std::string& text) {
    const std::string mantissa = text.substr(0, text.find_first_of("eE"));
    std::string digits;
    for (char c : mantissa)
        if (c >= '0' && c <= '9') digits += c;
    const std::size_t first = digits.find_first_not_of('0');
    if (first == std::string::npos) return 1;
    return static_cast<int>(digits.find_last_not_of('0') - first + 1);
}

template <class T>
void check_texts(int max_digits) {
    std::mt19937_64 random(42);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::uniform_int_distribution<int> exponent(-300, 300);
    for (int n = 0; n < 2000; ++n) {
        // Values with bits below double's: a double times a small odd correction.
        T x = T(unit(random)) * T(std::pow(2.0, exponent(random) % 120));
        x = x + x * T(unit(random)) / T(1e20);
        const std::string text = real_text(x);
        INFO(text);
        CHECK(same_real(read_back<T>(text), x));
        CHECK(digits_of(text) <= max_digits);
    }
    CHECK(real_text(T(0.5)) == "0.5");
    CHECK(real_text(T(-3)) == "-3");
    CHECK(real_text(T(1) / T(0)) == "inf");
    CHECK(real_text(-T(1) / T(0)) == "-inf");
}

}  // namespace

TEST_CASE("real_text is the shortest text that reads back to the same value in its own type", "[real]") {
    check_texts<float>(9);
    check_texts<double>(17);
    check_texts<long double>(21);
    check_texts<quad>(36);
    CHECK(real_text(0.1f) == "0.1");
    CHECK(real_text(0.1L) == "0.1");
    // 3.2 as a double, read exactly in a wider type, needs all its digits.
    CHECK(real_text(static_cast<long double>(3.2)) == "3.2000000000000001776");
    CHECK(real_text(static_cast<quad>(3.2)) == "3.2000000000000001776356839400250465");
}

TEST_CASE("in each real type the engine computes the article's program in that type, bit for bit", "[real]") {
    const Scene scene = article_scene();
    constexpr int w = 64;
    const auto check = [&](RealType type, auto literal) {
        const auto kernel = make_kernel(scene, type);
        int differ_from_double = 0;
        for (int i = 0; i < w; ++i) {
            for (int j = 0; j < w; ++j) {
                const auto expected = literal(i, j);
                const double got = kernel->intensity(w, i, j).x;
                INFO(real_type_name(type) << " (" << i << ", " << j << ")");
                CHECK(got == static_cast<double>(expected));
                if (got != literal_intensity<double>(w, i, j)) ++differ_from_double;
            }
        }
        return differ_from_double;
    };
    CHECK(check(RealType::double_, [](int i, int j) { return literal_intensity<double>(w, i, j); }) == 0);
    // float differs from double on (almost) every lit pixel; the wider types
    // differ from double too, in the last bits.
    CHECK(check(RealType::float_, [](int i, int j) { return literal_intensity<float>(w, i, j); }) > 1000);
    CHECK(check(RealType::long_double, [](int i, int j) { return literal_intensity<long double>(w, i, j); }) > 100);
    CHECK(check(RealType::quad_, [](int i, int j) { return literal_intensity<quad>(w, i, j); }) > 100);
}

TEST_CASE("a trace in another real type carries each value's exact text, and equals the untraced pixel",
          "[real]") {
    for (const RealType type : {RealType::float_, RealType::long_double, RealType::quad_}) {
        const PixelTrace trace = trace_pixel(article_scene(), 8, 3, 4, type);
        CHECK(trace.header.real == real_type_name(type));
        for (const Step& step : trace.steps) {
            INFO(key_name(step.key));
            if (std::holds_alternative<double>(step.value)) {
                REQUIRE(step.real_text.size() == 1);
            } else if (std::holds_alternative<Vec3d>(step.value)) {
                REQUIRE(step.real_text.size() == 3);
            }
        }
        REQUIRE(trace.result_real_text.size() == 1);
        CHECK(trace.result == make_kernel(article_scene(), type)->intensity(8, 3, 4).x);
    }
    const PixelTrace quad_trace = trace_pixel(article_scene(), 8, 3, 4, RealType::quad_);
    CHECK(quad_trace.result_real_text.front() == real_text(literal_intensity<quad>(8, 3, 4)));
    // Every example scene in every type: traced equals untraced.
    for (const char* name : {"everything", "floor", "phong"}) {
        const Scene scene = load_scene_file(std::string(PROMYK_SOURCE_DIR "/lessons/scenes/") + name + ".json");
        for (const RealType type : {RealType::float_, RealType::long_double, RealType::quad_}) {
            const auto kernel = make_kernel(scene, type);
            const TraceHeader header = trace_header(scene, 12);
            for (int i = 0; i < 12; ++i)
                for (int j = 0; j < 12; ++j) {
                    const PixelTrace trace = kernel->trace(header, i, j);
                    const Vec3d untraced = kernel->intensity(12, i, j);
                    CHECK((trace.result_rgb ? trace.result_rgb->z : trace.result) == untraced.z);
                }
        }
    }
}

TEST_CASE("trace --compare: digits agreeing with the most precise type, counted on exact values", "[real]") {
    // float 6.4 is 6.400000095367431640625: 7 digits of the double 6.4.
    CHECK(agreeing_digits("6.4", "float", "6.4", "double") == 7);
    CHECK(agreeing_digits("6.4", "double", "6.400000000000000355271367880050093", "quad") == -1);
    CHECK(agreeing_digits("3.14159", "quad", "3.14160", "quad") == 5);
    CHECK(agreeing_digits("-1", "double", "1", "double") == 0);
    CHECK(agreeing_digits("1", "double", "0", "double") == 0);
    CHECK(mark_digits("4.5578117", 6) == "4.55781|17");
    CHECK(mark_digits("0.0012345", 2) == "0.0012|345");
    CHECK(mark_digits("-10.240001", 7) == "-10.24000|1");
    CHECK(mark_digits("1.5e-07", 1) == "1.|5e-07");  // before the first digit that differs
    CHECK(mark_digits("4.5", 5) == "4.5");
    const std::vector<PixelTrace> traces = {trace_pixel(article_scene(), 8, 3, 4, RealType::float_),
                                            trace_pixel(article_scene(), 8, 3, 4, RealType::quad_)};
    const std::string text = format_comparison(traces, builtin_vocabulary(), Language::en);
    CHECK_THAT(text, Catch::Contains("delta  Δ/4\n  float  4.55781|17   6 significant digits agree\n"
                                     "  quad   4.557812500000000752176099183543587\n"));
    CHECK_THAT(text, Catch::Contains("E  E\n  float  (0.125, 0.125, 2)   exactly equal\n"));
}
