// The tracer against an independent high-precision reference
// (tests/reference/article_reference.json, made by make_reference.py with
// mpmath at 200 bits; see tests/reference/README.md), and the same checks on
// scenes that are not the article's (tests/reference/scenes_reference.json,
// made by make_reference.py --scenes from the scene files in
// tests/reference/scenes/: off-axis centres, I != 1, backgrounds != 1/2,
// z_E != 2, and pixels where delta or D is exactly 0 in double).
//
// For every pixel listed there the tracer's trace must have
// - the reference's branch (when the reference is certain of it);
// - the reference's keys, in order (a miss stops after delta, a dark pixel
//   after D), among the steps that are the program's variables (steps the
//   tracer adds for lessons are skipped: values are matched by key);
// - every recorded value, each vector component, and the result inside the
//   reference's rigorous enclosure [lo, hi] of what an IEEE double program
//   performing the article's operations in the article's order can produce;
// - every value equal, bit for bit, to the reference's `double`: the
//   article's program evaluated with Python floats (IEEE, no FMA), which a
//   correctly compiled tracer reproduces exactly (the enclosure alone would
//   let an FMA-contracted build through: fusing stays within one rounding);
// - every value within an error bound of the exact value that is derived
//   below, quantity by quantity, from the operations that produce it.
//
// The error bounds. u = 2^-53 is the unit roundoff: a correctly rounded
// operation returns (a op b)(1 + d) with |d| <= u (plus at most 2^-1075 in the
// subnormal range, which this scene never reaches). An error bound of k u
// relative is less than k ulp of the exact value. The program's inputs (the
// pane point E and the scene's numbers) are exact: the reference takes the
// exact values of the same doubles. A quantity computed from inputs that
// carry errors e_a, e_b has the error of the exact operation on the perturbed
// inputs plus one rounding of its own:
//   a + b, a - b:  e_a + e_b                                  + u |result|
//   a * b:         |a| e_b + |b| e_a + e_a e_b                + u |result|
//   a / b:         (e_a + |a/b| e_b) / (|b| - e_b)            + u |result|
//   sqrt(a):       e_a / (sqrt(a) + sqrt(max(a - e_a, 0)))    + u |result|
// (|result| meaning the exact result plus the propagated error). The test
// walks the program's operations with these rules (struct Bounded) starting
// from the exact inputs, so each quantity's bound is exactly the bound its
// derivation gives, evaluated at the pixel; the comments in
// `pixel_error_bounds` give the closed forms for the article's scene.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/trace_pixel.hpp"
#include "render/tracer.hpp"
#include "same_bits.hpp"
#include "scene/scene.hpp"
#include "scene/scene_json.hpp"
#include "trace/keys.hpp"
#include "trace/recorder.hpp"
#include "trace/trace.hpp"

namespace {

using promyk::Branch;
using promyk::Key;
using promyk::Vec3d;
using json = nlohmann::json;

constexpr long double unit_roundoff = 0x1p-53L;
constexpr long double subnormal_half_spacing = 0x1p-1075L;

const char* const reference_path = PROMYK_SOURCE_DIR "/tests/reference/article_reference.json";
const char* const scenes_reference_path = PROMYK_SOURCE_DIR "/tests/reference/scenes_reference.json";
const std::string scene_dir = PROMYK_SOURCE_DIR "/tests/reference/scenes/";

double parse_double(const json& text) {
    const std::string s = text.get<std::string>();
    char* end = nullptr;
    const double value = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size()) throw std::runtime_error("not a number: " + s);
    return value;
}

long double parse_long_double(const json& text) {
    const std::string s = text.get<std::string>();
    char* end = nullptr;
    const long double value = std::strtold(s.c_str(), &end);
    if (end != s.c_str() + s.size()) throw std::runtime_error("not a number: " + s);
    return value;
}

// p/q as long double (the pane's exact rational value; w < 2^31).
long double parse_rational(const json& text) {
    const std::string s = text.get<std::string>();
    const auto slash = s.find('/');
    if (slash == std::string::npos) throw std::runtime_error("not a fraction: " + s);
    return std::strtold(s.substr(0, slash).c_str(), nullptr) / std::strtold(s.substr(slash + 1).c_str(), nullptr);
}

// The spacing of doubles at x: 2^(e - 52) for 2^e <= |x| < 2^(e + 1).
long double ulp(long double x) {
    if (x == 0) return 0x1p-1074L;
    int e = 0;
    std::frexp(std::fabs(x), &e);  // |x| = m 2^e, m in [0.5, 1)
    return std::ldexp(1.0L, std::max(e - 53, -1074));
}

using promyk::testing::same_bits;
using promyk::testing::show_digits;

// --------------------------------------------------------------------------
// Running error bounds

// An approximation v of a quantity's exact value and a bound e on
// |computed - exact| for the double program.
struct Bounded {
    long double v = 0;
    long double e = 0;
};

Bounded exact_input(double d) { return {d, 0}; }

// One rounding of a result whose exact value is v, given the error `carried`
// of the exact operation on the computed inputs. An exact zero stays zero.
Bounded rounded(long double v, long double carried) {
    if (v == 0 && carried == 0) return {0, 0};
    return {v, carried + unit_roundoff * (std::fabs(v) + carried) + subnormal_half_spacing};
}

Bounded operator+(const Bounded& a, const Bounded& b) { return rounded(a.v + b.v, a.e + b.e); }
Bounded operator-(const Bounded& a, const Bounded& b) { return rounded(a.v - b.v, a.e + b.e); }
Bounded operator*(const Bounded& a, const Bounded& b) {
    return rounded(a.v * b.v, std::fabs(a.v) * b.e + std::fabs(b.v) * a.e + a.e * b.e);
}
Bounded operator/(const Bounded& a, const Bounded& b) {
    if (!(std::fabs(b.v) > b.e)) throw std::runtime_error("divisor may be zero");
    const long double v = a.v / b.v;
    return rounded(v, (a.e + std::fabs(v) * b.e) / (std::fabs(b.v) - b.e));
}
Bounded sqrt(const Bounded& a) {
    if (!(a.v > 0)) throw std::runtime_error("square root of a value that may be negative");
    const long double v = std::sqrt(a.v);
    return rounded(v, a.e / (v + std::sqrt(std::max(a.v - a.e, 0.0L))));
}

// Replaces the approximation by the reference's exact value (more accurate
// than the long double chain under cancellation), keeping the bound.
Bounded with_exact(Bounded b, long double exact) { return {exact, b.e}; }

struct Vec3b {
    Bounded x, y, z;
};

// The reference's exact values of one pixel, by key (a scalar is x).
struct ExactValues {
    std::map<std::string, std::vector<long double>> by_key;
    long double at(const std::string& key, std::size_t k = 0) const { return by_key.at(key).at(k); }
    bool has(const std::string& key) const { return by_key.count(key) != 0; }
};

// The error bound of every quantity the program computes at one pixel, in the
// program's order. Each follows from the rules at the top of this file, for
// any scene (Bounded walks the operations with the scene's numbers); the
// comments give the closed forms for the article's scene (z_E = 2,
// S = (0, 0, 3.2), r = 1.1, L = (1.5, 1, 1), I = 1; |x_E|, |y_E| < 1).
std::map<std::string, std::vector<long double>> pixel_error_bounds(const Vec3d& E_in, const promyk::Scene& scene,
                                                                   const ExactValues& exact) {
    std::map<std::string, std::vector<long double>> bound;
    const auto put = [&](const std::string& key, const Bounded& b) { bound[key] = {b.e}; };
    const auto put3 = [&](const std::string& key, const Vec3b& b) { bound[key] = {b.x.e, b.y.e, b.z.e}; };

    const Vec3b E{exact_input(E_in.x), exact_input(E_in.y), exact_input(E_in.z)};
    const Vec3d& S_in = scene.spheres[0].S;
    const Vec3b S{exact_input(S_in.x), exact_input(S_in.y), exact_input(S_in.z)};
    const Bounded r = exact_input(scene.spheres[0].r);
    const Vec3d& L_in = scene.lights[0].L;
    const Vec3b L{exact_input(L_in.x), exact_input(L_in.y), exact_input(L_in.z)};
    const Bounded I = exact_input(scene.lights[0].I);

    // E: the tracer's input, exactly the reference's doubles: bound 0.
    put3("E", {E.x, E.y, E.z});

    // EE = x_E^2 + y_E^2 + z_E^2: products and sums of non-negative terms, so
    // no cancellation. z_E^2 = 4 is exact; x_E^2, y_E^2 and the two sums are
    // rounded, and x_E^2 + y_E^2 <= EE/3, so the relative error is at most
    // u (last sum) + 2u/3 (the others, weighted by their share): < 2 ulp.
    const Bounded EE = with_exact(E.x * E.x + E.y * E.y + E.z * E.z, exact.at("EE"));
    put("EE", EE);

    // SS = x_S^2 + y_S^2 + z_S^2 = 0 + 0 + 3.2^2: one rounding, <= 0.5 ulp.
    const Bounded SS = with_exact(S.x * S.x + S.y * S.y + S.z * S.z, exact.at("SS"));
    put("SS", SS);

    // C = x_E x_S + y_E y_S + z_E z_S = 0 + 0 + 2 * 3.2: exact (a product by 2),
    // 0 ulp. (In general a dot product of mixed signs: error relative to the
    // sum of |terms|, not to C.)
    const Bounded C = with_exact(E.x * S.x + E.y * S.y + E.z * S.z, exact.at("C"));
    put("C", C);

    // delta = C^2 - EE (SS - r^2): the difference of two terms of about 41
    // and 36..54 that cancel at the silhouette, so its error is bounded
    // relative to the size of its terms, not to delta: C^2 (C exact) <= 0.5
    // ulp of 40.96; SS - r^2 carries 0.5 ulp from SS and r^2 and its own
    // rounding; EE (SS - r^2) carries EE's 5/3 u, that and its own 0.5 ulp:
    // together about 4.1 ulp of the larger term (2^-47 at 32..64), < 5 ulp.
    const Bounded delta = with_exact(C * C - EE * (SS - r * r), exact.at("delta"));
    put("delta", delta);
    // A miss returns the background, a constant: its result has no error.
    if (!exact.has("t")) {
        if (exact.has("I_P")) bound["I_P"] = {0};
        return bound;
    }

    // t = (C - sqrt(delta)) / EE: sqrt turns delta's absolute error e into
    // e / (2 sqrt(delta)), which grows without bound at the silhouette; C -
    // sqrt(delta) does not cancel (C = 6.4 > sqrt(delta) <= 2.2). Leading
    // terms: about (3 + 16 / sqrt(delta)) ulp of t.
    const Bounded t = with_exact((C - sqrt(delta)) / EE, exact.at("t"));
    put("t", t);

    // P = t E: t's relative error plus one rounding per component (x_E, y_E
    // exact inputs; a zero component stays exactly zero).
    Vec3b P{t * E.x, t * E.y, t * E.z};
    P = {with_exact(P.x, exact.at("P", 0)), with_exact(P.y, exact.at("P", 1)), with_exact(P.z, exact.at("P", 2))};
    put3("P", P);

    // N = P - S: P's absolute error plus one rounding; z_N = z_P - 3.2 loses
    // relative accuracy where z_P is close to 3.2, so the bound is absolute.
    Vec3b N{P.x - S.x, P.y - S.y, P.z - S.z};
    N = {with_exact(N.x, exact.at("N", 0)), with_exact(N.y, exact.at("N", 1)), with_exact(N.z, exact.at("N", 2))};
    put3("N", N);

    // K = L - P: likewise (y_K = 1 - y_P cancels where y_P is near 1).
    Vec3b K{L.x - P.x, L.y - P.y, L.z - P.z};
    K = {with_exact(K.x, exact.at("K", 0)), with_exact(K.y, exact.at("K", 1)), with_exact(K.z, exact.at("K", 2))};
    put3("K", K);

    // KK = |K|^2: non-negative terms, K's errors doubled by the squares, plus
    // five roundings (< 3 ulp of KK) on top.
    const Bounded KK = with_exact(K.x * K.x + K.y * K.y + K.z * K.z, exact.at("KK"));
    put("KK", KK);

    // D = N.K: mixed signs that cancel at the terminator: bounded by the
    // errors of N and K times |K| and |N| plus about 3 u of sum |N_i K_i|,
    // i.e. relative to the size of its terms, not to D.
    const Bounded D = with_exact(N.x * K.x + N.y * K.y + N.z * K.z, exact.at("D"));
    put("D", D);
    if (!exact.has("I_P")) return bound;  // uncertain at D
    // A dark pixel returns 0, a constant: no error.
    if (exact.at("I_P") == 0) {
        bound["I_P"] = {0};
        return bound;
    }

    // I_P = I D / (r sqrt(KK)): D's error relative to D (large at the
    // terminator) plus KK's halved by sqrt, plus four roundings (I D is exact
    // for I = 1, yet counted).
    const Bounded I_P = with_exact(I * D / (r * sqrt(KK)), exact.at("I_P"));
    put("I_P", I_P);
    return bound;
}

// --------------------------------------------------------------------------
// Loading the reference

struct RefValue {
    std::string key;
    std::vector<long double> exact;
    std::vector<double> lo, hi;
    std::vector<double> ieee;  // the reference's `double`
};

struct RefPixel {
    std::string scene;  // the scenes reference names each pixel's scene; empty: the article's
    int w = 0, i = 0, j = 0;
    std::string branch;        // miss, dark, lit or uncertain
    std::string uncertain_at;  // delta or D when uncertain
    std::vector<long double> pane_rational;
    std::vector<RefValue> steps;
    bool has_result = false;
    RefValue result;
};

RefValue parse_value(const json& j, const std::string& key) {
    RefValue v;
    v.key = key;
    if (j.at("exact").is_array()) {
        for (std::size_t k = 0; k < 3; ++k) {
            v.exact.push_back(parse_long_double(j.at("exact").at(k)));
            v.lo.push_back(parse_double(j.at("lo").at(k)));
            v.hi.push_back(parse_double(j.at("hi").at(k)));
            v.ieee.push_back(parse_double(j.at("double").at(k)));
        }
    } else {
        v.exact.push_back(parse_long_double(j.at("exact")));
        v.lo.push_back(parse_double(j.at("lo")));
        v.hi.push_back(parse_double(j.at("hi")));
        v.ieee.push_back(parse_double(j.at("double")));
    }
    return v;
}

struct Reference {
    json header;
    std::vector<RefPixel> pixels;
};

Reference load_reference(const char* path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(std::string("cannot open ") + path);
    const json doc = json::parse(in);
    Reference ref;
    ref.header = doc;
    ref.header.erase("pixels");
    for (const json& p : doc.at("pixels")) {
        RefPixel pixel;
        if (p.contains("scene")) pixel.scene = p.at("scene").get<std::string>();
        pixel.w = p.at("w").get<int>();
        pixel.i = p.at("i").get<int>();
        pixel.j = p.at("j").get<int>();
        pixel.branch = p.at("branch").get<std::string>();
        if (p.contains("uncertain_at")) pixel.uncertain_at = p.at("uncertain_at").get<std::string>();
        for (const json& q : p.at("pane_rational")) pixel.pane_rational.push_back(parse_rational(q));
        for (const json& s : p.at("steps")) pixel.steps.push_back(parse_value(s, s.at("key").get<std::string>()));
        if (p.contains("result")) {
            pixel.has_result = true;
            pixel.result = parse_value(p.at("result"), "I_P");
        }
        ref.pixels.push_back(std::move(pixel));
    }
    return ref;
}

const Reference& reference() {
    static const Reference loaded = load_reference(reference_path);
    return loaded;
}

const Reference& scenes_reference() {
    static const Reference loaded = load_reference(scenes_reference_path);
    return loaded;
}

// The scenes of the scenes reference, read from their files by promyk's own
// parser (the reference read the same files with Python's json), by name.
std::map<std::string, promyk::Scene> reference_scenes() {
    std::map<std::string, promyk::Scene> scenes;
    for (const json& s : scenes_reference().header.at("scenes"))
        scenes[s.at("name").get<std::string>()] =
            promyk::load_scene_file(scene_dir + s.at("file").get<std::string>());
    return scenes;
}

std::vector<double> components(const promyk::StepValue& value) {
    if (std::holds_alternative<double>(value)) return {std::get<double>(value)};
    const Vec3d& v = std::get<Vec3d>(value);
    return {v.x, v.y, v.z};
}

// The trace's steps that are the program's variables (the reference's keys),
// in the trace's order: steps the tracer may add for lessons are skipped, so
// values are compared by key, not by position.
std::vector<const promyk::Step*> program_steps(const promyk::PixelTrace& trace, const json& keys) {
    std::vector<const promyk::Step*> steps;
    for (const promyk::Step& step : trace.steps)
        for (const json& key : keys)
            if (promyk::key_name(step.key) == key.get<std::string>()) steps.push_back(&step);
    return steps;
}

// Largest errors seen, per quantity, for the optional report.
struct Worst {
    long double ulps = 0;        // |computed - exact| / ulp(exact)
    long double bound_ulps = 0;  // the derived bound at that pixel, in ulp(exact)
    long double max_bound_ulps = 0;
    long double ratio = 0;        // largest error / bound
    long double scaled_ulps = 0;  // |computed - exact| / ulp(size of its terms), for delta and D
    std::string where;
    int count = 0;
};

void check_scene_header(const json& s, const promyk::Scene& scene) {
    INFO("scene " << s.at("name").get<std::string>());
    CHECK(s.at("name").get<std::string>() == scene.name);
    CHECK(same_bits(parse_double(s.at("z_E")), scene.z_E));
    for (std::size_t k = 0; k < 3; ++k) {
        CHECK(same_bits(parse_double(s.at("S").at(k)), components(scene.spheres.at(0).S)[k]));
        CHECK(same_bits(parse_double(s.at("L").at(k)), components(scene.lights.at(0).L)[k]));
    }
    CHECK(same_bits(parse_double(s.at("r")), scene.spheres.at(0).r));
    CHECK(same_bits(parse_double(s.at("I")), scene.lights.at(0).I));
    CHECK(same_bits(parse_double(s.at("background")), scene.background.x));
}

std::string where_text(const RefPixel& p) {
    return (p.scene.empty() ? std::string() : p.scene + " ") + "w=" + std::to_string(p.w) + " (" +
           std::to_string(p.i) + "," + std::to_string(p.j) + ")";
}

// Checks every pixel of a reference against the tracer; `scene_of` gives a
// pixel's scene. `article` turns on the bounds derived for the article's
// scene only (fixed ulp bounds of EE, SS, C and delta's 5 ulp of its terms).
void check_against_reference(const Reference& ref, const std::map<std::string, promyk::Scene>& scene_of,
                             bool article) {
    std::map<std::string, Worst> worst;
    int failures = 0;
    std::string first_failures;
    const auto fail = [&](const RefPixel& p, const std::string& what) {
        if (++failures <= 10) first_failures += where_text(p) + ": " + what + "\n";
    };
    const json& keys = ref.header.at("keys");

    // Per quantity, a fixed bound in ulp of the exact value where the
    // derivation above gives one independent of the pixel (for the article's scene).
    const std::map<std::string, long double> fixed_ulps =
        article ? std::map<std::string, long double>{{"EE", 2}, {"SS", 0.5L}, {"C", 0}}
                : std::map<std::string, long double>{};

    for (const RefPixel& p : ref.pixels) {
        const promyk::Scene& scene = scene_of.at(p.scene);
        const promyk::PixelTrace trace = promyk::trace_pixel(scene, p.w, p.i, p.j);

        // The branch.
        if (p.branch == "uncertain") {
            if (p.uncertain_at == "D" && trace.branch == Branch::miss) fail(p, "missed; the reference hits");
        } else if (promyk::branch_name(trace.branch) != p.branch) {
            fail(p, "branch " + std::string(promyk::branch_name(trace.branch)) + ", reference " + p.branch);
            continue;
        }

        // The program's keys, in order.
        const std::vector<const promyk::Step*> steps = program_steps(trace, keys);
        const bool certain = p.branch != "uncertain";
        if (certain ? steps.size() != p.steps.size() : steps.size() < p.steps.size()) {
            fail(p, std::to_string(steps.size()) + " steps, reference " + std::to_string(p.steps.size()));
            continue;
        }
        bool keys_match = true;
        for (std::size_t k = 0; k < p.steps.size(); ++k)
            if (promyk::key_name(steps[k]->key) != p.steps[k].key) keys_match = false;
        if (!keys_match) {
            fail(p, "keys differ from the reference's");
            continue;
        }

        // The pane point: exactly the reference's doubles, and within 1 ulp
        // of 1 (2^-52) of the exact rational (the quotient (2j+1)/w < 2 is
        // rounded by <= 2^-53, the sum with -1 or 1 (|result| <= 1) by <= 2^-53).
        const std::vector<double> E = components(steps.at(0)->value);
        for (std::size_t k = 0; k < 2; ++k) {
            if (!same_bits(E[k], p.steps[0].lo[k]) || !same_bits(E[k], p.steps[0].hi[k]))
                fail(p, "E differs from the reference's pane point");
            if (std::fabs(E[k] - p.pane_rational[k]) > 0x1p-52L * (1 + 0x1p-40L))
                fail(p, "E more than 2^-52 from the exact pane point");
        }

        // Enclosures and error bounds.
        ExactValues exact;
        for (const RefValue& v : p.steps) exact.by_key[v.key] = v.exact;
        if (p.has_result) exact.by_key["I_P"] = p.result.exact;
        const auto bounds = pixel_error_bounds(Vec3d{E[0], E[1], E[2]}, scene, exact);

        // The size of delta's and D's terms, against which their cancellation
        // is measured.
        const long double C = exact.at("C"), EE = exact.at("EE"), SS = exact.at("SS");
        const long double r = scene.spheres[0].r;
        const long double larger_term = std::max(C * C, std::fabs(EE * (SS - r * r)));
        long double D_terms = 0;
        if (exact.has("D"))
            for (std::size_t k = 0; k < 3; ++k) D_terms += std::fabs(exact.at("N", k) * exact.at("K", k));

        const auto check = [&](const RefValue& ref_value, const std::vector<double>& got) {
            for (std::size_t k = 0; k < got.size(); ++k) {
                const std::string name =
                    ref_value.key + (got.size() == 3 ? std::string(".") + "xyz"[k] : std::string());
                if (!(ref_value.lo[k] <= got[k] && got[k] <= ref_value.hi[k]))
                    fail(p, name + " = " + show_digits(got[k]) + " outside [" + show_digits(ref_value.lo[k]) + ", " +
                                show_digits(ref_value.hi[k]) + "]");
                if (!same_bits(got[k], ref_value.ieee[k]))
                    fail(p, name + " = " + show_digits(got[k]) + ", the IEEE program gives " +
                                show_digits(ref_value.ieee[k]));
                const long double x = ref_value.exact[k];
                const long double error = std::fabs(static_cast<long double>(got[k]) - x);
                const long double bound = bounds.at(ref_value.key).at(k);
                // Slack: the bound is evaluated in long double and the exact
                // value is read from 30 digits (far below 1/256 ulp).
                const long double tolerance = bound * (1 + 0x1p-20L) + 0x1p-60L * std::fabs(x);
                if (!(error <= tolerance))
                    fail(p, name + " = " + show_digits(got[k]) + ", exact " + show_digits(x) + ": error " +
                                show_digits(error / ulp(x)) + " ulp, bound " + show_digits(bound / ulp(x)) + " ulp");
                const auto fixed = fixed_ulps.find(ref_value.key);
                if (fixed != fixed_ulps.end() && !(error <= fixed->second * ulp(x) + 0x1p-60L * std::fabs(x)))
                    fail(p, name + ": error " + show_digits(error / ulp(x)) + " ulp, above its fixed bound");
                Worst& w = worst[ref_value.key];
                ++w.count;
                const long double ulps = error / ulp(x);
                const long double scale = ref_value.key == "delta" ? larger_term
                                          : ref_value.key == "D"   ? D_terms
                                                                   : std::fabs(x);
                w.scaled_ulps = std::max(w.scaled_ulps, error / ulp(scale));
                w.max_bound_ulps = std::max(w.max_bound_ulps, bound / ulp(x));
                if (bound > 0) w.ratio = std::max(w.ratio, error / bound);
                if (ulps > w.ulps || w.where.empty()) {
                    w.ulps = ulps;
                    w.bound_ulps = bound / ulp(x);
                    w.where = where_text(p) + " " + name;
                }
            }
        };
        for (std::size_t k = 0; k < p.steps.size(); ++k) check(p.steps[k], components(steps[k]->value));
        if (p.has_result) check(p.result, {trace.result});

        // For the article's scene, delta also within 5 ulp of its larger term
        // (C^2 or EE (SS - r^2)), as derived for its bound above.
        if (article) {
            const double delta = std::get<double>(steps.at(4)->value);
            if (!(std::fabs(delta - exact.at("delta")) <= 5 * ulp(larger_term)))
                fail(p, "delta more than 5 ulp of its larger term from exact");
        }
    }

    INFO(first_failures);
    CHECK(failures == 0);

    // A table of the largest errors, only when asked for (no noise in ctest).
    if (std::getenv("PROMYK_REFERENCE_REPORT")) {
        std::printf("%-6s %6s %12s %12s %14s %10s %12s  %s\n", "key", "values", "max ulp", "bound there",
                    "largest bound", "err/bound", "ulp of terms", "where (max ulp)");
        for (const char* key : {"E", "EE", "SS", "C", "delta", "t", "P", "N", "K", "KK", "D", "I_P"}) {
            const auto it = worst.find(key);
            if (it == worst.end()) continue;
            const Worst& w = it->second;
            std::printf("%-6s %6d %12.3Lg %12.3Lg %14.3Lg %10.3Lg %12.3Lg  %s\n", key, w.count, w.ulps, w.bound_ulps,
                        w.max_bound_ulps, w.ratio, w.scaled_ulps, w.where.c_str());
        }
    }
}

}  // namespace

TEST_CASE("the reference describes the article's scene", "[reference]") {
    const Reference& ref = reference();
    const promyk::Scene scene = promyk::article_scene();
    CHECK(ref.header.at("precision_bits").get<int>() >= 200);
    check_scene_header(ref.header.at("scene"), scene);
    CHECK(ref.header.at("pixel_count").get<std::size_t>() == ref.pixels.size());

    // The pixel set covers what the reference promises.
    std::map<int, int> per_size;
    std::map<std::string, int> per_branch;
    for (const RefPixel& p : ref.pixels) {
        ++per_size[p.w];
        ++per_branch[p.branch];
    }
    CHECK(per_size[1] == 1);
    CHECK(per_size[8] == 64);
    CHECK(per_size[7] == 49);
    CHECK(per_size[512] > 0);
    CHECK(per_size[2049] > 0);
    CHECK(per_branch["miss"] > 0);
    CHECK(per_branch["dark"] > 0);
    CHECK(per_branch["lit"] > 0);
}

TEST_CASE("the tracer agrees with the high-precision reference", "[reference]") {
    check_against_reference(reference(), {{"", promyk::article_scene()}}, true);
}

TEST_CASE("the scenes reference describes its scene files and covers what it must", "[reference]") {
    const Reference& ref = scenes_reference();
    const std::map<std::string, promyk::Scene> scenes = reference_scenes();
    CHECK(ref.header.at("precision_bits").get<int>() >= 200);
    CHECK(ref.header.at("pixel_count").get<std::size_t>() == ref.pixels.size());
    for (const json& s : ref.header.at("scenes")) check_scene_header(s, scenes.at(s.at("name").get<std::string>()));

    // Not the article's: off-axis centres with distinct non-zero coordinates,
    // I != 1, backgrounds != 1/2, z_E != 2.
    bool off_axis = false, I_not_1 = false, background_not_half = false, z_E_not_2 = false;
    for (const auto& [name, scene] : scenes) {
        const Vec3d& S = scene.spheres.at(0).S;
        if (S.x != 0 && S.y != 0 && S.z != 0 && S.x != S.y && S.y != S.z && S.x != S.z) off_axis = true;
        if (scene.lights.at(0).I != 1) I_not_1 = true;
        if (scene.background.x != 0.5) background_not_half = true;
        if (scene.z_E != 2) z_E_not_2 = true;
    }
    CHECK(off_axis);
    CHECK(I_not_1);
    CHECK(background_not_half);
    CHECK(z_E_not_2);

    // Every branch, and pixels where delta or D is exactly 0 (exact value,
    // enclosure and double all 0): a tangent ray that misses, a hit facing
    // the light edge-on that is dark.
    std::map<std::string, int> per_branch;
    int delta_zero_misses = 0, D_zero_darks = 0;
    for (const RefPixel& p : ref.pixels) {
        ++per_branch[p.branch];
        for (const RefValue& v : p.steps) {
            const bool zero = v.exact.at(0) == 0 && v.lo.at(0) == 0 && v.hi.at(0) == 0 && v.ieee.at(0) == 0;
            if (zero && v.key == "delta" && p.branch == "miss") ++delta_zero_misses;
            if (zero && v.key == "D" && p.branch == "dark") ++D_zero_darks;
        }
    }
    CHECK(per_branch["miss"] > 0);
    CHECK(per_branch["dark"] > 0);
    CHECK(per_branch["lit"] > 0);
    CHECK(per_branch["uncertain"] == 0);
    CHECK(delta_zero_misses >= 3);
    CHECK(D_zero_darks >= 2);
}

TEST_CASE("the tracer agrees with the high-precision reference on scenes that are not the article's", "[reference]") {
    check_against_reference(scenes_reference(), reference_scenes(), false);
}
