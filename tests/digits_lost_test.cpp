// Digits lost (trace/digits_lost.hpp): the estimate on every traced
// subtraction that can cancel, checked against values computed here by hand,
// its bounds and keys over many random scenes in every real type and
// formula, the text trace's mark at 3 digits and its suggestion of the
// geometric formula, and rendering unchanged (traced equals untraced).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/sphere_formulas.hpp"
#include "render/kernel.hpp"
#include "render/trace_pixel.hpp"
#include "trace/digits_lost.hpp"
#include "trace/recorder.hpp"
#include "trace/trace_text.hpp"
#include "trace/vocabulary.hpp"
#include "same_bits.hpp"

using namespace promyk;

namespace {

// The step `key` at the top level or in the first group that has it.
const Step& lost_step_of(const std::vector<Step>& steps, Key key) {
    for (const Step& step : steps)
        if (step.key == key) return step;
    FAIL("no step " << key_name(key));
    return steps.front();
}

template <class Real>
std::vector<Step> article_steps(const Vec3<Real>& E, const Vec3<Real>& S, Real r) {
    RecordingRecorder record;
    intersect_sphere_article(E, S, r, record);
    return record.take_steps();
}

double full_digits_of(const std::string& real) {
    if (real == "float") return full_digits<float>();
    if (real == "double") return full_digits<double>();
    if (real == "long-double") return full_digits<long double>();
    return full_digits<quad>();
}

using promyk::testing::same_bits;

// The keys whose steps carry an estimate (docs/traces.md: digits lost; the schema).
const std::set<Key> estimated_keys = {Key::C,   Key::c_0, Key::delta, Key::delta_fma, Key::t,     Key::t_far,
                                      Key::q,   Key::l,   Key::delta_g, Key::N,       Key::K,     Key::D,
                                      Key::NE,  Key::b_s, Key::c_s,   Key::delta_s,   Key::s_1,   Key::s_2,
                                      Key::NK,  Key::s,   Key::R_hat, Key::RV};

}  // namespace

TEST_CASE("digits lost: the definition, by hand", "[digits-lost]") {
    CHECK(digits_lost(1000.0, 1.0) == Approx(3.0).margin(1e-12));
    CHECK(sum_digits_lost(10.0, -9.99, 0.01) == Approx(3.0).margin(1e-9));  // a + b of opposite signs
    CHECK(sum_digits_lost(2.0, 3.0, 5.0) == 0);                               // one sign: nothing cancels
    CHECK(sum_digits_lost(0.0, 0.0, 0.0) == 0);                               // nothing to lose
    // An exact cancellation loses every digit: the type's p·log10(2).
    CHECK(sum_digits_lost(1.0f, 1.0f, 0.0f) == Approx(24 * std::log10(2.0)));
    CHECK(sum_digits_lost(1.0, 1.0, 0.0) == Approx(53 * std::log10(2.0)));
    CHECK(sum_digits_lost(quad(1), quad(1), quad(0)) == Approx(113 * std::log10(2.0)));
    CHECK(full_digits<float>() == Approx(7.22).margin(0.01));
    CHECK(full_digits<double>() == Approx(15.95).margin(0.01));
    CHECK(full_digits<quad>() == Approx(34.02).margin(0.01));
    // Non-finite: no estimate.
    CHECK(std::isnan(sum_digits_lost(std::numeric_limits<double>::infinity(), 1.0, 2.0)));
    CHECK(std::isnan(sum_digits_lost(1.0, 1.0, std::numeric_limits<double>::quiet_NaN())));
    // A quad far beyond the range of a double: the logs are taken in quad.
    const quad huge = ldexpq(quad(1), 5000), tiny = ldexpq(quad(1), 4900);
    CHECK(sum_digits_lost(huge, huge - tiny, tiny) == Approx(100 * std::log10(2.0)).margin(1e-9));
    // Vectors: the operands' largest component against the result's (100
    // against 4: the y component's cancellation costs the vector only what
    // its length says); dot products: the largest term.
    CHECK(sum_digits_lost(Vec3d{1, 100, 5}, Vec3d{0, 99.9, 1}, Vec3d{1, 0.1, 4}) == Approx(std::log10(25.0)).margin(1e-12));
    CHECK(sum_digits_lost(Vec3d{1, 100, 5}, Vec3d{1, 100, 5}, Vec3d{0, 0, 0}) == Approx(53 * std::log10(2.0)));
    CHECK(dot_digits_lost(Vec3d{1, 1, 0}, Vec3d{1000, -999, 0}, 1.0) == Approx(3.0).margin(1e-12));
    CHECK(dot_digits_lost(Vec3d{1, 2, 3}, Vec3d{1, 1, 1}, 6.0) == 0);
}

TEST_CASE("digits lost: the article's pixel (3, 4), by hand", "[digits-lost]") {
    const PixelTrace trace = trace_pixel(article_scene(), 8, 3, 4);
    // delta = C^2 - |E|^2 (|S|^2 - r^2) with C = 6.4, C^2 = 40.96 the larger
    // operand (|E|^2 (|S|^2 - r^2) = 4.03125 * 9.03 = 36.4), delta = 4.5578125.
    CHECK(lost_step_of(trace.steps, Key::delta).digits_lost == Approx(std::log10(40.96 / 4.5578125)).epsilon(1e-12));
    // t's numerator C - sqrt(delta): 6.4 against 6.4 - 2.13490...
    const double root = std::sqrt(4.5578125);
    CHECK(lost_step_of(trace.steps, Key::t).digits_lost == Approx(std::log10(6.4 / (6.4 - root))).epsilon(1e-9));
    // C = 0.125*0 + 0.125*0 + 2*3.2: nothing cancels.
    CHECK(lost_step_of(trace.steps, Key::C).digits_lost == 0);
    // N = P - S: the largest operand 3.2 (S.z) against N's largest
    // component, its z, P.z - 3.2.
    const Vec3d P = std::get<Vec3d>(lost_step_of(trace.steps, Key::P).value);
    CHECK(lost_step_of(trace.steps, Key::N).digits_lost == Approx(std::log10(3.2 / (3.2 - P.z))).epsilon(1e-9));
    // K = L - P: the largest operand P.z (about 2.1) against K's largest
    // component, its x, 1.5 - P.x.
    CHECK(lost_step_of(trace.steps, Key::K).digits_lost == Approx(std::log10(P.z / (1.5 - P.x))).epsilon(1e-9));
    // D: three positive terms, nothing cancels.
    CHECK(lost_step_of(trace.steps, Key::D).digits_lost == 0);
    // No estimate where nothing is subtracted.
    for (const Key key : {Key::E, Key::EE, Key::SS, Key::Delta, Key::P, Key::KK, Key::cos_alpha})
        CHECK(std::isnan(lost_step_of(trace.steps, key).digits_lost));
    // The stable formula's q adds two numbers of one sign: 0.
    const PixelTrace stable = trace_pixel(article_scene(), 8, 3, 4, RealType::double_, Formula::stable);
    CHECK(lost_step_of(stable.steps, Key::q).digits_lost == 0);
    // JSON: rounded to one decimal, only where there is an estimate.
    std::string line;
    append_trace_json(line, trace);
    const nlohmann::json line_json = nlohmann::json::parse(line);
    for (const auto& step : line_json["steps"]) {
        if (step["key"] == "delta") CHECK(step["digits_lost"] == 1.0);
        if (step["key"] == "t") CHECK(step["digits_lost"] == 0.2);
        if (step["key"] == "EE" || step["key"] == "E") CHECK_FALSE(step.contains("digits_lost"));
    }
}

TEST_CASE("digits lost: a unit sphere 10^4 away loses every digit of delta in float", "[digits-lost]") {
    // A ray passing 0.9 from the centre of a unit sphere at distance 10^4:
    // E = (x, 0, 2) with x = 1.8e-4; S = (0, 0, 10^4), r = 1.
    // By hand, with exact numbers: C = 2·10^4, C^2 = 4·10^8, and
    // delta = C^2 - |E|^2 (|S|^2 - 1) = 4 - x^2 (10^8 - 1) = 0.76 + x^2:
    // delta cancels log10(4e8 / 0.76) = 8.72 digits, more than float has.
    const double x = 1.8e-4;
    const double exact_delta = 4 - x * x * (1e8 - 1);
    const double by_hand = std::log10(4e8 / exact_delta);
    CHECK(by_hand == Approx(8.7212).margin(1e-4));

    // In double, delta keeps about 7 of its 16 digits: the estimate is the hand's.
    const auto in_double = article_steps(Vec3d{x, 0, 2}, Vec3d{0, 0, 1e4}, 1.0);
    CHECK(lost_step_of(in_double, Key::delta).digits_lost == Approx(by_hand).margin(1e-6));

    // In float, delta is rounding noise: the estimate from the float values
    // (the larger of C^2 and |E|^2 (|S|^2 - r^2) against delta), and nearly
    // every one of float's 7.2 digits.
    const auto in_float = article_steps(Vec3<float>{float(x), 0, 2}, Vec3<float>{0, 0, 1e4f}, 1.0f);
    const double C = std::get<double>(lost_step_of(in_float, Key::C).value);
    const double EE = std::get<double>(lost_step_of(in_float, Key::EE).value);
    const double SS = std::get<double>(lost_step_of(in_float, Key::SS).value);
    const double delta = std::get<double>(lost_step_of(in_float, Key::delta).value);
    const double lost = lost_step_of(in_float, Key::delta).digits_lost;
    if (delta == 0) {
        CHECK(lost == full_digits<float>());
    } else {
        const double c_0 = static_cast<float>(SS - 1);  // SS - r*r, rounded as float rounds it
        CHECK(lost == Approx(std::log10(std::max(C * C, EE * c_0) / std::abs(delta))).margin(1e-6));
    }
    CHECK(lost >= 6);
    CHECK(lost <= full_digits<float>());

    // The pane's centre E = (0, 0, 2): C^2 = 4e8 and |E|^2 (|S|^2 - 1) rounds
    // to 4 · 1e8 in float (10^8 - 1 needs 27 bits): delta = 0 exactly, every
    // digit lost.
    const auto centre = article_steps(Vec3<float>{0, 0, 2}, Vec3<float>{0, 0, 1e4f}, 1.0f);
    CHECK(std::get<double>(lost_step_of(centre, Key::delta).value) == 0);
    CHECK(lost_step_of(centre, Key::delta).digits_lost == full_digits<float>());

    // The geometric formula: delta_g = r^2 - |l|^2 = 1 - 0.81 cancels little.
    RecordingRecorder record;
    intersect_sphere_geometric(Vec3<float>{float(x), 0, 2}, Vec3<float>{0, 0, 1e4f}, 1.0f, record);
    const auto geometric = record.take_steps();
    CHECK(lost_step_of(geometric, Key::delta_g).digits_lost < 1);
}

TEST_CASE("digits lost: the text trace counts 3 digits or more, and marks and advises only losses that matter",
          "[digits-lost]") {
    const Vocabulary& vocabulary = builtin_vocabulary();
    PixelTrace trace = trace_pixel(article_scene(), 8, 3, 4);
    auto delta = [&]() -> Step& {
        for (Step& step : trace.steps)
            if (step.key == Key::delta) return step;
        throw std::logic_error("no delta");
    };
    auto text = [&](Language language = Language::en) {
        TraceTextOptions options;
        options.language = language;
        return format_trace_text(trace, vocabulary, options);
    };
    const std::string suggestion = "--formula geometric";
    // The article's pixel loses at most one digit: no count, no mark, no note.
    CHECK(text().find("digits lost") == std::string::npos);

    delta().digits_lost = 2.94;  // shown as 2.9: below the count's threshold
    CHECK(text().find("digits lost") == std::string::npos);
    delta().digits_lost = 2.96;  // shown as 3.0: counted, harmless in double (16 digits)
    CHECK(text().find("= 4.557812500000004\n                3.0 of 16 digits lost\n") != std::string::npos);
    CHECK(text().find("⚠") == std::string::npos);
    CHECK(text().find(suggestion) == std::string::npos);
    // Double's half is 53·log10(2)/2 = 7.98: 7.9 survives it, 8.1 does not.
    delta().digits_lost = 7.9;
    CHECK(text().find("⚠") == std::string::npos);
    delta().digits_lost = 8.1;
    CHECK(text().find("= 4.557812500000004\n                ⚠ 8.1 of 16 digits lost\n") != std::string::npos);
    const auto flat = [](std::string t) {
        for (std::size_t at; (at = t.find("\n  ")) != std::string::npos;) t.replace(at, 3, " ");
        for (std::size_t at; (at = t.find("  ")) != std::string::npos;) t.replace(at, 2, " ");
        return t;
    };
    CHECK(flat(text()).find("(it loses more than 8.0)") != std::string::npos);
    CHECK(flat(text()).find("Δ/4 loses 8.1 significant digits: the article formula") != std::string::npos);
    CHECK(text().find(suggestion) != std::string::npos);
    CHECK(text(Language::pl).find("⚠ straconych cyfr: 8,1 z 16") != std::string::npos);
    CHECK(text(Language::pl).find("--formula geometric") != std::string::npos);
    {
        TraceTextOptions wide;
        wide.layout = TraceLayout::wide;
        CHECK(format_trace_text(trace, vocabulary, wide).find("4.557812500000004  ⚠ 8.1 of 16 digits lost") !=
              std::string::npos);
    }
    // In float (7.22 digits) the half is 3.61: 3.7 digits lost is marked.
    trace.header.real = "float";
    delta().digits_lost = 3.7;
    CHECK(text().find("⚠ 3.7 of 7 digits lost") != std::string::npos);
    trace.header.real = "double";
    // The geometric formula's trace does not suggest itself.
    delta().digits_lost = 8.1;
    trace.header.formula = "geometric";
    CHECK(text().find("⚠ 8.1 of 16 digits lost") != std::string::npos);
    CHECK(text().find(suggestion) == std::string::npos);
    // A step the formula does not change (N) is marked, with no suggestion.
    trace.header.formula = "article";
    delta().digits_lost = 1;
    for (Step& step : trace.steps)
        if (step.key == Key::N) step.digits_lost = 9.5;
    CHECK(text().find("⚠ 9.5 of 16 digits lost") != std::string::npos);
    CHECK(text().find(suggestion) == std::string::npos);
}

TEST_CASE("digits lost: the article's dark pixel (5, 1) counts its 3 digits, with no mark and no advice",
          "[digits-lost]") {
    const std::string text = format_trace_text(trace_pixel(article_scene(), 8, 5, 1), builtin_vocabulary(), {});
    CHECK(text.find("3.0 of 16 digits lost") != std::string::npos);
    CHECK(text.find("⚠") == std::string::npos);
    CHECK(text.find("--formula geometric") == std::string::npos);
}

TEST_CASE("digits lost: bounded, on the documented keys only, and rendering unchanged, over random scenes",
          "[digits-lost]") {
    std::mt19937_64 random(20261130);
    std::uniform_real_distribution<double> unit(-1, 1), positive(0.2, 3), depth(2, 30), far(1e3, 1e6);
    const RealType reals[] = {RealType::float_, RealType::double_, RealType::long_double, RealType::quad_};
    int estimates = 0, marked = 0, checked = 0;
    for (int n = 0; n < 40; ++n) {
        Scene scene;
        scene.z_E = positive(random);
        const bool article = n % 4 == 0;
        // Some spheres far away, where delta cancels.
        const double z = n % 3 == 0 ? far(random) : depth(random);
        scene.spheres = {Sphere{{unit(random) * 2, unit(random) * 2, z}, positive(random) * (n % 3 == 0 ? 0.3 : 1)}};
        scene.lights = {Light{{unit(random) * 5, unit(random) * 5, unit(random) * 5}, 1}};
        if (!article) {
            scene.spheres.push_back(Sphere{{unit(random) * 3, unit(random) * 3, depth(random)}, positive(random)});
            scene.planes = {Plane{{0, -1.5, 0}, {unit(random) * 0.2, 1, unit(random) * 0.2}}};
            scene.lights.push_back(Light{{unit(random) * 5, 5, unit(random) * 5}, 0.5});
            scene.shadows = n % 2 == 1;
            scene.materials = {Material{0.1, 0.8, 0.5, 1 + n % 20, white}};
            scene.spheres[0].material = 0;
        }
        const int w = 7;
        for (const RealType real : reals) {
            for (const Formula formula : all_formulas) {
                const auto kernel = make_kernel(scene, real, formula);
                const TraceHeader header = trace_header(scene, w);
                for (int i = 0; i < w; i += 2) {
                    for (int j = 0; j < w; j += 2) {
                        const PixelTrace trace = kernel->trace(header, i, j);
                        INFO("scene " << n << ", " << trace.header.real << ", " << trace.header.formula
                                      << ", pixel (" << i << ", " << j << ")");
                        double largest = 0;
                        for (const Step& step : trace.steps) {
                            if (std::isnan(step.digits_lost)) continue;
                            INFO("step " << key_name(step.key) << ": " << step.digits_lost);
                            CHECK(estimated_keys.count(step.key) == 1);
                            CHECK(std::isfinite(step.digits_lost));
                            CHECK(step.digits_lost >= 0);
                            CHECK(step.digits_lost <= full_digits_of(trace.header.real) + 1e-9);
                            largest = std::max(largest, step.digits_lost);
                            ++estimates;
                            marked += loses_many_digits(step.digits_lost);
                        }
                        // The discriminant of the eye's ray always has one when it is finite.
                        for (const Step& step : trace.steps)
                            if ((step.key == Key::delta || step.key == Key::delta_fma || step.key == Key::delta_g) &&
                                std::isfinite(std::get<double>(step.value)))
                                CHECK_FALSE(std::isnan(step.digits_lost));
                        // The map's estimate is the trace's largest, without a trace.
                        CHECK(kernel->digits_lost(w, i, j) == largest);
                        // Tracing (and estimating) changes nothing: the intensity
                        // rendering computes is the trace's, bit for bit.
                        Branch branch;
                        const Vec3d untraced = kernel->intensity(w, i, j, &branch);
                        CHECK(branch == trace.branch);
                        if (trace.result_rgb) {
                            CHECK(same_bits(untraced.x, trace.result_rgb->x));
                            CHECK(same_bits(untraced.y, trace.result_rgb->y));
                            CHECK(same_bits(untraced.z, trace.result_rgb->z));
                        } else {
                            CHECK(same_bits(untraced.x, trace.result));
                        }
                        ++checked;
                    }
                }
            }
        }
    }
    CHECK(checked == 40 * 4 * 4 * 16);
    CHECK(estimates > 10000);
    CHECK(marked > 100);  // the far spheres lose many digits
}
