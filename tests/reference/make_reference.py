#!/usr/bin/env python3
"""Independent high-precision reference for the article's scene.

Usage: python3 make_reference.py OUTPUT.json

For a fixed set of pixels of the article's scene (Fig. 5: z_E = 2,
S = (0, 0, 3.2), r = 1.1, L = (1.5, 1, 1), I = 1, background 1/2) this script
computes every quantity the tracer records (E, EE, SS, C, delta, t, P, N, K,
KK, D) and the pixel's intensity I_P, following section 5 of the article:

- `exact`: the value of the article's formula at 200 bits (mpmath), taking
  the scene's numbers and the pane point E as the exact values of the IEEE
  doubles the tracer receives (3.2 means Fraction(3.2), not 16/5). Written
  with 30 significant digits.
- `lo`, `hi`: a rigorous enclosure of every value an IEEE double program
  that performs the article's operations in the article's order (each
  + - * / sqrt correctly rounded to nearest, no FMA) can produce. Intervals
  are propagated at 200 bits with outward rounding; after each operation the
  interval is widened by one rounding, |fl(z) - z| <= 2^-53 |z| + 2^-1075
  (the second term only where the interval reaches the subnormal range; an
  exact zero stays zero). The endpoints are written as doubles, lo rounded
  down and hi rounded up (Python repr, which reads back exactly).
- `double`: the value the article's program computes in IEEE doubles without
  FMA, evaluated with Python floats (each + - * / and math.sqrt is one
  correctly rounded IEEE operation; Python never fuses operations). A
  correctly compiled tracer reproduces it bit for bit.
- `branch`: miss (delta <= 0), dark (D <= 0) or lit, or `uncertain` when the
  enclosure of delta or of D contains values on both sides of the test; an
  uncertain pixel lists the quantities up to that test only.

The pane point is computed with Python floats exactly as the pane formula
does, y_E = -(2i+1)/w + 1 and x_E = (2j+1)/w - 1 (int / int is correctly
rounded in Python, the addition is an IEEE double addition), since those
doubles are the tracer's input; the exact rational pane values are recorded
too (`pane_rational`).

The output is deterministic: the same bytes on every run, with mpmath 1.2 or
1.3 (only mpmath's raw libmp arithmetic with explicit rounding and its mpf
type are used; numbers are formatted by this script from exact rationals).
"""

import json
import math
import os
import sys
from fractions import Fraction

import mpmath
from mpmath import libmp

PREC = 200
mpmath.mp.prec = PREC

FLOOR = libmp.round_floor
CEIL = libmp.round_ceiling

# The article's scene, as the IEEE doubles the tracer holds.
ARTICLE_SCENE = {
    "name": "article",
    "z_E": 2.0,
    "S": (0.0, 0.0, 3.2),
    "r": 1.1,
    "L": (1.5, 1.0, 1.0),
    "I": 1.0,
    "background": 0.5,
}

EXACT_DIGITS = 30
KEYS = ["E", "EE", "SS", "C", "delta", "t", "P", "N", "K", "KK", "D"]


# --------------------------------------------------------------------------
# Exact rationals and doubles


def raw_to_fraction(raw):
    """The exact value of a raw mpf tuple (finite values only)."""
    sign, man, exp, _bc = raw
    if man == 0:
        if raw != libmp.fzero:
            raise ValueError("non-finite value %r" % (raw,))
        return Fraction(0)
    value = Fraction(man * 2**exp) if exp >= 0 else Fraction(man, 2**-exp)
    return -value if sign else value


def is_double(raw):
    """Whether a raw mpf value is exactly an IEEE double (finite)."""
    value = raw_to_fraction(raw)
    try:
        return Fraction(float(value)) == value
    except OverflowError:
        return False


def round_down(value):
    """The largest double <= value (value a Fraction)."""
    f = float(value)  # correctly rounded to nearest
    if Fraction(f) > value:
        f = math.nextafter(f, -math.inf)
    return f


def round_up(value):
    """The smallest double >= value (value a Fraction)."""
    f = float(value)
    if Fraction(f) < value:
        f = math.nextafter(f, math.inf)
    return f


def double_text(f):
    """A double as the shortest text that reads back to it."""
    if not math.isfinite(f):
        raise ValueError("non-finite double")
    if f == 0:
        f = 0.0  # never write -0.0 as an enclosure endpoint
    return repr(f)


def decimal_text(value, digits=EXACT_DIGITS):
    """A rational in scientific notation, `digits` significant digits,
    rounded half to even, formatted by exact integer arithmetic."""
    if value == 0:
        return "0"
    negative = value < 0
    a = -value if negative else value
    # e = floor(log10(a)), found exactly.
    e = len(str(a.numerator)) - len(str(a.denominator))
    while Fraction(10) ** e > a:
        e -= 1
    while Fraction(10) ** (e + 1) <= a:
        e += 1
    n = round(a * Fraction(10) ** (digits - 1 - e))
    if n >= 10**digits:
        n //= 10
        e += 1
    s = str(n)
    return "%s%s.%se%d" % ("-" if negative else "", s[0], s[1:], e)


def fraction_text(value):
    return "%d/%d" % (value.numerator, value.denominator)


# --------------------------------------------------------------------------
# Intervals at 200 bits, widened by one double rounding after every operation

UNIT_ROUNDOFF = libmp.from_man_exp(1, -53)
SUBNORMAL_HALF_SPACING = libmp.from_man_exp(1, -1075)
SMALLEST_NORMAL = libmp.from_man_exp(1, -1022)


def rmin(values):
    best = values[0]
    for v in values[1:]:
        if libmp.mpf_lt(v, best):
            best = v
    return best


def rmax(values):
    best = values[0]
    for v in values[1:]:
        if libmp.mpf_gt(v, best):
            best = v
    return best


class Interval:
    """[lo, hi] with raw mpf endpoints; contains every double the program
    can hold at this point."""

    def __init__(self, lo, hi):
        if libmp.mpf_gt(lo, hi):
            raise ValueError("empty interval")
        self.lo, self.hi = lo, hi

    @staticmethod
    def point(f):
        raw = libmp.from_float(f)
        return Interval(raw, raw)

    # One correctly rounded double operation whose exact result lies in
    # [lo, hi] returns a double in [lo - u|lo| - eta, hi + u|hi| + eta].
    def rounded(self):
        if self.lo == libmp.fzero and self.hi == libmp.fzero:
            return self  # an exact zero is returned exactly
        if self.lo == self.hi and is_double(self.lo):
            # The operation's exact result is this one value and it is a
            # double: a correctly rounded operation returns it exactly (so a
            # delta or D that is exactly 0 in double is a certain miss or dark).
            return self
        lo = libmp.mpf_sub(self.lo, libmp.mpf_mul(libmp.mpf_abs(self.lo), UNIT_ROUNDOFF, PREC, CEIL), PREC, FLOOR)
        hi = libmp.mpf_add(self.hi, libmp.mpf_mul(libmp.mpf_abs(self.hi), UNIT_ROUNDOFF, PREC, CEIL), PREC, CEIL)
        # Does the interval reach below the smallest normal in magnitude?
        reaches_subnormal = (libmp.mpf_le(self.lo, libmp.fzero) and libmp.mpf_ge(self.hi, libmp.fzero)) or \
            libmp.mpf_lt(rmin([libmp.mpf_abs(self.lo), libmp.mpf_abs(self.hi)]), SMALLEST_NORMAL)
        if reaches_subnormal:
            lo = libmp.mpf_sub(lo, SUBNORMAL_HALF_SPACING, PREC, FLOOR)
            hi = libmp.mpf_add(hi, SUBNORMAL_HALF_SPACING, PREC, CEIL)
        return Interval(lo, hi)

    def __neg__(self):
        """-x is exact in IEEE arithmetic: no rounding."""
        return Interval(libmp.mpf_neg(self.hi), libmp.mpf_neg(self.lo))

    def __add__(self, other):
        return Interval(libmp.mpf_add(self.lo, other.lo, PREC, FLOOR),
                        libmp.mpf_add(self.hi, other.hi, PREC, CEIL)).rounded()

    def __sub__(self, other):
        return Interval(libmp.mpf_sub(self.lo, other.hi, PREC, FLOOR),
                        libmp.mpf_sub(self.hi, other.lo, PREC, CEIL)).rounded()

    def __mul__(self, other):
        if other is self:
            return self.square()
        pairs = [(a, b) for a in (self.lo, self.hi) for b in (other.lo, other.hi)]
        return Interval(rmin([libmp.mpf_mul(a, b, PREC, FLOOR) for a, b in pairs]),
                        rmax([libmp.mpf_mul(a, b, PREC, CEIL) for a, b in pairs])).rounded()

    def square(self):
        """x*x with both factors the same double: never negative."""
        a, b = libmp.mpf_abs(self.lo), libmp.mpf_abs(self.hi)
        big = rmax([a, b])
        if libmp.mpf_le(self.lo, libmp.fzero) and libmp.mpf_ge(self.hi, libmp.fzero):
            small = libmp.fzero
        else:
            small = rmin([a, b])
        return Interval(libmp.mpf_mul(small, small, PREC, FLOOR), libmp.mpf_mul(big, big, PREC, CEIL)).rounded()

    def __truediv__(self, other):
        if libmp.mpf_le(other.lo, libmp.fzero) and libmp.mpf_ge(other.hi, libmp.fzero):
            raise ValueError("division by an interval containing zero")
        pairs = [(a, b) for a in (self.lo, self.hi) for b in (other.lo, other.hi)]
        return Interval(rmin([libmp.mpf_div(a, b, PREC, FLOOR) for a, b in pairs]),
                        rmax([libmp.mpf_div(a, b, PREC, CEIL) for a, b in pairs])).rounded()

    def sqrt(self):
        if libmp.mpf_lt(self.lo, libmp.fzero):
            raise ValueError("square root of an interval reaching below zero")
        return Interval(libmp.mpf_sqrt(self.lo, PREC, FLOOR), libmp.mpf_sqrt(self.hi, PREC, CEIL)).rounded()

    def doubles(self):
        """The enclosure as doubles: lo rounded down, hi rounded up."""
        return round_down(raw_to_fraction(self.lo)), round_up(raw_to_fraction(self.hi))


# --------------------------------------------------------------------------
# The article's program, section 5, evaluated two ways: with exact values
# (mpf at 200 bits) and with enclosures (Interval). `num` makes a number of
# the chosen kind from a double; `sqrt` is the square root of that kind.


def article_program(scene, num, sqrt, x_E, y_E, z_E):
    """Returns (steps, branch, result): steps is a list of (key, value) with
    value a number or a 3-tuple; branch is 'miss', 'dark' or 'lit', or
    ('test', value) for the caller to decide delta's or D's sign."""
    x_S, y_S, z_S = (num(v) for v in scene["S"])
    r = num(scene["r"])
    x_L, y_L, z_L = (num(v) for v in scene["L"])
    I = num(scene["I"])
    x_E, y_E, z_E = num(x_E), num(y_E), num(z_E)

    steps = [("E", (x_E, y_E, z_E))]
    EE = x_E * x_E + y_E * y_E + z_E * z_E
    steps.append(("EE", EE))
    SS = x_S * x_S + y_S * y_S + z_S * z_S
    steps.append(("SS", SS))
    C = x_E * x_S + y_E * y_S + z_E * z_S
    steps.append(("C", C))
    delta = C * C - EE * (SS - r * r)
    steps.append(("delta", delta))
    yield steps, "delta", delta  # the caller decides: Δ ≤ 0 returns 1/2
    t = (C - sqrt(delta)) / EE
    steps.append(("t", t))
    x_P, y_P, z_P = t * x_E, t * y_E, t * z_E
    steps.append(("P", (x_P, y_P, z_P)))
    x_N, y_N, z_N = x_P - x_S, y_P - y_S, z_P - z_S
    steps.append(("N", (x_N, y_N, z_N)))
    x_K, y_K, z_K = x_L - x_P, y_L - y_P, z_L - z_P
    steps.append(("K", (x_K, y_K, z_K)))
    K = x_K * x_K + y_K * y_K + z_K * z_K
    steps.append(("KK", K))
    D = x_N * x_K + y_N * y_K + z_N * z_K
    steps.append(("D", D))
    yield steps, "D", D  # the caller decides: D ≤ 0 returns 0
    yield steps, "result", I * D / (r * sqrt(K))


def exact_num(f):
    return mpmath.mpf(f)  # exact: a double has 53 bits


def interval_num(f):
    return Interval.point(f)


def run_exact(scene, x_E, y_E, z_E):
    """Exact values (200 bits) of every quantity the program reaches, and
    the exact branch."""
    program = article_program(scene, exact_num, mpmath.sqrt, x_E, y_E, z_E)
    steps, _, delta = next(program)
    if delta <= 0:
        return list(steps), "miss", Fraction(scene["background"])
    steps, _, D = next(program)
    if D <= 0:
        return list(steps), "dark", Fraction(0)
    _, _, result = next(program)
    return list(steps), "lit", result


def run_double(scene, x_E, y_E, z_E):
    """The IEEE double program: values, branch and result."""
    program = article_program(scene, float, math.sqrt, x_E, y_E, z_E)
    steps, _, delta = next(program)
    if delta <= 0:
        return list(steps), "miss", scene["background"]
    steps, _, D = next(program)
    if D <= 0:
        return list(steps), "dark", 0.0
    _, _, result = next(program)
    return list(steps), "lit", result


def run_enclosure(scene, x_E, y_E, z_E):
    """Enclosures of every quantity the program can reach, the branch
    ('uncertain' if a test can go either way) and the test it is uncertain
    at, and the result's enclosure (None if uncertain)."""
    program = article_program(scene, interval_num, Interval.sqrt, x_E, y_E, z_E)
    steps, _, delta = next(program)
    lo, hi = delta.doubles()
    if hi <= 0:
        return list(steps), "miss", None, Interval.point(scene["background"])
    if lo <= 0:
        return list(steps), "uncertain", "delta", None
    steps, _, D = next(program)
    lo, hi = D.doubles()
    if hi <= 0:
        return list(steps), "dark", None, Interval.point(0.0)
    if lo <= 0:
        return list(steps), "uncertain", "D", None
    _, _, result = next(program)
    return list(steps), "lit", None, result


# --------------------------------------------------------------------------
# One pixel


def pane_point(scene, w, i, j):
    """The tracer's input: the pane formula in IEEE doubles."""
    y_E = -(2 * i + 1) / w + 1
    x_E = (2 * j + 1) / w - 1
    return x_E, y_E, scene["z_E"]


def mpf_fraction(value):
    if isinstance(value, Fraction):
        return value
    return raw_to_fraction(value._mpf_)


def component_record(exact_value, enclosure, double_value):
    exact = mpf_fraction(exact_value)
    lo, hi = enclosure.doubles()
    if not (Fraction(lo) <= exact <= Fraction(hi)):
        raise AssertionError("exact value outside its enclosure")
    if not (lo <= double_value <= hi):
        raise AssertionError("double value outside its enclosure")
    return decimal_text(exact), double_text(lo), double_text(hi), repr(double_value)


def value_record(key, exact_value, enclosure, double_value):
    record = {"key": key}
    if isinstance(enclosure, tuple):
        parts = [component_record(e, b, d) for e, b, d in zip(exact_value, enclosure, double_value)]
        record["exact"] = [p[0] for p in parts]
        record["lo"] = [p[1] for p in parts]
        record["hi"] = [p[2] for p in parts]
        record["double"] = [p[3] for p in parts]
    else:
        record["exact"], record["lo"], record["hi"], record["double"] = \
            component_record(exact_value, enclosure, double_value)
    return record


def pixel_record(scene, w, i, j, name_scene=False):
    x_E, y_E, z_E = pane_point(scene, w, i, j)
    exact_steps, exact_branch, exact_result = run_exact(scene, x_E, y_E, z_E)
    bound_steps, branch, uncertain_at, bound_result = run_enclosure(scene, x_E, y_E, z_E)
    double_steps, double_branch, double_result = run_double(scene, x_E, y_E, z_E)

    record = {"scene": scene["name"]} if name_scene else {}
    record.update({"w": w, "i": i, "j": j})
    record["pane_rational"] = [fraction_text(Fraction(2 * j + 1, w) - 1), fraction_text(-Fraction(2 * i + 1, w) + 1)]
    record["branch"] = branch
    if branch == "uncertain":
        record["uncertain_at"] = uncertain_at
        record["exact_branch"] = exact_branch
    elif branch != exact_branch or branch != double_branch:
        raise AssertionError("certain branch differs from the exact or the double branch")
    # A miss stops after delta, a dark pixel after D; an uncertain pixel
    # lists what exists on every path.
    steps = []
    for (key, exact_value), (key2, enclosure), (key3, double_value) in zip(exact_steps, bound_steps, double_steps):
        assert key == key2 == key3
        steps.append(value_record(key, exact_value, enclosure, double_value))
    record["steps"] = steps
    if bound_result is not None:
        record["result"] = value_record("I_P", exact_result, bound_result, double_result)
        del record["result"]["key"]
    return record


# --------------------------------------------------------------------------
# Choosing pixels. The selection uses a plain double evaluation of the
# program, only to find pixels near the silhouette (small delta) and near
# the terminator (small D); it is deterministic (ties broken by (i, j)).


def double_program(scene, w, i, j):
    """(delta, delta's term size, D, D's term size) in doubles; D None on a miss."""
    x_E, y_E, z_E = pane_point(scene, w, i, j)
    x_S, y_S, z_S = scene["S"]
    r = scene["r"]
    x_L, y_L, z_L = scene["L"]
    EE = x_E * x_E + y_E * y_E + z_E * z_E
    SS = x_S * x_S + y_S * y_S + z_S * z_S
    C = x_E * x_S + y_E * y_S + z_E * z_S
    delta = C * C - EE * (SS - r * r)
    delta_size = C * C
    if delta <= 0:
        return delta, delta_size, None, None
    t = (C - math.sqrt(delta)) / EE
    x_P, y_P, z_P = t * x_E, t * y_E, t * z_E
    x_N, y_N, z_N = x_P - x_S, y_P - y_S, z_P - z_S
    x_K, y_K, z_K = x_L - x_P, y_L - y_P, z_L - z_P
    D = x_N * x_K + y_N * y_K + z_N * z_K
    D_size = abs(x_N * x_K) + abs(y_N * y_K) + abs(z_N * z_K)
    return delta, delta_size, D, D_size


def scan(scene, w, rows):
    """Per pixel of the given rows: (i, j, delta/size, D/size or None)."""
    out = []
    for i in rows:
        for j in range(w):
            delta, delta_size, D, D_size = double_program(scene, w, i, j)
            out.append((i, j, delta / delta_size, None if D is None else D / D_size))
    return out


def near_edges(table):
    """Pixels beside a sign change of delta or D along a row or a column."""
    by_pos = {(i, j): (d, k) for i, j, d, k in table}
    chosen = set()
    for (i, j), (d, k) in by_pos.items():
        for ni, nj in ((i, j + 1), (i + 1, j)):
            if (ni, nj) not in by_pos:
                continue
            d2, k2 = by_pos[(ni, nj)]
            if (d > 0) != (d2 > 0):
                chosen.update({(i, j), (ni, nj)})
            if k is not None and k2 is not None and (k > 0) != (k2 > 0):
                chosen.update({(i, j), (ni, nj)})
    return chosen


def smallest(table, index, count, positive):
    """The `count` pixels with the smallest |value| of one sign, at most two
    per value (delta is the same at the eight pixels symmetric in x_E, y_E)."""
    candidates = sorted((abs(row[index]), row[0], row[1]) for row in table
                        if row[index] is not None and (row[index] > 0) == positive)
    chosen, seen = [], {}
    for value, i, j in candidates:
        if len(chosen) == count:
            break
        if seen.get(value, 0) < 2:
            seen[value] = seen.get(value, 0) + 1
            chosen.append((i, j))
    return set(chosen)


def row_edges(scene, w, i):
    """The pixels of row i beside a sign change of delta or of D, found by
    bisection (delta falls as |x_E| grows; D is scanned every 8 columns
    over the hit span, then bisected), as rows of `scan`'s table."""
    def values(j):
        delta, delta_size, D, D_size = double_program(scene, w, i, j)
        return (i, j, delta / delta_size, None if D is None else D / D_size)

    middle = (w - 1) // 2
    if values(middle)[2] <= 0:
        return []
    lo, hi = 0, middle  # delta(lo) <= 0 < delta(hi), if the row's end misses
    if values(lo)[2] > 0:
        return []
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if values(mid)[2] > 0:
            hi = mid
        else:
            lo = mid
    first_hit, last_hit = hi, w - 1 - hi  # the row is symmetric in x_E
    edges = {lo, hi, w - 1 - hi, w - 1 - lo}

    def lit(j):
        return values(j)[3] > 0

    columns = list(range(first_hit, last_hit, 8)) + [last_hit]
    for a, b in zip(columns, columns[1:]):
        if lit(a) != lit(b):
            while b - a > 1:
                mid = (a + b) // 2
                if lit(mid) == lit(a):
                    a = mid
                else:
                    b = mid
            edges |= {a, b}
    return [values(j) for j in sorted(edges)]


def pixel_set():
    pixels = [(1, 0, 0)]
    pixels += [(8, i, j) for i in range(8) for j in range(8)]
    pixels += [(7, i, j) for i in range(7) for j in range(7)]

    # w = 512: a coarse grid, the pixels closest to the silhouette and the
    # terminator over the whole image (both sides of each test), and the
    # pixels beside the silhouette and the terminator on every 32nd row.
    w = 512
    table = scan(ARTICLE_SCENE, w, range(w))
    chosen = {(i, j) for i in range(32, w, 64) for j in range(32, w, 64)}
    chosen |= {(i, j) for i in (255, 256) for j in (255, 256)}  # the centre
    for index in (2, 3):
        for positive in (True, False):
            chosen |= smallest(table, index, 32, positive)
    rows = set(range(16, w, 32))
    edges = near_edges([row for row in table if row[0] in rows or row[0] + 1 in rows])
    chosen |= {(i, j) for i, j in edges if i in rows}
    pixels += [(w, i, j) for i, j in sorted(chosen)]

    # w = 2049 (odd: the middle row and column are exactly 0): the centre,
    # the corners, the pixels beside the silhouette and the terminator on
    # three rows, and over all rows the pixels closest to either test.
    w = 2049
    chosen = {(1024, 1024), (0, 0), (2048, 2048)}
    candidates = []
    for i in range(w):
        candidates += row_edges(ARTICLE_SCENE, w, i)
    for i in (600, 1024, 1400):
        chosen |= {(ci, cj) for ci, cj, _, _ in candidates if ci == i}
    for index in (2, 3):
        for positive in (True, False):
            chosen |= smallest(candidates, index, 16, positive)
    pixels += [(w, i, j) for i, j in sorted(chosen)]
    return pixels


# --------------------------------------------------------------------------
# Scenes other than the article's (--scenes): off-axis centres (x_S, y_S,
# z_S distinct and non-zero), I != 1, backgrounds != 1/2, z_E != 2, and
# scenes where delta or D is exactly 0 in double at some pixel. They live in
# tests/reference/scenes/ as scene files, which the C++ tests read with
# promyk's own parser; Python's json reads each number as the nearest double,
# as that parser does (the tests check that both hold the same doubles).

SCENE_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "scenes")

SCENE_FILES = [
    "off_axis_far.json",      # z_E = 3, I = 3, background 0.2
    "off_axis_near.json",     # z_E = 1.5, I = 0.75, background 0.75
    "tangent_axis.json",      # w = 1 and w = 3: E = (0, 0, 2) touches S = (1, 0, 4), r = 1: delta = 0
    "tangent_off_axis.json",  # w = 2, pixel (0, 1): E = (0.5, 0.5, 2) touches S = (3, 3, 7.5), r = 1.5
    "dark_exact.json",        # w = 1 and w = 3: P = (0, 0, 3), N = (0, 0, -1), K = (2, 1, 0): D = 0
]


def load_scene(file_name):
    with open(os.path.join(SCENE_DIR, file_name), encoding="utf-8") as f:
        doc = json.load(f)
    (sphere,), (light,) = doc["spheres"], doc["lights"]
    return {
        "name": doc["name"],
        "file": file_name,
        "z_E": float(doc["z_E"]),
        "S": tuple(float(v) for v in sphere["S"]),
        "r": float(sphere["r"]),
        "L": tuple(float(v) for v in light["L"]),
        "I": float(light["I"]),
        "background": float(doc["background"]),
    }


def scenes_pixel_set(scenes):
    """(scene, w, i, j) for every pixel of a few small panes of each scene,
    and for the off-axis scenes the pixels of w = 64 closest to either test."""
    pixels = []
    for s in scenes:
        if s["name"].startswith("off_axis"):
            sizes = (7, 8) if s["name"] == "off_axis_far" else (8,)
            chosen = []
            for w in sizes:
                chosen += [(w, i, j) for i in range(w) for j in range(w)]
            table = scan(s, 64, range(64))
            near = set()
            for index in (2, 3):
                for positive in (True, False):
                    near |= smallest(table, index, 4, positive)
            chosen += [(64, i, j) for i, j in sorted(near)]
        elif s["name"] == "tangent_off_axis":
            chosen = [(w, i, j) for w in (2, 3) for i in range(w) for j in range(w)]
        else:
            chosen = [(1, 0, 0)] + [(3, i, j) for i in range(3) for j in range(3)]
        pixels += [(s, w, i, j) for w, i, j in chosen]
    return pixels


# --------------------------------------------------------------------------
# Output


def scene_header(s):
    record = {"name": s["name"]}
    if "file" in s:
        record["file"] = s["file"]
    record.update({
        "z_E": double_text(s["z_E"]),
        "S": [double_text(v) for v in s["S"]],
        "r": double_text(s["r"]),
        "L": [double_text(v) for v in s["L"]],
        "I": double_text(s["I"]),
        "background": double_text(s["background"]),
        "note": "each number is taken as the exact value of the IEEE double nearest its decimal text",
    })
    return record


def header(scenes):
    start = {
        "format": "promyk article reference",
        "format_version": 1,
        "generator": "tests/reference/make_reference.py (python3 with mpmath); regenerate with: "
                     "python3 tests/reference/make_reference.py tests/reference/article_reference.json",
        "precision_bits": PREC,
        "scene": scene_header(ARTICLE_SCENE),
    }
    if scenes is not None:
        start = {
            "format": "promyk scenes reference",
            "format_version": 1,
            "generator": "tests/reference/make_reference.py (python3 with mpmath); regenerate with: "
                         "python3 tests/reference/make_reference.py --scenes tests/reference/scenes_reference.json",
            "precision_bits": PREC,
            "scenes": [scene_header(s) for s in scenes],
            "scene_files": "tests/reference/scenes/FILE, read by promyk's parse_scene in the tests",
        }
    return dict(start, **{
        "pane": "E = (x_E, y_E, z_E) with y_E = -(2i+1)/w + 1 and x_E = (2j+1)/w - 1 computed in IEEE doubles "
                "(the tracer's input); pane_rational holds the exact values [x_E, y_E]",
        "exact": "the article's formula at 200 bits from the exact double inputs, %d significant digits"
                 % EXACT_DIGITS,
        "enclosure": "[lo, hi]: every double an IEEE program performing the article's operations in the "
                     "article's order (each + - * / sqrt correctly rounded to nearest, no FMA) can produce; "
                     "200-bit intervals, each operation widened by 2^-53 relative (plus 2^-1075 near zero), "
                     "endpoints rounded outward to doubles",
        "double": "the article's program in IEEE doubles without FMA (Python floats), Python repr",
        "branch": "miss (delta <= 0), dark (D <= 0), lit, or uncertain (the enclosure of delta or D straddles "
                  "the test; steps stop at that test and there is no result)",
        "keys": KEYS,
    })


def main(argv):
    scenes_mode = len(argv) == 3 and argv[1] == "--scenes"
    if len(argv) != 2 and not scenes_mode:
        sys.stderr.write("usage: make_reference.py [--scenes] OUTPUT.json\n")
        return 2
    if argv[-1].startswith("-"):
        # An option misread as the output would write a file named like it
        # (a 257 KB file '--help' was committed once).
        sys.stderr.write(f"{argv[0]}: the output path must not begin with '-': {argv[-1]}\n")
        return 2
    if scenes_mode:
        scenes = [load_scene(name) for name in SCENE_FILES]
        pixels = scenes_pixel_set(scenes)
        records = [json.dumps(pixel_record(s, w, i, j, name_scene=True), separators=(",", ":"))
                   for s, w, i, j in pixels]
    else:
        scenes = None
        pixels = pixel_set()
        records = [json.dumps(pixel_record(ARTICLE_SCENE, w, i, j), separators=(",", ":")) for w, i, j in pixels]
    lines = ["{"]
    for key, value in header(scenes).items():
        lines.append(" %s: %s," % (json.dumps(key), json.dumps(value, ensure_ascii=True)))
    lines.append(' "pixel_count": %d,' % len(pixels))
    lines.append(' "pixels": [')
    lines.append(",\n".join(records))
    lines.append(" ]")
    lines.append("}")
    text = "\n".join(lines) + "\n"
    with open(argv[-1], "w", encoding="ascii", newline="\n") as out:
        out.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
