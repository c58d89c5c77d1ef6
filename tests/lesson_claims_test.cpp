// The numbers a lesson's prose states, computed: where float and double lose
// the far sphere, the largest sum of two lights, the colour of a highlight,
// how accurate Kahan's discriminant is, the bench figures lesson 11 quotes,
// the digits double keeps, the rounded squarings of the phong answer. Each
// test computes the claim and checks that both languages state that number
// (issue 15: a number in lesson prose is filled by the engine or checked by
// a test).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "lesson/lesson_render.hpp"
#include "math/real.hpp"
#include "render/trace_pixel.hpp"
#include "scene/scene_json.hpp"

using namespace promyk;

namespace {

const std::string source = PROMYK_SOURCE_DIR;

// A lesson file's text, with no-break spaces (inside long numbers) removed
// and lines joined, so that a number wrapped at a line end is found too.
std::string lesson_text(const std::string& language, const std::string& file) {
    std::ifstream in(source + "/lessons/" + language + "/" + file, std::ios::binary);
    REQUIRE(in);
    std::stringstream buffer;
    buffer << in.rdbuf();
    std::string text = buffer.str();
    for (std::size_t at; (at = text.find("\xC2\xA0")) != std::string::npos;) text.erase(at, 2);
    for (char& c : text)
        if (c == '\n') c = ' ';
    // Runs of spaces (a list item's indent) as one.
    std::string out;
    for (const char c : text)
        if (!(c == ' ' && !out.empty() && out.back() == ' ')) out += c;
    return out;
}

// A number as the lesson writes it: a decimal comma in Polish, U+2212 minus.
std::string written(std::string number, const std::string& language) {
    if (language == "pl")
        for (char& c : number)
            if (c == '.') c = ',';
    if (!number.empty() && number[0] == '-') number.replace(0, 1, "\u2212");
    return number;
}

void check_states(const std::string& file, const std::string& number) {
    for (const std::string language : {"pl", "en"}) {
        INFO(language << "/" << file << " states " << written(number, language));
        CHECK(lesson_text(language, file).find(written(number, language)) != std::string::npos);
    }
}

double number_of(const PixelTrace& trace, const std::string& key) {
    const std::optional<StepValue> value = lesson_value(trace, key);
    REQUIRE(value);
    return std::get<double>(*value);
}

// A unit sphere at distance D on the axis, the pane at z_E = D (lesson 11).
Scene far_unit_sphere(double D) {
    Scene scene;
    scene.name = "far";
    scene.z_E = D;
    scene.spheres = {Sphere{{0, 0, D}, 1}};
    scene.lights = {Light{{1.5, 1, D - 2}, 1}};
    return scene;
}

int hits(double D, RealType real) {
    const Scene scene = far_unit_sphere(D);
    int count = 0;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) count += trace_pixel(scene, 8, i, j, real).branch != Branch::miss;
    return count;
}

}  // namespace

TEST_CASE("lesson 11: where float and double lose the far unit sphere on an 8 x 8 pane", "[lesson][claims]") {
    const int whole = hits(4, RealType::double_);  // near: every pixel the sphere covers
    REQUIRE(whole > 0);
    // float: whole up to 1024, edge pixels gone by 1500, all of it from 4097 (4096 still drawn).
    CHECK(hits(1024, RealType::float_) == whole);
    CHECK(hits(1500, RealType::float_) < whole);
    CHECK(hits(4096, RealType::float_) > 0);
    for (const double D : {4097.0, 4100.0, 5000.0, 1e4, 1e5}) CHECK(hits(D, RealType::float_) == 0);
    // double: whole up to 3e7, edge pixels gone by 4e7, all of it from 94 906 266.
    CHECK(hits(3e7, RealType::double_) == whole);
    CHECK(hits(4e7, RealType::double_) < whole);
    CHECK(hits(94906265, RealType::double_) > 0);
    for (const double D : {94906266.0, 94906300.0, 95e6, 1e8, 1e9}) CHECK(hits(D, RealType::double_) == 0);
    check_states("11-precision.md", "D = 1024");
    check_states("11-precision.md", "1500");
    check_states("11-precision.md", "D = 4097");
    check_states("11-precision.md", "4096");
    check_states("11-precision.md", "D = 3·10⁷");
    check_states("11-precision.md", "4·10⁷");
    check_states("11-precision.md", "D = 94906266");
    check_states("11-precision.md", "94906265");
}

TEST_CASE("lesson 11: the far sphere's Delta/4 in double agrees with quad's in 7 to 9 digits", "[lesson][claims]") {
    const Scene scene = load_scene_file(source + "/lessons/scenes/far_sphere.json");
    double fewest = 99, most = 0, agree_low = 99, agree_high = 0;
    for (int i = 0; i < 8; ++i) {
        for (int j = 0; j < 8; ++j) {
            // The exact Delta/4 of the pixel's own E (exact in quad: E has few bits).
            const quad y_E = -quad(2 * i + 1) / 8 + 1, x_E = quad(2 * j + 1) / 8 - 1, z_E = scene.z_E;
            const quad z_S = scene.spheres[0].S.z, r = scene.spheres[0].r;
            const quad EE = x_E * x_E + y_E * y_E + z_E * z_E, C = z_E * z_S;
            const quad exact = C * C - EE * (z_S * z_S - r * r);
            if (!(exact > 0)) continue;
            const PixelTrace trace = trace_pixel(scene, 8, i, j);
            REQUIRE(trace.branch != Branch::miss);
            const double digits = -std::log10(std::fabs(double((quad(number_of(trace, "delta")) - exact) / exact)));
            fewest = std::min(fewest, digits);
            most = std::max(most, digits);
            // C² and |E|²·c, about 10¹⁶, agree in their first digits.
            const double agree = -std::log10(double(exact / (C * C)));
            agree_low = std::min(agree_low, agree);
            agree_high = std::max(agree_high, agree);
            // float's Delta/4 is 0: not one correct digit.
            CHECK(number_of(trace_pixel(scene, 8, i, j, RealType::float_), "delta") == 0);
        }
    }
    CHECK(std::floor(fewest) == 7);
    CHECK(std::floor(most) == 9);
    CHECK(lesson_text("pl", "11-precision.md").find("na 7 do 9 cyfrach znaczących") != std::string::npos);
    CHECK(lesson_text("en", "11-precision.md").find("in 7 to 9 significant digits") != std::string::npos);
    CHECK(std::floor(agree_low) == 8);
    CHECK(std::floor(agree_high) == 9);
    CHECK(lesson_text("pl", "11-precision.md").find("pierwszych ośmiu, dziewięciu cyfrach") != std::string::npos);
    CHECK(lesson_text("en", "11-precision.md").find("first eight or nine digits") != std::string::npos);
    // "Floats near 10⁸ are 8 apart"; the sphere is 10⁴ radii from the eye.
    CHECK(std::nextafter(1e8f, 2e8f) - 1e8f == 8.0f);
    CHECK(scene.spheres[0].S.z / scene.spheres[0].r == 1e4);
}

TEST_CASE("lesson 11: with the geometric formula float's values lie within two ulps of the exact ones", "[lesson][claims]") {
    const Scene scene = load_scene_file(source + "/lessons/scenes/far_sphere.json");
    int pixels = 0;
    for (int i = 0; i < 8; ++i) {
        for (int j = 0; j < 8; ++j) {
            const PixelTrace in_float = trace_pixel(scene, 8, i, j, RealType::float_, Formula::geometric);
            const PixelTrace exact = trace_pixel(scene, 8, i, j, RealType::quad_, Formula::geometric);
            if (exact.branch == Branch::miss) continue;
            ++pixels;
            CHECK(in_float.branch != Branch::miss);
            for (const std::string key : {"delta_g", "t_hit"}) {
                const double f = number_of(in_float, key), q = number_of(exact, key);
                const double ulp = std::nextafter(float(std::fabs(q)), 1e30f) - float(std::fabs(q));
                INFO("(" << i << ", " << j << ") " << key << ": float " << f << ", exact " << q);
                CHECK(std::fabs(f - q) <= 2 * ulp);
            }
        }
    }
    CHECK(pixels > 0);
}

TEST_CASE("lessons 03 and 11: Kahan's fma discriminant is accurate to about an ulp, not exact", "[lesson][claims]") {
    double worst = 0;
    int inexact = 0, hit = 0;
    for (const std::string file : {"article.json", "far_sphere.json", "two_spheres.json"}) {
        Scene scene = load_scene_file(source + "/lessons/scenes/" + file);
        scene.spheres.resize(1);
        for (int i = 0; i < 32; ++i) {
            for (int j = 0; j < 32; ++j) {
                const PixelTrace trace = trace_pixel(scene, 32, i, j, RealType::double_, Formula::fma);
                const double C = number_of(trace, "C"), EE = number_of(trace, "EE"), c_0 = number_of(trace, "c_0");
                const double delta = number_of(trace, "delta_fma");
                // Exact for the rounded C, |E|² and c: each product has 106 bits, quad holds 113.
                const quad exact = quad(C) * C - quad(EE) * c_0;
                if (!(exact > 0)) continue;
                ++hit;
                const double nearest = double(exact);
                const double ulp = std::nextafter(nearest, 1e300) - nearest;
                const double error = std::fabs(double(quad(delta) - exact)) / ulp;
                worst = std::max(worst, error);
                inexact += delta != nearest;
            }
        }
    }
    INFO("hits " << hit << ", inexact " << inexact << ", worst " << worst << " ulp");
    CHECK(hit > 100);
    CHECK(worst <= 2);    // "about an ulp"
    CHECK(inexact > 0);   // and not exact: some results are not the nearest double
    for (const std::string language : {"pl", "en"}) {
        for (const std::string file : {"03-sphere.md", "11-precision.md"}) {
            const std::string text = lesson_text(language, file);
            CHECK(text.find("exact for the numbers") == std::string::npos);
            CHECK(text.find("dokładny dla liczb") == std::string::npos);
        }
    }
    CHECK(lesson_text("pl", "11-precision.md").find("jednej jednostki ostatniego miejsca (ulp)") != std::string::npos);
    CHECK(lesson_text("en", "11-precision.md").find("accurate to about an ulp") != std::string::npos);
}

TEST_CASE("lesson 07: two lights on opposite sides never sum above 0.70 on the sphere", "[lesson][claims]") {
    const Scene scene = load_scene_file(source + "/lessons/scenes/two_lights.json");
    const Sphere& sphere = scene.spheres.at(0);
    const auto sum_at = [&](double theta, double phi) {
        const Vec3d N{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
        const Vec3d P{sphere.S.x + sphere.r * N.x, sphere.S.y + sphere.r * N.y, sphere.S.z + sphere.r * N.z};
        double sum = 0;
        for (const Light& light : scene.lights) {
            const Vec3d K{light.L.x - P.x, light.L.y - P.y, light.L.z - P.z};
            const double cos_alpha = (N.x * K.x + N.y * K.y + N.z * K.z) / std::sqrt(K.x * K.x + K.y * K.y + K.z * K.z);
            sum += light.I * std::max(0.0, cos_alpha);
        }
        return sum;
    };
    const double pi = std::acos(-1.0);
    double best = 0, best_theta = 0, best_phi = 0;
    const int n = 300;
    for (int a = 0; a <= n; ++a)
        for (int b = 0; b < 2 * n; ++b)
            if (const double s = sum_at(pi * a / n, pi * b / n); s > best) best = s, best_theta = pi * a / n, best_phi = pi * b / n;
    // Refine around the best grid point.
    for (double step = pi / n; step > 1e-9; step /= 2)
        for (const auto& [dt, dp] : std::vector<std::pair<double, double>>{{1, 0}, {-1, 0}, {0, 1}, {0, -1}})
            while (sum_at(best_theta + dt * step, best_phi + dp * step) > best)
                best_theta += dt * step, best_phi += dp * step, best = sum_at(best_theta, best_phi);
    INFO("the largest sum: " << best);
    CHECK(best < 0.705);
    CHECK(best > 0.695);
    CHECK(scene.lights[0].I + scene.lights[1].I == Approx(1.2));  // what the sum is not
    check_states("07-lights.md", "0.70");
}

TEST_CASE("lesson 10: a light's colour multiplies its whole contribution, the material's not the highlight", "[lesson][claims]") {
    const Scene scene = parse_scene(R"({"name": "red ball", "z_E": 2, "background": [0, 0, 0],
        "spheres": [{"S": [0, 0, 3.2], "r": 1.1, "material": 0}],
        "lights": [{"L": [1.5, 1, 1], "I": 0.9, "colour": [1, 0.8, 0.6]}],
        "materials": [{"ambient": 0.1, "diffuse": 0.7, "specular": 0.5, "exponent": 20, "colour": [0.9, 0.2, 0.15]}]})",
                                    "red ball");
    const PixelTrace trace = trace_pixel(scene, 8, 3, 5);
    const double I = 0.9, k_a = 0.1, k_d = 0.7;
    const Vec3d c{1, 0.8, 0.6}, m{0.9, 0.2, 0.15};
    const double diffuse = number_of(trace, "light[0].diffuse"), specular = number_of(trace, "light[0].specular");
    REQUIRE(specular > 0.01);
    const std::optional<StepValue> contribution = lesson_value(trace, "light[0].contribution");
    REQUIRE(contribution);
    const Vec3d got = std::get<Vec3d>(*contribution);
    // contribution = c·(m·(k_a·I + k_d·I·cos α) + I·k_s·(R̂·V̂)ⁿ), with diffuse = I·cos α.
    const double lambert = k_a * I + k_d * diffuse;
    CHECK(got.x == Approx(c.x * (m.x * lambert + specular)).epsilon(1e-12));
    CHECK(got.y == Approx(c.y * (m.y * lambert + specular)).epsilon(1e-12));
    CHECK(got.z == Approx(c.z * (m.z * lambert + specular)).epsilon(1e-12));
    CHECK(got.y != Approx(c.y * m.y * (lambert + specular)));  // not "all multiplied by m"
    CHECK(lesson_text("pl", "10-phong.md").find("wkład = c·(m·(k_a·I + k_d·I·cos α) + I·k_s·(R̂·V̂)ⁿ)") != std::string::npos);
    CHECK(lesson_text("en", "10-phong.md").find("contribution = c·(m·(k_a·I + k_d·I·cos α) + I·k_s·(R̂·V̂)ⁿ)") !=
          std::string::npos);
    CHECK(lesson_text("en", "10-phong.md").find("all multiplied by") == std::string::npos);
}

TEST_CASE("lesson 10: the phong answer's squarings, rounded to four decimals at each step", "[lesson][claims]") {
    const Scene scene = load_scene_file(source + "/lessons/scenes/phong.json");
    const PixelTrace trace = trace_pixel(scene, 8, 3, 5);  // the lesson's first pixel
    const double RV = number_of(trace, "light[0].RV");
    check_states("10-phong.md", fmt::format("{:.6f}…", std::trunc(RV * 1e6) / 1e6));
    // In units of 10⁻⁴, halves away from zero, as a pupil rounds.
    const long long x = std::llround(RV * 1e4);
    check_states("10-phong.md", fmt::format("0.{:04d};", x));
    std::vector<long long> powers{x};
    for (int k = 0; k < 4; ++k) powers.push_back((powers.back() * powers.back() + 5000) / 10000);
    const long long product = (powers[2] * powers[4] + 5000) / 10000;
    const char* names[] = {"", "RV² = ", "RV⁴ = ", "RV⁸ = ", "RV¹⁶ = "};
    for (std::size_t k = 1; k <= 4; ++k) check_states("10-phong.md", fmt::format("{}0.{:04d}", names[k], powers[k]));
    check_states("10-phong.md", fmt::format("RV⁴ · RV¹⁶ = 0.{:04d}", product));
    CHECK(product == 3714);
    check_states("10-phong.md", fmt::format(")²⁰ = {:.4f}", number_of(trace, "light[0].RV_n")));
}

TEST_CASE("lesson 11 quotes the far sphere's row of docs/bench.md", "[lesson][claims]") {
    std::ifstream in(source + "/docs/bench.md");
    REQUIRE(in);
    std::map<std::string, std::pair<double, std::string>> row;  // "real formula" at spp 1 -> ratio, max error
    bool far = false;
    const std::regex line(R"(^\s+1\s+(\S+)\s+(\S+)\s+\S+\s+(\S+)\s+(\S+)\s+.*$)");
    for (std::string text; std::getline(in, text);) {
        // The table may write its exponents with U+2212 (1.08e−03).
        for (std::size_t at; (at = text.find("\u2212")) != std::string::npos;) text.replace(at, 3, "-");
        if (text.rfind("scene far_sphere:", 0) == 0) far = true;
        if (far && text.empty() && !row.empty()) break;
        std::smatch match;
        if (far && std::regex_match(text, match, line))
            row[match[1].str() + " " + match[2].str()] = {std::stod(match[3].str()), match[4].str()};
    }
    REQUIRE(row.size() == 16);
    const auto ratio = [&](const std::string& what, int decimals) { return fmt::format("{:.{}f}", row.at(what).first, decimals); };
    // 3.00e-08 as the lesson writes it: 3.00·10⁻⁸.
    const auto error = [&](const std::string& what) {
        const std::string e = row.at(what).second;
        const std::size_t at = e.find('e');
        const int exponent = std::stoi(e.substr(at + 1));
        const char* superscripts[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
        std::string power = "⁻";
        for (const char digit : std::to_string(-exponent)) power += superscripts[digit - '0'];
        return e.substr(0, at) + "·10" + power;
    };
    check_states("11-precision.md", ratio("float article", 2));
    check_states("11-precision.md", ratio("float geometric", 2));
    check_states("11-precision.md", ratio("double geometric", 2));
    check_states("11-precision.md", ratio("long-double article", 2));
    check_states("11-precision.md", error("double geometric"));
    check_states("11-precision.md", error("double article"));
    check_states("11-precision.md", error("long-double article"));
    double quad_low = 1e9, quad_high = 0;
    for (const std::string formula : {"article", "stable", "fma", "geometric"}) {
        quad_low = std::min(quad_low, row.at("quad " + formula).first);
        quad_high = std::max(quad_high, row.at("quad " + formula).first);
    }
    check_states("11-precision.md", fmt::format("{}", std::llround(quad_low)));
    check_states("11-precision.md", fmt::format("{}", std::llround(quad_high)));
    // Every ratio the lesson names is of the far sphere: the article scene's
    // long double (4.90) and float (1.30) are not quoted.
    for (const std::string stale : {"1.3,", "4.90", "5 to 7", "170"}) CHECK(lesson_text("en", "11-precision.md").find(stale) == std::string::npos);
}

TEST_CASE("lessons 01, 02 and 08: the numbers of their prose", "[lesson][claims]") {
    // Lesson 01: |S|² of the article's scene printed with every digit.
    const Scene article = load_scene_file(source + "/lessons/scenes/article.json");
    const double SS = number_of(trace_pixel(article, 8, 3, 4), "SS");
    CHECK(fmt::format("{}", SS) == "10.240000000000002");
    check_states("01-vectors.md", fmt::format("{}", SS));
    // The stored 3.2 is a hair larger than 3.2; exercise c)'s vectors are perpendicular, of length 3.
    CHECK(quad(3.2) * 10 > quad(32));
    CHECK(1 * 2 + 2 * -2 + 2 * 1 == 0);
    CHECK(1 * 1 + 2 * 2 + 2 * 2 == 9);
    CHECK(2 * 2 + -2 * -2 + 1 * 1 == 9);
    // Lesson 02, exercise a): square (3, 2) of a 4 × 4 pane.
    const std::optional<StepValue> E = lesson_value(trace_pixel(article, 4, 3, 2), "E");
    REQUIRE(E);
    CHECK(std::get<Vec3d>(*E).x == 0.25);
    CHECK(std::get<Vec3d>(*E).y == -0.75);
    // Lesson 08: the light stands 0.3 in front of the wall; the wall's turned normal.
    const Scene walls = load_scene_file(source + "/lessons/scenes/floor_wall.json");
    CHECK(walls.planes.at(1).Q.x - walls.lights.at(0).L.x == Approx(0.3));
    check_states("08-planes.md", "0.3 ");
    const std::optional<StepValue> N = lesson_value(trace_pixel(walls, 15, 0, 13), "N_plane");
    REQUIRE(N);
    CHECK(std::get<Vec3d>(*N).x == -1);
    CHECK(std::get<Vec3d>(*N).y == 0);
    CHECK(std::get<Vec3d>(*N).z == 0);
    CHECK(lesson_text("en", "08-planes.md").find("N = [−1, 0, 0]") != std::string::npos);
    CHECK(lesson_text("pl", "08-planes.md").find("N = [−1; 0; 0]") != std::string::npos);
}

TEST_CASE("lesson 09: a shadow ray tested against its own sphere finds a root s of about 1e-16", "[lesson][claims]") {
    const Scene scene = load_scene_file(source + "/lessons/scenes/shadows.json");
    const Vec3d S = scene.spheres.at(0).S;
    const double r = scene.spheres.at(0).r;
    std::vector<double> roots;
    for (int i = 0; i < 8; ++i) {
        for (int j = 0; j < 8; ++j) {
            const PixelTrace trace = trace_pixel(scene, 8, i, j);
            const std::optional<StepValue> nearest = lesson_value(trace, "nearest");
            if (!nearest || std::get<std::string>(*nearest) != "sphere 0") continue;
            const Vec3d P = std::get<Vec3d>(*lesson_value(trace, "P"));
            const Vec3d K = std::get<Vec3d>(*lesson_value(trace, "light[0].K"));
            // |K|² s² − 2b s + c = 0 with b = K·(S − P), c = |S − P|² − r²: c is a rounding error.
            const Vec3d d{S.x - P.x, S.y - P.y, S.z - P.z};
            const double KK = K.x * K.x + K.y * K.y + K.z * K.z, b = K.x * d.x + K.y * d.y + K.z * d.z;
            const double c = d.x * d.x + d.y * d.y + d.z * d.z - r * r;
            const double q = b + std::copysign(std::sqrt(b * b - KK * c), b);  // the root near 0 is c/q
            if (c != 0) roots.push_back(std::fabs(c / q));
        }
    }
    REQUIRE(roots.size() >= 5);
    std::sort(roots.begin(), roots.end());
    const double median = roots[roots.size() / 2];
    INFO("median |s| " << median);
    CHECK(median > 1e-17);
    CHECK(median < 1e-15);
    check_states("09-shadows.md", "10⁻¹⁶");
}

TEST_CASE("lesson 11: the digits each type keeps, and the numbers of its exercise b)", "[lesson][claims]") {
    CHECK(std::numeric_limits<float>::digits == 24);
    CHECK(std::numeric_limits<double>::digits == 53);
    CHECK(FLT128_MANT_DIG == 113);
    CHECK(std::lround(24 * std::log10(2.0)) == 7);
    CHECK(std::lround(53 * std::log10(2.0)) == 16);
    CHECK(std::lround(113 * std::log10(2.0)) == 34);
    for (const std::string language : {"pl", "en"}) CHECK(lesson_text(language, "11-precision.md").find("113") != std::string::npos);
    // b): 2²⁶ ≈ 6.7·10⁷, 2²⁷ ≈ 1.3·10⁸; floats there 8 apart, doubles 2⁻²⁶; 99999999 is a float 10⁸.
    CHECK(std::round(std::ldexp(1.0, 26) / 1e6) / 10 == 6.7);
    CHECK(std::round(std::ldexp(1.0, 27) / 1e7) / 10 == 1.3);
    CHECK(std::nextafter(99999999.0f, 0.0f) == 99999992.0f);
    CHECK(float(99999999.0) == 1e8f);
    CHECK(std::nextafter(99999999.0, 1e9) - 99999999.0 == std::ldexp(1.0, -26));
    check_states("11-precision.md", "6.7·10⁷");
    check_states("11-precision.md", "1.3·10⁸");
    // |E|² and E·S are about 10⁸ on the far sphere's pane.
    const Scene scene = load_scene_file(source + "/lessons/scenes/far_sphere.json");
    const PixelTrace corner = trace_pixel(scene, 8, 0, 0);
    CHECK(number_of(corner, "EE") / 1e8 == Approx(1).epsilon(1e-7));
    CHECK(number_of(corner, "C") == 1e8);
}

TEST_CASE("lesson 10: its first two pixels' R·V differ by less than a fifth, their highlights by far more", "[lesson][claims]") {
    const Scene scene = load_scene_file(source + "/lessons/scenes/phong.json");
    const PixelTrace first = trace_pixel(scene, 8, 3, 5), second = trace_pixel(scene, 8, 2, 4);
    const double RV1 = number_of(first, "light[0].RV"), RV2 = number_of(second, "light[0].RV");
    CHECK(std::fabs(RV1 - RV2) < RV1 / 5);
    CHECK(number_of(second, "light[0].specular") < number_of(first, "light[0].specular") / 5);
    // 20 = 10100 in binary: 4 squarings and one product, 5 multiplications.
    CHECK(fmt::format("{:b}", 20) == "10100");
}

TEST_CASE("lesson 02: on an even pane the centre is the corner of four squares", "[lesson][claims]") {
    const Scene article = load_scene_file(source + "/lessons/scenes/article.json");
    for (const auto& [i, j] : std::vector<std::pair<int, int>>{{3, 3}, {3, 4}, {4, 3}, {4, 4}}) {
        const Vec3d E = std::get<Vec3d>(*lesson_value(trace_pixel(article, 8, i, j), "E"));
        CHECK(std::fabs(E.x) == 0.125);
        CHECK(std::fabs(E.y) == 0.125);
    }
    for (const std::string language : {"pl", "en"})
        CHECK(lesson_text(language, "02-pane.md").find("(3, 3), (3, 4), (4, 3)") != std::string::npos);
}
