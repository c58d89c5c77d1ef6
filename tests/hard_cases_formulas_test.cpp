// The engine's other sphere formulas (stable, fma, geometric: --formula) on
// the hard cases, in every real type, against
// tests/reference/hard_cases_reference.json. hard_cases_test.cpp does the
// same for the default (article) formula; see its comment for the reading
// of values and the running error bound.
//
// make_hard_cases.py simulates each formula in the engine's own operation
// order (src/geometry/sphere_stable.hpp, sphere_fma.hpp, sphere_geometric.hpp;
// docs/conventions.md, "The engine's conventions"), with the engine's root choice
// (nearest_root_ahead: the near root if > 0, else the far one, in either
// kernel, render/tracer.hpp) and logs the values the engine records under the
// engine's keys. For every case, type and formula the test checks:
//
// 1. Bit for bit: branch, hit object, every recorded scalar of the formula
//    (stable: delta, q, t_q, t_c; fma: w_fma, e_fma, delta_fma, t, t_far;
//    geometric: t_mid, ll, delta_g, q, t_q, t_c), the planes' NE and t_plane,
//    t_hit, each light's D, and the result equal the simulation's.
//
// 2. The branch is the exact one (the engine's computation carried out
//    exactly: the article's, whose branch every formula would give with exact
//    arithmetic) wherever the reference says the formula gets it right;
//    elsewhere the case is in the documented list below, with the digits
//    the article's delta C^2 - |E|^2 c_0 loses (exact values) asserted
//    exactly. Two kinds of failure:
//    - the cancellation reaches the type's digits (loss >= p log10 2, or
//      "all": the exact delta is 0, a tangent, where any residue of either
//      sign decides); stable and fma share the article's delta (fma computes
//      it exactly from rounded coefficients, which does not help: see
//      sphere_fma.hpp), so they fail where the article does and more
//      (a tangent residue); geometric computes delta_g = r^2 - |l|^2 and
//      fails only in float, where even its inputs are rounded off the tangent
//      or the sphere is 1e8 away;
//    - the near root rounds to t <= 0 for an eye outside the sphere (exact
//      branch: miss, no cancellation in delta, loss < the type's digits) and
//      the engine's root choice takes the far root: a "dark" pixel.
//
// 3. Error bounds for stable and geometric (and fma), where the branch is
//    right and there is a hit: |t - t_exact| and |result - result_exact| are
//    at most the running error bound of the script, which follows the
//    formula's operations one by one (+-*/ sqrt fma: e_a + e_b + u|v| and the
//    product/quotient/sqrt rules of hard_cases_test.cpp, u = 2^-p), so its
//    size is operation count x u in the cancellation-free parts and grows
//    only through the operations that cancel (delta for stable, r^2 - |l|^2
//    and the l components for geometric). In the cancellation-free
//    structure q = C + sign(C) sqrt(delta) adds two numbers of one sign, so
//    |q^ - q| <= e_C + e_sqrt + u|q| with no division by a small difference;
//    t_q = q/EE and t_c = c_0/q then add (e_q/|q| + e_EE/EE + u) |t|, resp.
//    (e_q/|q| + e_c0/|c_0| + u) |t|: the bound is not fitted, it is this
//    sum evaluated on the case's values.
//
//    For stable the test also asserts a closed-form bound from operation
//    counts. With exact inputs, u = 2^-p, M = |E|^2 (|S|^2 + r^2) (>= C^2 by
//    Cauchy-Schwarz and >= |E|^2 |c_0|, so M >= |delta|), the condition
//    numbers k_d = M / |delta| of delta and k_c = (|S|^2 + r^2) / |c_0| of
//    c_0, first order:
//      EE, SS: 3 roundings each, |EE^ - EE| <= 3u EE;
//      C: |C^ - C| <= 3u |E||S| <= 3u sqrt(M);
//      c_0 = SS - r*r: |c_0^ - c_0| <= 3u SS + u r^2 + u|c_0| <= 4u (SS + r^2);
//      delta = C*C - EE*c_0: 2|C| 3u|E||S| + u C^2 (C^2) + (3u + 4u k..)
//        gathered: |delta^ - delta| <= 6uM + uM + 3uM + 4uM + uM = 15uM, + u|delta|;
//      sqrt: relative error <= half of delta's + u <= 8u k_d + u;
//      q = C + sign(C) sqrt(delta), two terms of one sign (the
//        cancellation-free structure): |q| >= sqrt(delta) and >= |C|, so the
//        error of C over |q| is <= 3u sqrt(M / delta) <= 3u k_d, and
//        rel(q) <= 3u k_d + 8u k_d + u + u = 11u k_d + 2u;
//      t_q = q / EE: rel <= 11u k_d + 2u + 3u + u = (11 k_d + 6) u;
//      t_c = c_0 / q: rel <= 4u k_c + 11u k_d + 2u + u = (11 k_d + 4 k_c + 3) u.
//    So |t - t_exact| <= (11 k_d + 4 k_c + 6) u |t_exact| to first order; the
//    test asserts (16 k_d + 8 k_c + 16) u |t_exact|, the margin covering the
//    second-order terms (all below p^2 u^2 k). No cancellation (k_d, k_c small)
//    gives a few dozen u; the eye near a huge sphere's surface (k_c large)
//    or a grazing ray (k_d large) lose what k says, and no more. k_d comes
//    from the exact delta in the reference, k_c from the type's inputs in
//    quad (their squares' rounding, 2^-112 relative, is allowed for).
//
//    For geometric the closed form needs the condition of delta_g, which
//    comes from l = t_mid E - S, the vector from the centre to the ray's
//    point nearest it. Exactly, l is perpendicular to E, so |S|^2 =
//    |t_mid E|^2 + |l|^2 (|t_mid E| <= |S|, |l| <= |S|), delta_g = r^2 -
//    |l|^2 = delta / |E|^2 (Lagrange's identity) and a = |t_mid E|^2 =
//    c_0 + delta_g >= 0. With a hit (delta_g > 0, so |l| < r) let
//    D = sqrt(delta_g (a + delta_g)) and
//      k_g = (r^2 + r|S| + 6u|S|^2) / D   (>= 1: D <= r sqrt(|S|^2 + r^2)),
//    k_c as above. First order, exact inputs (the type's: the reference's
//    exact values are computed from them, so their rounding is not an error):
//      t_mid = C / EE: |t_mid^ - t_mid| <= 3u|S|/|E| + 3u|t_mid| (C's and
//        EE's errors) + u|t_mid| <= 7u|S|/|E| (|t_mid E| <= |S|; C may
//        cancel, so this is an absolute bound, not a relative one);
//      l = t_mid E - S: the error vector has norm
//        eta <= 7u|S| + u|t_mid E| + u|l| <= 8u|S| + u|l| <= 9u|S|;
//      ll = |l|^2: |ll^ - |l|^2| <= 2|l| eta + eta^2 + 3u|l|^2
//        <= 16u r|S| + 5u r^2 + 81u^2|S|^2 (|l| < r); eta^2 is kept: u^2|S|^2
//        is as large as u r|S| when the sphere is |S|/r ~ 1/u away;
//      delta_g = r*r - ll: + u r^2 + u delta_g, so
//        |delta_g^ - delta_g| <= 16u (r^2 + r|S| + 6u|S|^2) + u delta_g
//        = 16u k_g D + u delta_g;
//      A = EE*delta_g: |A^ - A| <= EE |delta_g^ - delta_g| + 4u A;
//      root = sqrt(A) = |E| sqrt(delta_g): |sqrt(A^) - root| =
//        |A^ - A| / (sqrt(A^) + root) <= |A^ - A| / root, + u root (no
//        linearisation: on a grazing ray delta_g^ may be off by more than
//        delta_g itself while t stays good, root being small against |q|);
//      q = C + sign(C) root: |q| = |C| + root >= sqrt(C^2 + A) =
//        |E| sqrt(a + delta_g), so C's error 3u|E||S| over |q| is
//        <= 3u|S| sqrt(delta_g) / D <= 3u r|S| / D <= 3u k_g, and root's is
//        <= (EE (16u k_g D + u delta_g) + 4u A) / (root |q|) + u
//        <= 16u k_g + u + 4u + u (delta_g <= D, root <= |q|):
//        rel(q) <= 3u k_g + 16u k_g + 6u + u = (19 k_g + 7) u. (Should C^
//        round to the sign opposite to C's, |C| <= 3u|E||S| and the same two
//        roots come in the other order, |q| smaller by a relative 3u k_g at
//        most: the same bound to first order);
//      t_q = q / EE: (19 k_g + 7) u + 3u + u = (19 k_g + 11) u;
//      t_c = c_0 / q: (3 k_c + 1) u + (19 k_g + 7) u + u = (19 k_g + 3 k_c + 9) u.
//    So each root is within R_1 = (19 k_g + 3 k_c + 11) u of its exact value,
//    relatively, to first order. The engine's choice is the smaller positive
//    root: min is monotone, so min(t_a^, t_b^) lies within R_1 min(t_a, t_b)
//    of the exact choice even when the two roots swap, and with R_1 < 1 no
//    root changes sign (the eye inside: the far root on both sides). The
//    test asserts (24 k_g + 8 k_c + 16) u |t_exact|, the constants rounded
//    up to the next multiple of 8 (at least 24/19 = 1.26 times R_1), where
//    R_1 <= 1/16: the terms left out are the products of the relative errors
//    above, which compose as factors (1 + e_i)^(+-1) with sum |e_i| = s <=
//    R_1, whose product is within e^(s/(1 - s)) - 1 <= 1.11 s of 1 for
//    s <= 1/16 (the second-order terms inside the sums, u times an error,
//    are smaller still). Where R_1 > 1/16 the first order is not a bound and
//    the case is skipped, listed below (geometric_closed_form_skipped) and
//    checked to be exactly those; the running bound above still holds it. The
//    eye on the surface (c_0 = 0: t_c = 0, k_c infinite) is left out as for
//    stable. No cancellation (k_g, k_c about 1) gives a few dozen u; a far
//    sphere on the ray's line has k_g about 1 + 6u|S|/r, so it loses digits
//    only as |S|/r nears 1/u (the article's delta, as it nears 1/sqrt(u));
//    a grazing ray loses what k_g says (about r / sqrt(delta_g), the centre
//    ahead), the eye near a huge sphere's surface what k_c says. The test
//    reports (INFO) the fraction of the bound used.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "hard_cases_support.hpp"
#include <quadmath.h>

#include "math/real.hpp"
#include "render/trace_pixel.hpp"
#include "scene/scene.hpp"
#include "scene/scene_json.hpp"
#include "trace/keys.hpp"
#include "trace/trace.hpp"

namespace {

using namespace hard_cases_support;

struct FormulaFailure {
    const char* formula;
    const char* id;
    const char* type;
    const char* lost;
    const char* what;
};

// Generated from the reference and checked here: every entry must fail and
// every failure must be listed.
const FormulaFailure documented_formula_failures[] = {
    // stable
    {"stable", "far_1e4", "float", "8.0", "miss (exact lit): the cancellation reaches the type's digits"},
    {"stable", "far_1e5", "float", "10.0", "miss (exact lit): the cancellation reaches the type's digits"},
    {"stable", "far_1e6", "float", "12.0", "miss (exact lit): the cancellation reaches the type's digits"},
    {"stable", "far_1e7", "float", "14.0", "miss (exact lit): the cancellation reaches the type's digits"},
    {"stable", "far_1e8", "float", "16.0", "miss (exact lit): the cancellation reaches the type's digits"},
    {"stable", "far_1e8", "double", "16.0", "miss (exact lit): the cancellation reaches the type's digits"},
    {"stable", "huge_near_1e9", "float", "0.0",
     "dark (exact miss): the near root rounds to t <= 0 and the far root is taken"},
    {"stable", "tangent_axis_z07", "float", "all", "false dark: the exact delta is 0"},
    {"stable", "tangent_axis_z07", "long-double", "all", "false dark: the exact delta is 0"},
    {"stable", "tangent_off_axis_1", "float", "9.6", "lit (exact miss): the cancellation reaches the type's digits"},
    {"stable", "tangent_off_axis_1", "double", "all", "false lit: the exact delta is 0"},
    {"stable", "tangent_off_axis_2", "double", "all", "false dark: the exact delta is 0"},
    {"stable", "tangent_off_axis_3", "double", "all", "false lit: the exact delta is 0"},
    {"stable", "tangent_off_axis_4", "float", "8.0", "miss (exact dark): the cancellation reaches the type's digits"},
    {"stable", "tangent_off_axis_5", "float", "all", "false lit: the exact delta is 0"},
    {"stable", "grazing_float", "float", "8.3", "miss (exact lit): the cancellation reaches the type's digits"},
    {"stable", "grazing_double", "double", "17.1", "miss (exact lit): the cancellation reaches the type's digits"},
    {"stable", "eye_just_outside", "float", "0.0",
     "dark (exact miss): the near root rounds to t <= 0 and the far root is taken"},
    // fma
    {"fma", "far_1e4", "float", "8.0", "miss (exact lit): the cancellation reaches the type's digits"},
    {"fma", "far_1e5", "float", "10.0", "miss (exact lit): the cancellation reaches the type's digits"},
    {"fma", "far_1e7", "float", "14.0", "miss (exact lit): the cancellation reaches the type's digits"},
    {"fma", "far_1e8", "float", "16.0", "miss (exact lit): the cancellation reaches the type's digits"},
    {"fma", "far_1e8", "double", "16.0", "miss (exact lit): the cancellation reaches the type's digits"},
    {"fma", "huge_near_1e9", "float", "0.0",
     "dark (exact miss): the near root rounds to t <= 0 and the far root is taken"},
    {"fma", "tangent_axis_tenth", "float", "all", "false dark: the exact delta is 0"},
    {"fma", "tangent_axis_tenth", "double", "all", "false dark: the exact delta is 0"},
    {"fma", "tangent_axis_z07", "float", "all", "false dark: the exact delta is 0"},
    {"fma", "tangent_axis_z07", "long-double", "all", "false dark: the exact delta is 0"},
    {"fma", "tangent_off_axis_1", "float", "9.6", "lit (exact miss): the cancellation reaches the type's digits"},
    {"fma", "tangent_off_axis_1", "double", "all", "false lit: the exact delta is 0"},
    {"fma", "tangent_off_axis_2", "double", "all", "false dark: the exact delta is 0"},
    {"fma", "tangent_off_axis_2", "long-double", "all", "false dark: the exact delta is 0"},
    {"fma", "tangent_off_axis_3", "float", "8.5", "lit (exact miss): the cancellation reaches the type's digits"},
    {"fma", "tangent_off_axis_3", "double", "all", "false lit: the exact delta is 0"},
    {"fma", "tangent_off_axis_4", "float", "8.0", "miss (exact dark): the cancellation reaches the type's digits"},
    {"fma", "tangent_off_axis_4", "double", "all", "false dark: the exact delta is 0"},
    {"fma", "tangent_off_axis_5", "float", "all", "false lit: the exact delta is 0"},
    {"fma", "grazing_float", "float", "8.3", "miss (exact lit): the cancellation reaches the type's digits"},
    {"fma", "grazing_double", "double", "17.1", "miss (exact lit): the cancellation reaches the type's digits"},
    {"fma", "eye_just_outside", "float", "0.0",
     "dark (exact miss): the near root rounds to t <= 0 and the far root is taken"},
    // geometric
    {"geometric", "far_1e8", "float", "16.0",
     "dark (exact lit): t E rounds to the centre's depth 1e8, N = P - S = 0, D = 0"},
    {"geometric", "huge_near_1e9", "float", "0.0",
     "dark (exact miss): the near root rounds to t <= 0 and the far root is taken"},
    {"geometric", "tangent_off_axis_1", "float", "9.6", "lit (exact miss): the cancellation reaches the type's digits"},
    {"geometric", "tangent_off_axis_4", "float", "8.0",
     "miss (exact dark): the cancellation reaches the type's digits"},
    {"geometric", "eye_just_outside", "float", "0.0",
     "dark (exact miss): the near root rounds to t <= 0 and the far root is taken"},
};

// Where the geometric formula's closed-form bound is not asserted: its
// first-order error R_1 = (19 k_g + 3 k_c + 11) u exceeds 1/16 (the comment at
// the top). Checked to be exactly these.
struct ClosedFormSkip {
    const char* id;
    const char* type;
    const char* why;
};
const ClosedFormSkip geometric_closed_form_skipped[] = {
    {"eye_just_outside", "double",
     "k_c ~ 5.7e15, R_1 ~ 1.9: c_0 = SS - r*r keeps no sure digit, nor does the near root c_0/q"},
};



}  // namespace

TEST_CASE("Hard cases: stable, fma and geometric formulas as simulated, exact branch or documented failure, bounded",
          "[reference][hard][hard-cases]") {
    const std::pair<promyk::Formula, std::set<std::string>> formulas[] = {
        {promyk::Formula::stable, {"delta", "q", "t_q", "t_c", "NE", "t_plane", "t_hit", "D"}},
        {promyk::Formula::fma, {"w_fma", "e_fma", "delta_fma", "t", "t_far", "NE", "t_plane", "t_hit", "D"}},
        {promyk::Formula::geometric, {"t_mid", "ll", "delta_g", "q", "t_q", "t_c", "NE", "t_plane", "t_hit", "D"}},
    };
    const json& cases = hard_cases_reference().at("cases");
    int failures_seen = 0;
    int geometric_skips_seen = 0;
    for (const json& c : cases) {
        const std::string id = c.at("id").get<std::string>();
        const promyk::Scene scene = promyk::parse_scene(c.at("scene").dump(), "hard case " + id);
        const int w = c.at("pixel").at("w").get<int>();
        const int i = c.at("pixel").at("i").get<int>();
        const int j = c.at("pixel").at("j").get<int>();
        for (const auto& [formula, keys] : formulas) {
            const std::string fname(promyk::formula_name(formula));
            for (const TypeInfo& type : real_types) {
                INFO("case " << id << ", formula " << fname << ", " << type.name << ", pixel (" << i << ", " << j
                             << ") of w = " << w);
                const json& record = c.at("types").at(type.name);
                const json& exact = record.at("exact");
                const json& sim = record.at("formulas").at(fname);
                const promyk::PixelTrace trace = promyk::trace_pixel(scene, w, i, j, type.real, formula);

                // 1. Bit for bit.
                const std::string branch(promyk::branch_name(trace.branch));
                CHECK(branch == sim.at("branch").get<std::string>());
                if (!trace.hit_object.empty()) CHECK(trace.hit_object == sim.at("hit").get<std::string>());
                std::vector<std::pair<std::string, quad>> expected;
                for (const json& step : sim.at("steps")) {
                    const std::string label = step.at(0).get<std::string>();
                    if (label.size() > 3 &&
                        (label.substr(label.size() - 3) == " 2D" || label.substr(label.size() - 3) == " KK"))
                        continue;
                    expected.emplace_back(label, read_in(step.at(1).get<std::string>(), type.name));
                }
                const auto got = engine_steps(trace, type.name, keys);
                REQUIRE(got.size() == expected.size());
                for (std::size_t k = 0; k < got.size(); ++k) {
                    INFO("step " << got[k].first << ": engine " << show(got[k].second) << ", simulated "
                                 << show(expected[k].second));
                    CHECK(got[k].first == expected[k].first);
                    CHECK(got[k].second == expected[k].second);
                }
                const quad result = type.real == promyk::RealType::double_
                                        ? quad(trace.result)
                                        : read_in(trace.result_real_text.at(0), type.name);
                if (sim.contains("result")) CHECK(result == read_in(sim.at("result").get<std::string>(), type.name));

                // 2. The exact branch, or a documented failure.
                const bool correct = sim.at("branch_correct").get<bool>();
                const FormulaFailure* failure = nullptr;
                for (const FormulaFailure& f : documented_formula_failures)
                    if (fname == f.formula && id == f.id && std::string(type.name) == f.type) failure = &f;
                const json& spheres = exact.at("spheres");
                if (correct) {
                    CHECK(failure == nullptr);
                    CHECK(branch == exact.at("branch").get<std::string>());
                } else {
                    INFO(fname << ": " << branch << ", exact: " << exact.at("branch").get<std::string>());
                    REQUIRE(failure != nullptr);
                    ++failures_seen;
                    REQUIRE(spheres.size() == 1);
                    const std::string lost = digits_lost_text(spheres.at(0).at("delta_digits_lost"));
                    INFO("documented: " << failure->what << ", " << failure->lost << " digits of delta lost");
                    CHECK(lost == failure->lost);
                    const std::string what = failure->what;
                    if (lost == "all") {
                        CHECK(spheres.at(0).at("delta").get<std::string>() == "0");
                    } else if (what.find("far root") != std::string::npos) {
                        CHECK(std::stod(lost) < type.bits * std::log10(2.0));
                        CHECK(exact.at("branch").get<std::string>() == "miss");
                        CHECK(branch != "miss");
                    } else {
                        CHECK(std::stod(lost) + 0.05 >= type.bits * std::log10(2.0));
                    }
                }

                // 3. Within the running error bound; no cancellation: 64 u relative.
                if (correct && sim.contains("t_error")) {
                    const quad t = read_in(sim.at("t").get<std::string>(), type.name);
                    const quad t_exact = text_q(exact.at("t"));
                    const quad t_bound = text_q(sim.at("t_error").at("bound"));
                    INFO("t: engine " << show(t) << ", exact " << show(t_exact) << ", bound " << show(t_bound));
                    CHECK(absq(t - t_exact) <= t_bound + absq(t_exact) * quad(0x1p-110));
                    const quad r_exact = text_q(exact.at("result"));
                    const quad r_bound = text_q(sim.at("result_error").at("bound"));
                    INFO("result: engine " << show(result) << ", exact " << show(r_exact) << ", bound "
                                           << show(r_bound));
                    CHECK(absq(result - r_exact) <= r_bound + absq(r_exact) * quad(0x1p-110));
                    // (The eye on the surface, c_0 = 0 in the type, is left out: k_c is infinite.)
                    if ((formula == promyk::Formula::stable || formula == promyk::Formula::geometric) &&
                        spheres.size() == 1 && exact.at("hit") == "sphere 0" &&
                        !spheres.at(0).at("eye_on_surface").get<bool>()) {
                        const json& in = record.at("inputs");
                        quad EE = 0, SS = 0;
                        for (int k = 0; k < 3; ++k) {
                            const quad e = read_in(in.at("E").at(k).get<std::string>(), type.name);
                            const quad sk =
                                read_in(in.at("spheres").at(0).at("S").at(k).get<std::string>(), type.name);
                            EE += e * e;
                            SS += sk * sk;
                        }
                        const quad r = read_in(in.at("spheres").at(0).at("r").get<std::string>(), type.name);
                        const quad big = SS + r * r;
                        // A lower bound of |c_0| (> 0: no case has the eye off the surface by less
                        // than 2^-110 (SS + r^2)).
                        const quad c0 = absq(SS - r * r) - big * quad(0x1p-110);
                        REQUIRE(c0 > 0);
                        const quad delta = absq(text_q(spheres.at(0).at("delta"))) * (1 - quad(0x1p-100));
                        REQUIRE(delta > 0);
                        const quad k_c = big / c0;
                        const quad u = quad(std::ldexp(1.0, -type.bits));
                        const quad error = absq(t - t_exact);
                        const quad slack = absq(t_exact) * quad(0x1p-110);
                        if (formula == promyk::Formula::stable) {
                            const quad k_d = EE * big / delta;
                            const quad closed = (16 * k_d + 8 * k_c + 16) * u * absq(t_exact);
                            INFO("closed-form bound: k_d " << show(k_d) << ", k_c " << show(k_c) << ", bound "
                                                           << show(closed));
                            CHECK(error <= closed + slack);
                        } else {
                            // Lower bounds of delta_g = delta / EE and of a + delta_g = c_0 + 2 delta_g
                            // (and >= delta_g, a >= 0), an upper bound of k_g's numerator.
                            const quad delta_g = delta / EE * (1 - quad(0x1p-100));
                            const quad c0_low = (SS - r * r) - big * quad(0x1p-110);
                            const quad a_plus = c0_low + 2 * delta_g > delta_g ? c0_low + 2 * delta_g : delta_g;
                            const quad D = sqrtq(delta_g * a_plus) * (1 - quad(0x1p-100));
                            const quad k_g = (r * r + r * sqrtq(SS) + 6 * u * SS) * (1 + quad(0x1p-100)) / D;
                            const quad first_order = (19 * k_g + 3 * k_c + 11) * u;
                            const quad closed = (24 * k_g + 8 * k_c + 16) * u * absq(t_exact);
                            const ClosedFormSkip* skip = nullptr;
                            for (const ClosedFormSkip& s : geometric_closed_form_skipped)
                                if (id == s.id && std::string(type.name) == s.type) skip = &s;
                            INFO("geometric closed-form bound: k_g " << show(k_g) << ", k_c " << show(k_c)
                                                                     << ", R_1 " << show(first_order) << ", bound "
                                                                     << show(closed) << ", fraction used "
                                                                     << show(error / closed));
                            CHECK((first_order > quad(0.0625)) == (skip != nullptr));
                            if (skip == nullptr) {
                                CHECK(error <= closed + slack);
                            } else {
                                ++geometric_skips_seen;
                            }
                        }
                    }
                }
            }
        }
    }
    CHECK(failures_seen ==
          static_cast<int>(sizeof documented_formula_failures / sizeof documented_formula_failures[0]));
    CHECK(geometric_skips_seen ==
          static_cast<int>(sizeof geometric_closed_form_skipped / sizeof geometric_closed_form_skipped[0]));
    for (const FormulaFailure& f : documented_formula_failures) {
        INFO("documented failure " << f.formula << " " << f.id << " in " << f.type);
        CHECK_FALSE(
            case_by_id(f.id).at("types").at(f.type).at("formulas").at(f.formula).at("branch_correct").get<bool>());
    }
}
