// The lessons in other numeric settings: `promyk lesson --real/--formula`,
// the header's real: and formula:, settings qualifiers ({delta@float}) in
// lessons, worksheets and answer files, and the precision lesson. The numbers
// expected are computed here, in float and double, following the article's
// program and the geometric formula step by step.
#include <stdio.h>
#include <sys/wait.h>

#include <fstream>
#include <string>

#include <catch2/catch.hpp>

#include "lesson/lesson.hpp"
#include "math/real.hpp"
#include "temp_dir.hpp"

namespace {

struct Run {
    int exit_code = -1;
    std::string out;  // standard output and standard error together
};

Run run_promyk(const std::string& arguments) {
    Run run;
    FILE* pipe = ::popen((std::string(PROMYK_BINARY) + " " + arguments + " 2>&1").c_str(), "r");
    REQUIRE(pipe != nullptr);
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) run.out.append(buffer, n);
    const int status = ::pclose(pipe);
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

void write(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// The article's program for pixel (i, j) of a w × w pane, in Real, up to Δ/4.
template <class Real>
struct PrecisionArticle {
    Real EE, SS, C, delta;
};

template <class Real>
PrecisionArticle<Real> article_delta(int w, int i, int j, Real z_E, Real x_S, Real y_S, Real z_S, Real r) {
    const Real y_E = -Real(2 * i + 1) / Real(w) + Real(1);
    const Real x_E = Real(2 * j + 1) / Real(w) - Real(1);
    PrecisionArticle<Real> a;
    a.EE = x_E * x_E + y_E * y_E + z_E * z_E;
    a.SS = x_S * x_S + y_S * y_S + z_S * z_S;
    a.C = x_E * x_S + y_E * y_S + z_E * z_S;
    a.delta = a.C * a.C - a.EE * (a.SS - r * r);
    return a;
}

// The geometric discriminant (Haines et al. 2019) for a sphere on the z axis.
float geometric_delta(int w, int i, int j, float z_E, float z_S, float r) {
    const float y_E = -float(2 * i + 1) / float(w) + 1.0f;
    const float x_E = float(2 * j + 1) / float(w) - 1.0f;
    const float EE = x_E * x_E + y_E * y_E + z_E * z_E;
    const float C = x_E * 0.0f + y_E * 0.0f + z_E * z_S;
    const float t_mid = C / EE;
    const float lx = t_mid * x_E - 0.0f, ly = t_mid * y_E - 0.0f, lz = t_mid * z_E - z_S;
    const float ll = lx * lx + ly * ly + lz * lz;
    return r * r - ll;
}

// A number as English text shows it: the minus sign U+2212.
std::string precision_english(std::string text) {
    for (std::size_t at; (at = text.find('-')) != std::string::npos;) text.replace(at, 1, "\u2212");
    return text;
}

std::string polish(std::string text) {
    for (char& c : text)
        if (c == '.') c = ',';
    return precision_english(text);
}

const std::string precision_far_sphere = std::string(PROMYK_SOURCE_DIR) + "/lessons/scenes/far_sphere.json";

}  // namespace

TEST_CASE("a placeholder's settings qualifier is read and checked", "[lesson][precision]") {
    const auto found = promyk::find_placeholders("{delta@float:9} {t@geometric} {P.x@quad,stable} {delta@} {symbol:t@float}");
    REQUIRE(found.size() == 5);
    CHECK(found[0].valid);
    CHECK(found[0].path == "delta");
    CHECK(found[0].settings == "float");
    CHECK(found[0].decimals == 9);
    CHECK(found[1].settings == "geometric");
    CHECK(found[2].component == 'x');
    CHECK(found[2].settings == "quad,stable");
    CHECK_FALSE(found[3].valid);
    CHECK_FALSE(found[4].valid);  // a symbol is the same in every setting
    CHECK(promyk::parse_settings("float,geometric"));
    CHECK(promyk::parse_settings("geometric,float"));
    CHECK_FALSE(promyk::parse_settings("float,double"));
    CHECK_FALSE(promyk::parse_settings("floaty"));
    CHECK(promyk::split_settings("sphere[0].delta@quad").first == "sphere[0].delta");
    CHECK(promyk::path_key("sphere[0].delta@quad") == "delta");
}

TEST_CASE("lesson precision shows float's and double's own numbers of the far sphere", "[lesson][precision]") {
    // Pixel (3, 4) of the 8 × 8 pane; the sphere r = 1 at (0, 0, 10000), z_E = 10000.
    const PrecisionArticle<float> f = article_delta<float>(8, 3, 4, 10000.0f, 0.0f, 0.0f, 10000.0f, 1.0f);
    const PrecisionArticle<double> d = article_delta<double>(8, 3, 4, 10000.0, 0.0, 0.0, 10000.0, 1.0);
    const PrecisionArticle<double> d00 = article_delta<double>(8, 0, 0, 10000.0, 0.0, 0.0, 10000.0, 1.0);
    CHECK(f.delta <= 0);  // float loses the sphere ...
    CHECK(d.delta > 0);   // ... double keeps it
    const float g = geometric_delta(8, 3, 4, 10000.0f, 10000.0f, 1.0f);
    CHECK(g > 0);

    // Markdown keeps the lesson's lines as written (text reflows them to 80 columns).
    const Run en = run_promyk("lesson precision --lang en --format markdown");
    INFO(en.out);
    REQUIRE(en.exit_code == 0);
    CHECK_THAT(en.out, Catch::Contains("Float: Δ/4 = " + precision_english(promyk::real_text(f.delta)) + "."));
    CHECK_THAT(en.out, Catch::Contains("Double: Δ/4 = " + precision_english(promyk::real_text(d.delta)) + ";"));
    CHECK_THAT(en.out, Catch::Contains("float gives " + precision_english(promyk::real_text(f.EE)) + "."));
    CHECK_THAT(en.out, Catch::Contains("exactly, " + precision_english(promyk::real_text(d.EE)) + ";"));
    CHECK_THAT(en.out, Catch::Contains("Δ_g in float is " + precision_english(promyk::real_text(g)) + ";"));
    CHECK_THAT(en.out, Catch::Contains("(float, geometric) | " + precision_english(promyk::real_text(g)) + " |"));  // the table's float row
    CHECK_THAT(en.out, Catch::Contains("What precision costs"));

    const Run pl = run_promyk("lesson precision --lang pl --format markdown");
    INFO(pl.out);
    REQUIRE(pl.exit_code == 0);
    CHECK_THAT(pl.out, Catch::Contains("Float: Δ/4 = " + polish(promyk::real_text(f.delta)) + "."));
    CHECK_THAT(pl.out, Catch::Contains("Quad: Δ/4 = " + polish("-53124998.46875")));
    CHECK_THAT(pl.out, Catch::Contains("Double: Δ/4 = " + polish(promyk::real_text(d00.delta)) + ";"));
    CHECK_THAT(pl.out, Catch::Contains("We float Δ_g = " + polish(promyk::real_text(g)) + ","));
}

TEST_CASE("lesson --real float prints float's exact text, in both languages", "[lesson][precision]") {
    // The article's scene, pixel (3, 4), in float: 8 significant digits
    // tell float's Δ/4 (4.5578117) from double's (4.5578125); the default 4
    // would show both as 4.558.
    const PrecisionArticle<float> f = article_delta<float>(8, 3, 4, 2.0f, 0.0f, 0.0f, 3.2f, 1.1f);
    const PrecisionArticle<double> d = article_delta<double>(8, 3, 4, 2.0, 0.0, 0.0, 3.2, 1.1);
    const std::string float_text = promyk::real_text(f.delta);
    REQUIRE(float_text == "4.5578117");
    REQUIRE(promyk::real_text(d.delta) == "4.557812500000004");

    const Run en = run_promyk("lesson sphere --real float --pixel 3,4 --lang en --digits 8");
    INFO(en.out);
    REQUIRE(en.exit_code == 0);
    CHECK_THAT(en.out, Catch::Contains("Numbers: float, formula: article"));
    CHECK_THAT(en.out, Catch::Contains("(3, 4): " + float_text + "\n"));
    CHECK_THAT(en.out, Catch::Contains("(3, 4): " + promyk::real_text(f.SS) + "\n"));
    CHECK_THAT(en.out, !Catch::Contains("4.5578125"));

    const Run pl = run_promyk("lesson sphere --real float --pixel 3,4 --lang pl --digits 8");
    INFO(pl.out);
    REQUIRE(pl.exit_code == 0);
    CHECK_THAT(pl.out, Catch::Contains("(3, 4): " + polish(float_text) + "\n"));

    // The header's real: does the same; the command line overrides it.
    const Run plain = run_promyk("lesson sphere --pixel 3,4 --lang en --digits 8");
    CHECK_THAT(plain.out, Catch::Contains("(3, 4): 4.5578125\n"));
    // And by default, 4 significant digits.
    CHECK_THAT(run_promyk("lesson sphere --real float --pixel 3,4 --lang en").out, Catch::Contains("(3, 4): 4.558\n"));
}

TEST_CASE("worksheet and answers in float, and qualified answers", "[lesson][precision]") {
    promyk::testing::TempDir dir;
    const PrecisionArticle<float> f = article_delta<float>(8, 3, 4, 2.0f, 0.0f, 0.0f, 3.2f, 1.1f);

    const Run sheet = run_promyk("lesson sphere --real float --pixel 3,4 --lang en --worksheet --key");
    INFO(sheet.out);
    REQUIRE(sheet.exit_code == 0);
    std::string command = sheet.out;  // the "check with" command, its shell lines joined
    for (std::size_t at; (at = command.find(" \\\n      ")) != std::string::npos;) command.replace(at, 9, " ");
    CHECK_THAT(command, Catch::Contains("--pixel 3,4 --real float --lang en --answers"));
    CHECK_THAT(sheet.out, Catch::Contains("Δ/4 = 4.558   [delta]"));  // 4.5578117 to 4 digits

    // Float's Δ/4 is 4.557811737060546875: to 7 decimals 4.5578117. The exact Δ/4 is 4.5578125000000028…:
    // double's 4.5578125 has more digits than a float holds and lies nearer it, so it is right, and said so;
    // 4.5578100, farther from it than float's value, is wrong.
    write(dir.file("right.txt"), "delta = " + promyk::real_text(f.delta) + "\n");
    write(dir.file("nearer.txt"), "delta = 4.5578125\n");
    write(dir.file("wrong.txt"), "delta = 4.5578100\n");
    const Run right = run_promyk("lesson sphere --real float --pixel 3,4 --lang en --answers " + dir.file("right.txt"));
    CHECK(right.exit_code == 0);
    const Run nearer = run_promyk("lesson sphere --real float --pixel 3,4 --lang en --answers " + dir.file("nearer.txt"));
    CHECK(nearer.exit_code == 0);
    CHECK_THAT(nearer.out, Catch::Contains("4.5578125: right, and more digits than a float holds"));
    const Run wrong = run_promyk("lesson sphere --real float --pixel 3,4 --lang en --answers " + dir.file("wrong.txt"));
    CHECK(wrong.exit_code == 1);
    CHECK_THAT(wrong.out, Catch::Contains("4.5578117"));

    // The precision lesson's worksheet asks for qualified values; its answers name them.
    const Run precision_sheet = run_promyk("lesson precision --lang en --worksheet");
    CHECK(precision_sheet.exit_code == 0);
    CHECK_THAT(precision_sheet.out, Catch::Contains("delta_g@float,geometric = "));
    const float g = geometric_delta(8, 3, 4, 10000.0f, 10000.0f, 1.0f);
    write(dir.file("qualified_right.txt"), "[3,4]\ndelta@float = 0\ndelta_g@float,geometric = " + promyk::real_text(g) + "\n");
    // Double's 0.9687500000097656 would be right (more digits than a float holds, nearer the exact value); this is not.
    write(dir.file("qualified_wrong.txt"), "[3,4]\ndelta_g@float,geometric = 0.9697500000097656\n");
    write(dir.file("qualified_bad.txt"), "delta@floaty = 0\n");
    CHECK(run_promyk("lesson precision --lang en --answers " + dir.file("qualified_right.txt")).exit_code == 0);
    CHECK(run_promyk("lesson precision --lang en --answers " + dir.file("qualified_wrong.txt")).exit_code == 1);
    // Nothing else to read: the file is refused at its unreadable line.
    const Run bad = run_promyk("lesson precision --lang en --answers " + dir.file("qualified_bad.txt"));
    CHECK(bad.exit_code == 3);
    CHECK_THAT(bad.out, Catch::Contains("qualified_bad.txt: line 1: \"delta@floaty\""));
}

TEST_CASE("a bad real:, formula: or qualifier is a fault of the lesson, with its file and line", "[lesson][precision]") {
    promyk::testing::TempDir dir;
    std::filesystem::create_directories(dir.path / "en");
    const std::string header = "---\nname: demo\ntitle: T\nsummary: S\n";
    const std::string body = "---\n\n## [a] A\n\n::: pixel\nΔ/4 = {delta@float}\n:::\n";
    const auto run_with = [&](const std::string& text, const std::string& arguments) {
        write((dir.path / "en" / "99-demo.md").string(), text);
        return run_promyk("lesson " + arguments + " --lessons " + dir.path.string() + " --lang en");
    };

    const Run good = run_with(header + "real: float\n" + body, "demo");
    INFO(good.out);
    CHECK(good.exit_code == 0);
    CHECK_THAT(good.out, Catch::Contains("Numbers: float, formula: article"));

    const Run bad_real = run_with(header + "real: floaty\n" + body, "demo");
    CHECK(bad_real.exit_code == 3);
    CHECK_THAT(bad_real.out, Catch::Contains("en/99-demo.md: line 5: bad value of \"real\""));
    const Run bad_formula = run_with(header + "formula: magic\n" + body, "demo");
    CHECK(bad_formula.exit_code == 3);
    CHECK_THAT(bad_formula.out, Catch::Contains("en/99-demo.md: line 5: bad value of \"formula\""));

    const std::string bad_body = "---\n\n## [a] A\n\n::: pixel\nΔ/4 = {delta@floaty}\n:::\n";
    const Run bad_qualifier = run_with(header + bad_body, "demo");
    CHECK(bad_qualifier.exit_code == 3);
    CHECK_THAT(bad_qualifier.out, Catch::Contains("en/99-demo.md: line 10: \"delta@floaty\""));
    const Run checked = run_with(header + bad_body, "--check");
    CHECK(checked.exit_code == 1);
    CHECK_THAT(checked.out, Catch::Contains("en/99-demo.md:10: \"delta@floaty\": after @ comes"));
    const Run bad_table = run_with(header + "---\n\n## [a] A\n\n= delta@float,double\n", "--check");
    CHECK(bad_table.exit_code == 1);
    CHECK_THAT(bad_table.out, Catch::Contains("en/99-demo.md:9: \"delta@float,double\""));
}
