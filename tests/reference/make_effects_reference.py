#!/usr/bin/env python3
"""Independent high-precision reference for the extended engine.

Usage: python3 make_effects_reference.py OUTPUT.json

Follows docs/conventions.md, "The engine's conventions (the extensions)", operation by
operation: the nearest hit with t > 0 over spheres (the far root when the eye
is inside) and planes, the normal facing the eye, per light the article's
diffuse term (I*D)/(r*sqrt(KK)), Phong's highlight with RV^n by repeated
squaring, the contribution c (.) (m (.) (k_a*I + k_d*diffuse) + specular),
shadow rays with the no-acne rule, and the branches miss, dark, shadowed,
lit. It does not use promyk's code.

For a chosen set of pixels of each example scene in lessons/scenes/ (all but
article.json, which article_reference.json covers) and for a few closed-form
cases (scenes written inline in the output), every quantity is computed three
ways from the exact values of the IEEE doubles the engine holds:

- `exact`: at 200 bits (mpmath), 30 significant digits;
- `lo`, `hi`: a rigorous enclosure of every double a program performing the
  README's operations in the README's order can produce (the Interval class
  of make_reference.py: 200-bit intervals, each operation widened by one
  rounding); every test the engine makes (delta > 0, t > 0, the nearest t,
  NE = 0, NE > 0, D > 0, the shadow tests, RV > 0) must be decided by the
  enclosures, otherwise the pixel is `uncertain` and is never chosen;
- `double`: the README's operations in IEEE doubles (Python floats: every
  + - * / and math.sqrt is one correctly rounded operation, never fused).

The pixels are chosen by tracing every pixel of the pane (w = 16, and also
w = 15 for floor.json) in doubles and with enclosures, and covering every
feature a scene shows (branch, object, nearest of several hits, lights
reaching, behind or blocked and by what, Phong highlight or RV <= 0, colour,
a ray parallel to a plane) with certain pixels: the strongest highlight,
then greedily the pixel showing the most features not yet covered, then up
to 8 pixels spread over the features. The output is deterministic.
"""

import json
import math
import os
import sys
from fractions import Fraction

sys.dont_write_bytecode = True  # no __pycache__ in the source tree (the CTest check runs this script)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_reference as mr  # noqa: E402  (shared helpers: Interval, number formatting)
from make_reference import Interval, libmp, mpmath  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE_DIR = os.path.normpath(os.path.join(HERE, "..", "..", "lessons", "scenes"))

SCENE_FILES = [
    "two_spheres.json",
    "two_lights.json",
    "floor.json",
    "floor_wall.json",
    "shadows.json",
    "phong.json",
    "colour.json",
    "everything.json",
]
SIZES = {"floor.json": (16, 15), "floor_wall.json": (16, 15)}  # odd w: row 7 has y_E = 0, parallel to the floor
DEFAULT_SIZES = (16,)
MIN_PIXELS = 8


# --------------------------------------------------------------------------
# Scenes


DEFAULT_MATERIAL = {"ambient": 0.0, "diffuse": 1.0, "specular": 0.0, "exponent": 10, "colour": (1.0, 1.0, 1.0)}


def vec(v):
    x, y, z = v
    return (float(x), float(y), float(z))


def colour(v):
    if isinstance(v, (int, float)):
        return (float(v),) * 3
    return vec(v)


def parse_scene(doc):
    """A scene file's JSON as the doubles the engine holds, with the
    defaults of lessons/scenes/README.md."""
    materials = []
    for m in doc.get("materials", []):
        materials.append({
            "ambient": float(m.get("ambient", 0)),
            "diffuse": float(m.get("diffuse", 1)),
            "specular": float(m.get("specular", 0)),
            "exponent": int(m.get("exponent", 10)),
            "colour": colour(m.get("colour", [1, 1, 1])),
        })
    scene = {
        "name": doc.get("name", "untitled"),
        "z_E": float(doc.get("z_E", 2)),
        "background": colour(doc.get("background", 0.5)),
        "shadows": bool(doc.get("shadows", False)),
        "spheres": [{"S": vec(s["S"]), "r": float(s["r"]), "material": s.get("material")}
                    for s in doc.get("spheres", [])],
        "planes": [{"Q": vec(p["Q"]), "n": vec(p["n"]), "material": p.get("material")}
                   for p in doc.get("planes", [])],
        "lights": [{"L": vec(l["L"]), "I": float(l.get("I", 1)), "colour": colour(l.get("colour", [1, 1, 1]))}
                   for l in doc["lights"]],
        "materials": materials,
    }
    used = [material_of(scene, o["material"]) for o in scene["spheres"] + scene["planes"]]
    grey = lambda c: c[0] == c[1] == c[2]  # noqa: E731
    scene["coloured"] = not grey(scene["background"]) or \
        any(not grey(l["colour"]) for l in scene["lights"]) or any(not grey(m["colour"]) for m in used)
    return scene


def material_of(scene, index):
    return DEFAULT_MATERIAL if index is None else scene["materials"][index]


def load_scene_file(file_name):
    with open(os.path.join(SCENE_DIR, file_name), encoding="utf-8") as f:
        return parse_scene(json.load(f))


# --------------------------------------------------------------------------
# Three kinds of arithmetic. Each logs the engine's tests in order; the three
# runs of one pixel must take every test the same way.


class Uncertain(Exception):
    def __init__(self, at):
        super().__init__(at)
        self.at = at


class DoubleArith:
    def __init__(self):
        self.log = []

    num = staticmethod(float)
    sqrt = staticmethod(math.sqrt)

    def decide(self, name, outcome):
        self.log.append((name, outcome))
        return outcome

    def gt(self, name, a, b):
        return self.decide(name, a > b)

    def lt(self, name, a, b):
        return self.decide(name, a < b)

    def is_zero(self, name, a):
        return self.decide(name, a == 0)


class ExactArith(DoubleArith):
    num = staticmethod(mpmath.mpf)  # exact: a double has 53 bits
    sqrt = staticmethod(mpmath.sqrt)


class IntervalArith(DoubleArith):
    num = staticmethod(Interval.point)

    @staticmethod
    def sqrt(x):
        return x.sqrt()

    def gt(self, name, a, b):
        if libmp.mpf_gt(a.lo, b.hi):
            return self.decide(name, True)
        if libmp.mpf_le(a.hi, b.lo):
            return self.decide(name, False)
        raise Uncertain(name)

    def lt(self, name, a, b):
        if libmp.mpf_lt(a.hi, b.lo):
            return self.decide(name, True)
        if libmp.mpf_ge(a.lo, b.hi):
            return self.decide(name, False)
        raise Uncertain(name)

    def is_zero(self, name, a):
        if a.lo == libmp.fzero and a.hi == libmp.fzero:
            return self.decide(name, True)
        if libmp.mpf_gt(a.lo, libmp.fzero) or libmp.mpf_lt(a.hi, libmp.fzero):
            return self.decide(name, False)
        raise Uncertain(name)


# Vector operations, each component one operation, sums left to right.

def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def scale(s, v):
    return (s * v[0], s * v[1], s * v[2])


def divide(v, s):
    return (v[0] / s, v[1] / s, v[2] / s)


def neg(v):
    return (-v[0], -v[1], -v[2])


def power(x, n):
    """x^n by repeated squaring from the lowest bit (README): y = 1, and for
    each bit: if set y = y*x, then x = x*x. y = 1*x is exact, so the first
    multiplication is written as y = x; the last squaring is never used."""
    y = None
    while n:
        if n & 1:
            y = x if y is None else y * x
        n >>= 1
        if n:
            x = x * x
    return y


# --------------------------------------------------------------------------
# The engine's conventions (docs/conventions.md), one pixel


def pane_point(scene, w, i, j):
    """The engine's input: the pane formula in IEEE doubles."""
    return (2 * j + 1) / w - 1, -(2 * i + 1) / w + 1, scene["z_E"]


def trace(scene, ar, E_in):
    """Every quantity of one pixel, in arithmetic `ar`. Returns a dict whose
    numeric leaves are numbers or 3-tuples of `ar`'s kind."""
    num = ar.num
    zero, one, two = num(0.0), num(1.0), num(2.0)
    E = tuple(num(v) for v in E_in)
    EE = E[0] * E[0] + E[1] * E[1] + E[2] * E[2]
    out = {}

    candidates = []
    best = None
    for k, sphere in enumerate(scene["spheres"]):
        name = "sphere %d" % k
        S = tuple(num(v) for v in sphere["S"])
        r = num(sphere["r"])
        SS = S[0] * S[0] + S[1] * S[1] + S[2] * S[2]
        C = E[0] * S[0] + E[1] * S[1] + E[2] * S[2]
        delta = C * C - EE * (SS - r * r)
        if not ar.gt(name + ": delta > 0", delta, zero):
            continue
        root_delta = ar.sqrt(delta)
        t = (C - root_delta) / EE
        root = "near"
        if not ar.gt(name + ": t > 0", t, zero):
            t = (C + root_delta) / EE
            root = "far"
            if not ar.gt(name + ": t_far > 0", t, zero):
                continue
        hit = {"object": name, "kind": "sphere", "index": k, "root": root, "t": t, "S": S, "r": r}
        candidates.append(hit)
        if best is None or ar.lt("nearest: %s before %s" % (name, best["object"]), t, best["t"]):
            best = hit

    planes = []
    for k, plane in enumerate(scene["planes"]):
        name = "plane %d" % k
        n = tuple(num(v) for v in plane["n"])
        Q = tuple(num(v) for v in plane["Q"])
        n_len = ar.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2])
        n_hat = divide(n, n_len)
        NQ = dot(n_hat, Q)
        planes.append((n_hat, NQ))
        NE = dot(n_hat, E)
        if ar.is_zero(name + ": NE = 0 (the ray is parallel)", NE):
            continue
        t = NQ / NE
        if isinstance(t, float) and not math.isfinite(t):
            raise ValueError("a non-finite plane t")  # the chosen scenes never have one
        if not ar.gt(name + ": t > 0", t, zero):
            continue
        hit = {"object": name, "kind": "plane", "index": k, "t": t, "NE": NE}
        candidates.append(hit)
        if best is None or ar.lt("nearest: %s before %s" % (name, best["object"]), t, best["t"]):
            best = hit

    out["candidates"] = [{"object": h["object"], "t": h["t"]} for h in candidates]
    if best is None:
        out["branch"] = "miss"
        out["hit"] = None
        out["result"] = tuple(num(v) for v in scene["background"])
        return out

    t = best["t"]
    P = scale(t, E)
    if best["kind"] == "sphere":
        N = sub(P, best["S"])
        r = best["r"]
        flipped = best["root"] == "far"
        material = material_of(scene, scene["spheres"][best["index"]]["material"])
    else:
        N = planes[best["index"]][0]
        r = one
        flipped = ar.gt(best["object"] + ": NE > 0 (seen from its back)", best["NE"], zero)
        material = material_of(scene, scene["planes"][best["index"]]["material"])
    if flipped:
        N = neg(N)
    hit_record = {"object": best["object"], "kind": best["kind"], "index": best["index"]}
    if best["kind"] == "sphere":
        hit_record["root"] = best["root"]
    hit_record["normal_flipped"] = flipped
    out["hit"] = hit_record
    out["t"] = t
    out["P"] = P
    out["N"] = N

    ka, kd, ks = material["ambient"], material["diffuse"], material["specular"]
    m = material["colour"]
    lights = []
    total = None
    for l, light in enumerate(scene["lights"]):
        prefix = "light %d: " % l
        L = tuple(num(v) for v in light["L"])
        I = num(light["I"])
        c = light["colour"]
        K = sub(L, P)
        KK = K[0] * K[0] + K[1] * K[1] + K[2] * K[2]
        D = N[0] * K[0] + N[1] * K[1] + N[2] * K[2]
        record = {"light": l, "K": K, "KK": KK, "D": D}
        faces = ar.gt(prefix + "D > 0", D, zero)
        record["faces"] = faces
        blocker = ""
        if faces and scene["shadows"]:
            for k, sphere in enumerate(scene["spheres"]):
                name = "sphere %d" % k
                if best["object"] == name:
                    # The no-acne rule: never tested numerically against its
                    # own point; from inside it blocks exactly when 2D < KK.
                    blocks = best["root"] == "far" and ar.lt(prefix + name + " blocks its own inside: 2D < KK",
                                                             two * D, KK)
                else:
                    S = tuple(num(v) for v in sphere["S"])
                    r_s = num(sphere["r"])
                    SP = sub(S, P)
                    b = K[0] * SP[0] + K[1] * SP[1] + K[2] * SP[2]
                    c_s = (SP[0] * SP[0] + SP[1] * SP[1] + SP[2] * SP[2]) - r_s * r_s
                    delta_s = b * b - KK * c_s
                    blocks = False
                    if ar.gt(prefix + name + ": delta_s > 0", delta_s, zero):
                        root_s = ar.sqrt(delta_s)
                        s1 = (b - root_s) / KK
                        s2 = (b + root_s) / KK
                        # Every test is made (and must be certain), so the
                        # record does not depend on the order of the tests.
                        in1 = [ar.gt(prefix + name + ": s1 > 0", s1, zero), ar.lt(prefix + name + ": s1 < 1", s1, one)]
                        in2 = [ar.gt(prefix + name + ": s2 > 0", s2, zero), ar.lt(prefix + name + ": s2 < 1", s2, one)]
                        blocks = all(in1) or all(in2)
                if blocks and not blocker:
                    blocker = name
            for k, (n_hat, NQ) in enumerate(planes):
                name = "plane %d" % k
                if best["object"] == name:
                    continue  # a plane cannot block its own point
                nK = n_hat[0] * K[0] + n_hat[1] * K[1] + n_hat[2] * K[2]
                blocks = False
                if not ar.is_zero(prefix + name + ": n.K = 0", nK):
                    s = (NQ - (n_hat[0] * P[0] + n_hat[1] * P[1] + n_hat[2] * P[2])) / nK
                    blocks = all([ar.gt(prefix + name + ": s > 0", s, zero), ar.lt(prefix + name + ": s < 1", s, one)])
                if blocks and not blocker:
                    blocker = name
        record["blocked"] = bool(blocker)
        record["blocker"] = blocker
        reaches = faces and not blocker
        diffuse = (I * D) / (r * ar.sqrt(KK)) if reaches else zero
        record["diffuse"] = diffuse
        specular = None
        if reaches and ks > 0:
            root_KK = ar.sqrt(KK)
            N_hat = divide(N, r)
            K_hat = divide(K, root_KK)
            cos_alpha = N_hat[0] * K_hat[0] + N_hat[1] * K_hat[1] + N_hat[2] * K_hat[2]
            R_hat = sub(scale(two * cos_alpha, N_hat), K_hat)
            root_PP = ar.sqrt(P[0] * P[0] + P[1] * P[1] + P[2] * P[2])
            V_hat = divide(neg(P), root_PP)
            RV = R_hat[0] * V_hat[0] + R_hat[1] * V_hat[1] + R_hat[2] * V_hat[2]
            record["cos_alpha"] = cos_alpha
            record["RV"] = RV
            if ar.gt(prefix + "RV > 0", RV, zero):
                specular = I * (num(ks) * power(RV, material["exponent"]))
        record["specular"] = specular if specular is not None else zero
        # c (.) (m (.) (k_a I + k_d diffuse) + specular), per channel. A
        # factor 1 or a term 0 that the engine skips (its stage does not run)
        # or computes gives the same double (1*x = x, 0*I + x = x for x >= 0,
        # x + 0 = x), so they are skipped here, keeping the enclosures tight.
        base = diffuse if kd == 1.0 else num(kd) * diffuse
        if ka != 0.0:
            base = num(ka) * I + base
        contribution = []
        for ch in range(3):
            value = base if m[ch] == 1.0 else num(m[ch]) * base
            if specular is not None:
                value = value + specular
            if c[ch] != 1.0:
                value = num(c[ch]) * value
            contribution.append(value)
        contribution = tuple(contribution)
        record["contribution"] = contribution
        total = contribution if total is None else tuple(a + b for a, b in zip(total, contribution))
        lights.append(record)
    out["lights"] = lights
    faced = [rec for rec in lights if rec["faces"]]
    if not faced:
        out["branch"] = "dark"
    elif all(rec["blocked"] for rec in faced):
        out["branch"] = "shadowed"
    else:
        out["branch"] = "lit"
    out["result"] = total
    return out


# --------------------------------------------------------------------------
# Records


def trace_double(scene, E):
    ar = DoubleArith()
    return trace(scene, ar, E), ar.log


def trace_interval(scene, E):
    """(trace, log), or raises Uncertain at the first undecided test."""
    ar = IntervalArith()
    return trace(scene, ar, E), ar.log


def trace_exact(scene, E):
    ar = ExactArith()
    return trace(scene, ar, E), ar.log


def all_finite(value):
    if isinstance(value, float):
        return math.isfinite(value)
    if isinstance(value, (tuple, list)):
        return all(all_finite(v) for v in value)
    if isinstance(value, dict):
        return all(all_finite(v) for v in value.values())
    return True


def value_record(exact, enclosure, double):
    if isinstance(double, tuple):
        parts = [mr.component_record(e, b, d) for e, b, d in zip(exact, enclosure, double)]
        return {"exact": [p[0] for p in parts], "lo": [p[1] for p in parts],
                "hi": [p[2] for p in parts], "double": [p[3] for p in parts]}
    e, lo, hi, d = mr.component_record(exact, enclosure, double)
    return {"exact": e, "lo": lo, "hi": hi, "double": d}


def combine(exact, enclosure, double):
    """One record from the three runs (the same structure)."""
    if isinstance(double, (float, tuple)):
        return value_record(exact, enclosure, double)
    if isinstance(double, dict):
        assert exact.keys() == enclosure.keys() == double.keys()
        return {key: combine(exact[key], enclosure[key], double[key]) for key in double}
    if isinstance(double, list):
        assert len(exact) == len(enclosure) == len(double)
        return [combine(e, b, d) for e, b, d in zip(exact, enclosure, double)]
    assert exact == enclosure == double, (exact, enclosure, double)
    return double


def grey_values(record, coloured):
    """In a grey scene the three channels are equal: one value."""
    if coloured:
        return record
    out = {}
    for key in ("exact", "lo", "hi", "double"):
        values = record[key]
        assert values[0] == values[1] == values[2]
        out[key] = values[0]
    return out


def error_bound(exact, record):
    """max |v - exact| over v in [lo, hi], rounded up to a double, per value
    (from the 200-bit exact value, not its 30-digit text)."""
    def one(e, lo, hi):
        e = mr.mpf_fraction(e)
        return mr.double_text(mr.round_up(max(e - Fraction(float(lo)), Fraction(float(hi)) - e)))
    if isinstance(record["lo"], list):
        return [one(e, lo, hi) for e, lo, hi in zip(exact, record["lo"], record["hi"])]
    return one(exact[0], record["lo"], record["hi"])


def pixel_record(scene, w, i, j, extra=None):
    E = pane_point(scene, w, i, j)
    double, double_log = trace_double(scene, E)
    enclosure, enclosure_log = trace_interval(scene, E)  # raises Uncertain
    exact, exact_log = trace_exact(scene, E)
    if not (double_log == enclosure_log == exact_log):
        raise AssertionError("the three runs took different branches at %r" % ((w, i, j),))
    assert all_finite(double)
    record = {"w": w, "i": i, "j": j}
    if extra:
        record.update(extra)
    record["pane_rational"] = [mr.fraction_text(Fraction(2 * j + 1, w) - 1),
                               mr.fraction_text(-Fraction(2 * i + 1, w) + 1)]
    record["E"] = [repr(v) for v in E]
    record["branch"] = double["branch"]
    hit = double["hit"]
    record["hit_object"] = hit["object"] if hit else ""
    if hit:
        record["hit"] = hit
    record["candidates"] = combine(exact["candidates"], enclosure["candidates"], double["candidates"])
    for key in ("t", "P", "N"):
        if key in double:
            record[key] = combine(exact[key], enclosure[key], double[key])
    if "lights" in double:
        lights = combine(exact["lights"], enclosure["lights"], double["lights"])
        for light in lights:
            light["contribution"] = grey_values(light["contribution"], scene["coloured"])
        record["lights"] = lights
    result = grey_values(combine(exact["result"], enclosure["result"], double["result"]), scene["coloured"])
    result["error_bound"] = error_bound(exact["result"], result)
    record["result"] = result
    return record, exact


# --------------------------------------------------------------------------
# Choosing pixels


def features(scene, tr, E):
    """What a traced pixel (double run) shows, as short names."""
    out = ["branch " + tr["branch"]]
    hit = tr["hit"]
    if hit is None:
        if E[1] == 0 and scene["planes"]:
            out.append("parallel to the planes: miss")
        return out
    obj = hit["object"]
    out.append("%s %s" % (obj, tr["branch"]))
    if len(tr["candidates"]) >= 2:
        out.append("nearest of %d hits: %s" % (len(tr["candidates"]), obj))
    if hit.get("root") == "far":
        out.append("far root")
    if hit["normal_flipped"]:
        out.append("normal flipped")
    if E[1] == 0 and scene["planes"]:
        out.append("parallel to the planes: %s" % obj)
    multi = len(tr["lights"]) > 1
    for rec in tr["lights"]:
        l = rec["light"]
        if not rec["faces"]:
            if multi:
                out.append("%s: light %d behind" % (obj, l))
        elif rec["blocked"]:
            out.append("%s: light %d blocked by %s" % (obj, l, rec["blocker"]))
        elif multi:
            out.append("%s: light %d reaches" % (obj, l))
        if "RV" in rec:
            out.append("Phong highlight" if rec["RV"] > 0 else "Phong RV <= 0")
    if scene["coloured"]:
        r, g, b = tr["result"]
        if not (r == g == b):
            out.append("coloured")
    return out


def highlight(tr):
    return max([rec["specular"] for rec in tr.get("lights", [])] + [0.0])


def choose(scene, w):
    """The chosen pixels [(i, j, picked_for)], and the uncertain pixels of the
    whole pane [(i, j, test)]."""
    table = {}
    uncertain = []
    for i in range(w):
        for j in range(w):
            E = pane_point(scene, w, i, j)
            tr, log = trace_double(scene, E)
            try:
                _, interval_log = trace_interval(scene, E)
            except Uncertain as u:
                uncertain.append((i, j, u.at))
                continue
            if log != interval_log:
                raise AssertionError("double outside its enclosure's decisions at %r" % ((w, i, j),))
            if not all_finite(tr):
                continue
            table[(i, j)] = (features(scene, tr, E), tr)

    order = []
    for feats, _ in (table[key] for key in sorted(table)):
        for f in feats:
            if f not in order:
                order.append(f)
    # Branches first, then rays parallel to a plane, then the rest as first seen.
    order.sort(key=lambda f: (not f.startswith("branch "), not f.startswith("parallel")))

    chosen = {}
    covered = set()

    def pick(key, reason):
        if key not in chosen:
            chosen[key] = []
        chosen[key].append(reason)
        covered.update(table[key][0])

    # The strongest highlight, a real peak rather than the rim of one.
    shiny = [(highlight(tr), key) for key, (_, tr) in table.items() if highlight(tr) > 0]
    if shiny:
        pick(max(shiny, key=lambda s: (s[0], -s[1][0], -s[1][1]))[1], "strongest Phong highlight")
    # Then greedily: the pixel that shows the most features not yet covered
    # (ties: the one nearest the middle of the pane, then by (i, j)).
    middle = w - 1  # 2 * the middle's coordinate
    while True:
        best, best_key = None, None
        for key in sorted(table):
            gain = len(set(table[key][0]) - covered)
            rank = (-gain, (2 * key[0] - middle) ** 2 + (2 * key[1] - middle) ** 2, key)
            if gain and (best is None or rank < best):
                best, best_key = rank, key
        if best_key is None:
            break
        pick(best_key, "features: " + ", ".join(f for f in table[best_key][0] if f not in covered))
    # Up to MIN_PIXELS: round the features again (misses last), each time
    # the member farthest from the pixels chosen so far.
    refill = [f for f in order if f != "branch miss"] + ["branch miss"]
    while len(chosen) < MIN_PIXELS:
        added = False
        for f in refill:
            if len(chosen) >= MIN_PIXELS:
                break
            members = [key for key, (feats, _) in sorted(table.items()) if f in feats and key not in chosen]
            if not members:
                continue
            distance = lambda k: min((k[0] - c[0]) ** 2 + (k[1] - c[1]) ** 2 for c in chosen)  # noqa: E731
            pick(min(members, key=lambda k: (-distance(k), k)), "another: " + f)
            added = True
        if not added:
            break
    return [(i, j, chosen[(i, j)], table[(i, j)][0]) for i, j in sorted(chosen)], uncertain


# --------------------------------------------------------------------------
# Closed-form cases: small scenes written inline, one pixel each, whose
# values follow by hand. The script checks the exact values against them.

F = Fraction

# A sphere out of the way (a scene has at least one sphere): the rays of the
# cases without a sphere of their own miss it (delta < 0), and none of them
# casts shadows.
ASIDE = {"S": [3, 3, 6], "r": 1}

CLOSED_FORM = [
    {
        "name": "plane head-on",
        "why": "w = 1, E = (0, 0, 2) meets the plane z = 4 (n = (0, 0, -2), so n^ = (0, 0, -1) exactly) "
               "at right angles: NE = -2, NQ = -4, t = 2, P = (0, 0, 4), N = (0, 0, -1) (r = 1); the light "
               "at (0, 0, 1): K = (0, 0, -3), KK = 9, D = 3, I_P = 0.75 * 3 / (1 * 3) = 0.75",
        "scene": {"name": "plane head-on", "z_E": 2, "background": 0.5,
                  "spheres": [ASIDE], "planes": [{"Q": [0, 0, 4], "n": [0, 0, -2]}],
                  "lights": [{"L": [0, 0, 1], "I": 0.75}]},
        "w": 1, "i": 0, "j": 0,
        "expect": {"branch": "lit", "hit_object": "plane 0", "t": F(2), "P": (0, 0, 4), "N": (0, 0, -1),
                   "KK": F(9), "D": F(3), "result": F(3, 4)},
    },
    {
        "name": "plane from its back",
        "why": "the same plane with n = (0, 0, 1): NE = 2 > 0, NQ = 4, t = 2; the normal is flipped to "
               "(0, 0, -1), which faces the eye, and the light: D = 3, I_P = 0.75",
        "scene": {"name": "plane from its back", "z_E": 2, "background": 0.5,
                  "spheres": [ASIDE], "planes": [{"Q": [0, 0, 4], "n": [0, 0, 1]}],
                  "lights": [{"L": [0, 0, 1], "I": 0.75}]},
        "w": 1, "i": 0, "j": 0,
        "expect": {"branch": "lit", "hit_object": "plane 0", "t": F(2), "P": (0, 0, 4), "N": (0, 0, -1),
                   "KK": F(9), "D": F(3), "result": F(3, 4), "normal_flipped": True},
    },
    {
        "name": "light straight above",
        "why": "w = 2, pixel (1, 0): E = (-0.5, -0.5, 1) meets the floor y = -1 at t = 2, P = (-1, -1, 2); "
               "the light at (-1, 3, 2) is straight above P: K = (0, 4, 0), KK = 16, D = 4, cos(alpha) = 1, "
               "diffuse = 0.5 * 4 / (1 * 4) = 0.5; with k_a = 0.25, k_d = 0.5: "
               "I_P = 0.25 * 0.5 + 0.5 * 0.5 = 0.375",
        "scene": {"name": "light straight above", "z_E": 1, "background": 0.5, "spheres": [ASIDE],
                  "planes": [{"Q": [0, -1, 0], "n": [0, 1, 0], "material": 0}],
                  "lights": [{"L": [-1, 3, 2], "I": 0.5}],
                  "materials": [{"ambient": 0.25, "diffuse": 0.5}]},
        "w": 2, "i": 1, "j": 0,
        "expect": {"branch": "lit", "hit_object": "plane 0", "t": F(2), "P": (-1, -1, 2), "N": (0, 1, 0),
                   "KK": F(16), "D": F(4), "diffuse": F(1, 2), "result": F(3, 8)},
    },
    {
        "name": "eye inside a sphere",
        "why": "w = 2, z_E = 0.25, pixel (0, 1): E = (0.5, 0.5, 0.25), |E| = 0.75; the sphere of radius 2 "
               "at the origin: C = 0, delta = 4 EE, the near root -2/|E| < 0, so the far root "
               "t_far = 2/|E| = 8/3 is taken, P = (4/3, 4/3, 2/3) (|P| = 2), N = -(P - S) = -P (flipped). "
               "Light 0 at the origin: K = -P, KK = 4, D = 4, 2D = 8 >= KK: not blocked, diffuse = "
               "0.5 * 4 / (2 * 2) = 0.5. Light 1 at (0, 0, 3), outside: K = (-4/3, -4/3, 7/3), KK = 9, "
               "D = 2 > 0 but 2D = 4 < KK: the sphere blocks its own inside. I_P = 0.5",
        "scene": {"name": "eye inside a sphere", "z_E": 0.25, "background": 0.5, "shadows": True,
                  "spheres": [{"S": [0, 0, 0], "r": 2}],
                  "lights": [{"L": [0, 0, 0], "I": 0.5}, {"L": [0, 0, 3], "I": 1}]},
        "w": 2, "i": 0, "j": 1,
        "expect": {"branch": "lit", "hit_object": "sphere 0", "t": F(8, 3), "P": (F(4, 3), F(4, 3), F(2, 3)),
                   "N": (F(-4, 3), F(-4, 3), F(-2, 3)), "KK": F(4), "D": F(4), "result": F(1, 2),
                   "root": "far", "normal_flipped": True,
                   "light 1": {"KK": F(9), "D": F(2), "blocked": True, "blocker": "sphere 0"}},
    },
    {
        "name": "Phong peak",
        "why": "w = 8, z_E = 0.1875, pixel (4, 5): E = (0.375, -0.125, 0.1875) meets the floor y = -1 at "
               "t = 8, P = (3, -1, 1.5), |P| = 3.5, V^ = -P/3.5 = (-6, 2, -3)/7; the light at "
               "L = P + (6, 2, 3) = (9, 1, 4.5) is the mirror image of the eye's direction in the floor: "
               "K = (6, 2, 3), KK = 49, D = 2, cos(alpha) = 2/7, R^ = (4/7) (0, 1, 0) - K/7 = V^, RV = 1. "
               "k_d = 0.7, k_s = 0.5, n = 20: I_P = 0.7 * 2/7 + 0.5 * 1^20 = 0.2 + 0.5 (with the doubles "
               "0.7 and 0.5)",
        "scene": {"name": "Phong peak", "z_E": 0.1875, "background": 0.5, "spheres": [ASIDE],
                  "planes": [{"Q": [0, -1, 0], "n": [0, 1, 0], "material": 0}],
                  "lights": [{"L": [9, 1, 4.5], "I": 1}],
                  "materials": [{"diffuse": 0.7, "specular": 0.5, "exponent": 20}]},
        "w": 8, "i": 4, "j": 5,
        "expect": {"branch": "lit", "hit_object": "plane 0", "t": F(8), "P": (3, -1, F(3, 2)), "N": (0, 1, 0),
                   "KK": F(49), "D": F(2), "cos_alpha": F(2, 7), "RV": F(1), "diffuse": F(2, 7),
                   "specular": F(0.5), "result": F(0.7) * F(2, 7) + F(0.5)},
    },
    {
        "name": "blocker midway",
        "why": "as 'light straight above' (P = (-1, -1, 2), L = (-1, 3, 2), K = (0, 4, 0), KK = 16) with "
               "shadows and a sphere of radius 0.5 centred midway, at (-1, 1, 2) (the eye's ray passes it "
               "at a distance sqrt(10/3) > 0.5): S - P = (0, 2, 0), b = 8, c = 4 - 0.25 = 3.75, "
               "delta_s = 64 - 60 = 4, s = (8 -+ 2)/16 = 0.375, 0.625 = 1/2 -+ r/|K|: blocked. "
               "Only the ambient remains: I_P = 0.25 * 0.5 = 0.125",
        "scene": {"name": "blocker midway", "z_E": 1, "background": 0.5, "shadows": True,
                  "spheres": [{"S": [-1, 1, 2], "r": 0.5, "material": 0}],
                  "planes": [{"Q": [0, -1, 0], "n": [0, 1, 0], "material": 0}],
                  "lights": [{"L": [-1, 3, 2], "I": 0.5}],
                  "materials": [{"ambient": 0.25, "diffuse": 0.5}]},
        "w": 2, "i": 1, "j": 0,
        "expect": {"branch": "shadowed", "hit_object": "plane 0", "t": F(2), "P": (-1, -1, 2), "N": (0, 1, 0),
                   "KK": F(16), "D": F(4), "diffuse": F(0), "result": F(1, 8), "blocked": True,
                   "blocker": "sphere 0"},
    },
]


def close(value, expected):
    """The 200-bit value agrees with a closed form (2^-180 relative)."""
    value = mr.mpf_fraction(value) if not isinstance(value, Fraction) else value
    expected = Fraction(expected)
    return abs(value - expected) <= abs(expected) * Fraction(1, 2**180) + Fraction(1, 2**400)


def check_closed_form(case, record, exact):
    expect = case["expect"]
    problems = []

    def need(ok, what):
        if not ok:
            problems.append(what)

    need(record["branch"] == expect["branch"], "branch")
    need(record["hit_object"] == expect["hit_object"], "hit object")
    for key in ("root", "normal_flipped"):
        if key in expect:
            need(record["hit"][key] == expect[key], key)
    need(close(exact["t"], expect["t"]), "t")
    for key in ("P", "N"):
        need(all(close(a, b) for a, b in zip(exact[key], expect[key])), key)
    light = exact["lights"][0]
    for key in ("KK", "D", "diffuse", "cos_alpha", "RV", "specular"):
        if key in expect:
            need(close(light[key], expect[key]), key)
    for key in ("blocked", "blocker"):
        if key in expect:
            need(light[key] == expect[key], key)
    if "light 1" in expect:
        other = exact["lights"][1]
        for key, value in expect["light 1"].items():
            need(other[key] == value if isinstance(value, (bool, str)) else close(other[key], value), "light 1 " + key)
    need(all(close(v, expect["result"]) for v in exact["result"]), "result")
    if problems:
        raise AssertionError("closed form %r: %s differ" % (case["name"], ", ".join(problems)))


def closed_form_text(expect):
    def text(v):
        if isinstance(v, (bool, str)):
            return v
        if isinstance(v, dict):
            return {k: text(x) for k, x in v.items()}
        if isinstance(v, tuple):
            return [text(x) for x in v]
        v = Fraction(v)
        return str(v.numerator) if v.denominator == 1 else mr.fraction_text(v)
    return {k: text(v) for k, v in expect.items()}


# --------------------------------------------------------------------------
# Output


def header():
    return {
        "format": "promyk effects reference",
        "format_version": 1,
        "generator": "tests/reference/make_effects_reference.py (python3 with mpmath); regenerate with: "
                     "python3 tests/reference/make_effects_reference.py tests/reference/effects_reference.json",
        "precision_bits": mr.PREC,
        "conventions": "docs/conventions.md, 'The engine's conventions (the extensions)', followed operation by operation",
        "scene_files": "lessons/scenes/FILE; each number is taken as the exact value of the IEEE double nearest "
                       "its decimal text",
        "pane": "E = (x_E, y_E, z_E) with x_E = (2j+1)/w - 1 and y_E = -(2i+1)/w + 1 in IEEE doubles; "
                "pane_rational holds the exact [x_E, y_E]",
        "exact": "200 bits from the exact double inputs, %d significant digits" % mr.EXACT_DIGITS,
        "enclosure": "[lo, hi]: every double a program performing the README's operations in its order (each "
                     "+ - * / sqrt correctly rounded to nearest, no FMA) can produce; 200-bit intervals, each "
                     "operation widened by 2^-53 relative (plus 2^-1075 near zero), endpoints rounded outward",
        "double": "the README's operations in IEEE doubles without FMA (Python floats), Python repr",
        "error_bound": "max |v - exact| over v in [lo, hi], rounded up: a bound on the engine's error",
        "certain": "every test the engine makes is decided by the enclosures at every listed pixel; "
                   "`uncertain` lists the pixels of each pane where one is not (never chosen)",
        "result": "a number for a grey scene, [r, g, b] for a coloured one",
    }


def main(argv):
    if len(argv) != 2:
        sys.stderr.write("usage: make_effects_reference.py OUTPUT.json\n")
        return 2
    if argv[-1].startswith("-"):
        # An option misread as the output would write a file named like it
        # (a 257 KB file '--help' was committed once).
        sys.stderr.write(f"{argv[0]}: the output path must not begin with '-': {argv[-1]}\n")
        return 2
    scene_blocks = []
    for file_name in SCENE_FILES:
        scene = load_scene_file(file_name)
        for w in SIZES.get(file_name, DEFAULT_SIZES):
            chosen, uncertain = choose(scene, w)
            pixels = []
            for i, j, picked_for, feats in chosen:
                record, _ = pixel_record(scene, w, i, j, {"picked_for": picked_for, "features": feats})
                pixels.append(record)
            scene_blocks.append({
                "file": file_name,
                "name": scene["name"],
                "coloured": scene["coloured"],
                "w": w,
                "uncertain": [{"i": i, "j": j, "at": at} for i, j, at in uncertain],
                "pixels": pixels,
            })
    closed = []
    for case in CLOSED_FORM:
        scene = parse_scene(case["scene"])
        record, exact = pixel_record(scene, case["w"], case["i"], case["j"])
        check_closed_form(case, record, exact)
        closed.append({"name": case["name"], "why": case["why"], "scene": case["scene"],
                       "coloured": scene["coloured"], "closed_form": closed_form_text(case["expect"]),
                       "pixel": record})

    lines = ["{"]
    for key, value in header().items():
        lines.append(" %s: %s," % (json.dumps(key), json.dumps(value, ensure_ascii=True)))
    lines.append(' "scenes": [')
    blocks = []
    for block in scene_blocks:
        pixels = block.pop("pixels")
        head = json.dumps(block, separators=(",", ":"))[:-1]
        body = ",\n".join("  " + json.dumps(p, separators=(",", ":")) for p in pixels)
        blocks.append(" %s,\"pixels\":[\n%s\n ]}" % (head, body))
    lines.append(",\n".join(blocks))
    lines.append(" ],")
    lines.append(' "closed_form": [')
    lines.append(",\n".join(" " + json.dumps(c, separators=(",", ":")) for c in closed))
    lines.append(" ]")
    lines.append("}")
    text = "\n".join(lines) + "\n"
    json.loads(text)  # well-formed
    with open(argv[-1], "w", encoding="ascii", newline="\n") as out:
        out.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
