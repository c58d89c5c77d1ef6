// promyk bench accuracy (src/bench/accuracy.hpp): the errors and branch
// counts on real values, checked against what the geometry says
// independently; the table and the JSON of a tiny run. Timings are never
// asserted (they depend on the machine and its load).
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "bench/accuracy.hpp"
#include "flat_text.hpp"
#include "render/kernel.hpp"
#include "scene/scene.hpp"
#include "trace/messages.hpp"
#include "util/text.hpp"

using namespace promyk;
using namespace promyk::bench;

namespace {

PaneValues values_of(const Scene& scene, RealType real, Formula formula, int spp, int w) {
    return pane_values(*make_kernel(scene, real, formula, spp), w, 2);
}

// Pixels whose centre ray (through E = (x_E, y_E, z_E), spp 1) meets the
// sphere, from the ray's distance to the centre: d² = |S|² − (E·S)²/|E|² < r²,
// in long double, with every pixel required to be clearly inside or outside
// (no tangent ray whose side rounding could decide).
long long pixels_hit(const Scene& scene, int w) {
    const Sphere& sphere = scene.spheres.at(0);
    const long double Sx = sphere.S.x, Sy = sphere.S.y, Sz = sphere.S.z, r = sphere.r;
    long long hits = 0;
    for (int i = 0; i < w; ++i) {
        for (int j = 0; j < w; ++j) {
            const long double x = (2.0L * j + 1) / w - 1, y = -(2.0L * i + 1) / w + 1, z = scene.z_E;
            const long double ES = x * Sx + y * Sy + z * Sz, EE = x * x + y * y + z * z;
            const long double d2 = Sx * Sx + Sy * Sy + Sz * Sz - ES * ES / EE;
            REQUIRE(std::fabs(static_cast<double>(d2 - r * r)) > 1e-6);
            if (d2 < r * r) ++hits;
        }
    }
    return hits;
}

}  // namespace

TEST_CASE("the far sphere covers about half the pane and is mostly lit", "[bench][accuracy]") {
    const Scene far = far_sphere_scene();
    REQUIRE(far.spheres.size() == 1);
    REQUIRE(far.lights.size() == 1);
    CHECK(far.spheres[0].S.z == 1e4);
    CHECK(far.spheres[0].r == 1);
    const int w = 64;
    const long long hits = pixels_hit(far, w);
    CHECK(hits > w * w * 4 / 10);
    CHECK(hits < w * w * 6 / 10);
    // In the reference, about nine tenths of the sphere's pixels are lit.
    const PaneValues reference = values_of(far, RealType::quad_, Formula::geometric, 1, w);
    long long lit = 0, sphere = 0;
    for (const Branch b : reference.branch) {
        lit += b == Branch::lit;
        sphere += b != Branch::miss;
    }
    CHECK(sphere == hits);
    CHECK(lit > sphere * 8 / 10);
    CHECK(lit < sphere);  // and some are on the dark side
}

TEST_CASE("the article's formula in float loses the far sphere: every pixel it covers has the wrong branch",
          "[bench][accuracy]") {
    const Scene far = far_sphere_scene();
    const int w = 48;
    const long long hits = pixels_hit(far, w);
    const PaneValues reference = values_of(far, RealType::quad_, Formula::geometric, 1, w);
    const PaneValues run = values_of(far, RealType::float_, Formula::article, 1, w);
    for (const Branch b : run.branch) REQUIRE(b == Branch::miss);
    const ErrorStats stats = compare_to_reference(run, reference);
    CHECK(stats.pixels == w * w);
    CHECK(stats.sphere_pixels == hits);
    CHECK(stats.branch_differs == hits);
    CHECK(stats.non_finite == 0);
    // A lit pixel shown as the background 1/2: the largest error is the
    // brightest lit pixel's distance from 1/2 or the dark side's 1/2.
    double largest = 0;
    for (std::size_t k = 0; k < reference.I.size(); ++k) largest = std::max(largest, std::fabs(reference.I[k] - 0.5));
    CHECK(stats.max_error == largest);
    CHECK(stats.median_error > 0.1);
}

TEST_CASE("the geometric formula keeps the far sphere in float and double", "[bench][accuracy]") {
    const Scene far = far_sphere_scene();
    const int w = 48;
    const PaneValues reference = values_of(far, RealType::quad_, Formula::geometric, 1, w);
    for (const RealType real : {RealType::float_, RealType::double_}) {
        const ErrorStats stats = compare_to_reference(values_of(far, real, Formula::geometric, 1, w), reference);
        CAPTURE(real_type_name(real));
        CHECK(stats.branch_differs == 0);
        CHECK(stats.max_error < (real == RealType::float_ ? 1e-2 : 1e-9));
    }
}

TEST_CASE("double with the article's formula on the article's scene: a typical error of an ulp or two, the largest "
          "at the silhouette", "[bench][accuracy]") {
    const Scene article = article_scene();
    const int w = 64;
    const PaneValues reference = values_of(article, RealType::quad_, Formula::geometric, 1, w);
    const PaneValues run = values_of(article, RealType::double_, Formula::article, 1, w);
    const ErrorStats stats = compare_to_reference(run, reference);
    CHECK(stats.branch_differs == 0);
    CHECK(stats.non_finite == 0);
    CHECK(stats.sphere_pixels == pixels_hit(article, w));
    // Both intensities are compared as doubles: an ulp of I in [1/4, 1/2) is 5.6e-17.
    CHECK(stats.median_error <= 2.3e-16);
    // The largest error is some 50 times larger, at a ray that grazes the
    // sphere: there Δ/4 = C² − |E|²(|S|² − r²) is a small difference of large
    // numbers, and its square root passes the cancellation on to t and P.
    CHECK(stats.max_error > 1e-15);
    CHECK(stats.max_error <= 1e-14);
    std::size_t worst = 0;
    for (std::size_t k = 0; k < run.I.size(); ++k)
        if (std::fabs(run.I[k] - reference.I[k]) > std::fabs(run.I[worst] - reference.I[worst])) worst = k;
    const int i = static_cast<int>(worst) / w, j = static_cast<int>(worst) % w;
    const long double x = (2.0L * j + 1) / w - 1, y = -(2.0L * i + 1) / w + 1, z = article.z_E;
    const Vec3d S = article.spheres[0].S;
    const long double ES = x * S.x + y * S.y + z * S.z, EE = x * x + y * y + z * z;
    const long double d2 = S.x * S.x + S.y * S.y + S.z * S.z - ES * ES / EE;  // the ray's distance² to the centre
    const long double r = article.spheres[0].r;
    CAPTURE(i, j, static_cast<double>(d2 / (r * r)));
    CHECK(d2 / (r * r) > 0.9);
    // The same at spp 4: each sample's error is of that size, and so is their mean's.
    const ErrorStats sampled = compare_to_reference(values_of(article, RealType::double_, Formula::article, 4, w),
                                                    values_of(article, RealType::quad_, Formula::geometric, 4, w));
    CHECK(sampled.branch_differs == 0);
    CHECK(sampled.median_error <= 2.3e-16);
    CHECK(sampled.max_error <= 1e-14);
}

TEST_CASE("the reference against itself has no error", "[bench][accuracy]") {
    const PaneValues reference = values_of(article_scene(), RealType::quad_, Formula::geometric, 4, 16);
    const ErrorStats stats = compare_to_reference(reference, reference);
    CHECK(stats.max_error == 0);
    CHECK(stats.median_error == 0);
    CHECK(stats.branch_differs == 0);
}

TEST_CASE("errors: max over every pixel, median over the reference's sphere pixels, non-finite as infinite",
          "[bench][accuracy]") {
    PaneValues reference, run;
    reference.w = run.w = 2;
    reference.I = {0.5, 0.25, 0.75, 0};
    reference.branch = {Branch::miss, Branch::lit, Branch::lit, Branch::dark};
    run.I = {0.5, 0.25 + 1e-3, 0.75 - 4e-3, 0.5};
    run.branch = {Branch::miss, Branch::lit, Branch::lit, Branch::miss};
    ErrorStats stats = compare_to_reference(run, reference);
    CHECK(stats.pixels == 4);
    CHECK(stats.sphere_pixels == 3);
    CHECK(stats.max_error == 0.5);
    CHECK(stats.median_error == Approx(4e-3).epsilon(1e-12));
    CHECK(stats.branch_differs == 1);
    CHECK(stats.non_finite == 0);

    run.I[1] = NAN;
    run.branch[1] = Branch::non_finite;
    stats = compare_to_reference(run, reference);
    CHECK(std::isinf(stats.max_error));
    CHECK(stats.non_finite == 1);
    CHECK(stats.branch_differs == 2);
    CHECK(stats.median_error == 0.5);  // 4e-3, 0.5 and infinity
}

TEST_CASE("a tiny run: one row per scene x spp x type x formula, the baseline timed even when not listed, "
          "every ratio given",
          "[bench][accuracy]") {
    AccuracyOptions options;
    options.w = 6;
    options.repetitions = 1;
    options.spps = {1, 4};
    options.reals = {RealType::float_, RealType::quad_};
    options.formulas = {Formula::article, Formula::geometric};
    const AccuracyReport report = run_accuracy_bench(options);
    REQUIRE(report.scenes.size() == 2);
    CHECK(report.scenes[0].name == "article");
    CHECK(report.scenes[1].name == "far_sphere");
    REQUIRE(report.rows.size() == 2 * 2 * 2 * 2);
    for (const AccuracyScene& scene : report.scenes) CHECK(scene.base_ns_per_pixel > 0);
    for (const AccuracyRow& row : report.rows) {
        CHECK(row.ns_per_pixel > 0);
        CHECK(row.ratio > 0);  // a 6 × 6 pane is repeated until a run lasts 20 ms: every ratio is given
        CHECK(row.untimed.empty());
        CHECK(row.timed_w >= 4);
        CHECK(row.errors.pixels == 36);
        if (row.real == RealType::quad_ && row.formula == Formula::geometric) CHECK(row.errors.max_error == 0);
    }
    CHECK(report.timeable);
    CHECK(report.shortest_ms >= 20);
    // Timed as promyk render runs without --stats (and as bench speed and
    // effects time it): no timed kernel counts every branch, and both say so.
    CHECK_FALSE(report.counted_branches);

    const Language before = ui_language();
    set_ui_language(Language::en);
    const std::string table = accuracy_table(report);
    CHECK(table.find("scene far_sphere:\n  z_E = 8000, S = (0, 0, 10000), r = 1, L = (5000, 5000, 0), I = 1\n") !=
          std::string::npos);
    CHECK(table.find("no ratio") == std::string::npos);
    CHECK(flat(table).find("Times are measured as promyk render runs without --stats") != std::string::npos);
    CHECK(table.find("spp 4: ") != std::string::npos);
    set_ui_language(Language::pl);
    const std::string polish = accuracy_table(report);
    set_ui_language(before);
    CHECK(polish.find("scena far_sphere:\n  z_E = 8000; S = (0; 0; 10000); r = 1; L = (5000; 5000; 0); I = 1\n") !=
          std::string::npos);
    CHECK(polish.find("36 pikseli na szybę") != std::string::npos);  // w = 6
    CHECK(flat(polish).find("jak działa promyk render bez --stats") != std::string::npos);
    // Both languages fit 80 columns, and the Polish table has no English heading.
    for (const std::string* text : {&table, &polish}) {
        std::size_t start = 0;
        for (std::size_t end; (end = text->find('\n', start)) != std::string::npos; start = end + 1) {
            INFO(text->substr(start, end - start));
            CHECK(display_width(std::string_view(*text).substr(start, end - start)) <= 80);
        }
    }
    for (const char* english : {"formula", "medians", "scene ", "pixels", "the whole run"}) {
        INFO(english);
        CHECK(polish.find(english) == std::string::npos);
    }

    const nlohmann::json report_json = nlohmann::json::parse(accuracy_json(report));
    CHECK(report_json["bench"] == "accuracy");
    CHECK(report_json["w"] == 6);
    REQUIRE(report_json["results"].size() == 16);
    for (const nlohmann::json& result : report_json["results"]) {
        CHECK(result["ratio"].is_number());
        CHECK_FALSE(result.contains("untimed"));
    }
    CHECK(report_json["timeable"] == true);
    CHECK(report_json["counts_branches"] == false);
    CHECK(report_json["scenes"][1]["scene_content"]["spheres"][0]["r"] == 1);
}

TEST_CASE("the bench's reference, quad/geometric, agrees with the mpmath reference to the last bit of a double",
          "[bench][accuracy]") {
    // tests/reference/article_reference.json: the article's scene at 200 bits
    // (make_reference.py). Panes whose side is a power of two only: there
    // x_E and y_E are exact in double and quad alike, as the reference takes them.
    std::ifstream file(PROMYK_SOURCE_DIR "/tests/reference/article_reference.json");
    REQUIRE(file);
    const nlohmann::json reference = nlohmann::json::parse(file);
    const std::unique_ptr<Kernel> bench_reference = make_kernel(article_scene(), RealType::quad_, Formula::geometric, 1);
    int checked = 0;
    for (const nlohmann::json& pixel : reference["pixels"]) {
        const int w = pixel["w"], i = pixel["i"], j = pixel["j"];
        if ((w & (w - 1)) != 0) continue;
        Branch branch{};
        const double I = bench_reference->intensity(w, i, j, &branch).x;
        const double exact = std::stod(pixel["result"]["exact"].get<std::string>());  // the double nearest it
        CAPTURE(w, i, j, I, exact);
        CHECK(branch_name(branch) == pixel["branch"].get<std::string>());
        CHECK(I == exact);
        ++checked;
    }
    CHECK(checked == 1 + 64 + 274);
}
