#!/usr/bin/env python3
"""The hard cases: exact values, and what each sphere formula reaches in each
real type.

Usage: python3 make_hard_cases.py OUTPUT.json             (the reference)
       python3 make_hard_cases.py --catalogue OUTPUT.json (tests/data/hard_cases.json)

For every case (a scene written inline, one pixel) and every real type the
engine computes in (float, double, long double, quad: significands of 24, 53,
64 and 113 bits) this script computes, without promyk's code:

- the inputs as the engine holds them in that type: each scene number (a
  double, as promyk's loader reads it) rounded to nearest in the type (exact
  for long double and quad), and the pane point x_E = (2j+1)/w - 1,
  y_E = -(2i+1)/w + 1 evaluated in the type, one rounding per operation, as
  render/pane.hpp does;
- `exact`: the engine's computation (docs/conventions.md, "The engine's conventions (the
  extensions)", with the article's formula for the sphere) carried out
  EXACTLY on those inputs: every + - * is exact (4096-bit mpmath arithmetic,
  more than the inputs' products and sums can need: the script checks delta
  against Fractions), / and sqrt are correct to 4096 bits. A test between
  two values that agree to 3500 bits is a tie (it can only come from an
  exact equality, such as 2D = |K|^2 for a light on the sphere's surface),
  decided as exact equality decides it;
- `formulas`: for each sphere formula (article, stable, fma, geometric) what
  a program following the formula computes when every operation (+ - * /
  sqrt, and fma) is correctly rounded to nearest (ties to even) in the type:
  mpmath with the type's precision and one rounding after EVERY operation.
  mpmath has no exponent limits, so overflow and underflow are NOT modelled:
  every rounded value is checked to lie in the type's normal range (or be
  0), and the script stops if a case ever leaves it. Each simulated value
  carries a running error bound (README in this folder): a rigorous bound
  on its distance from the exact value, derived operation by operation;
- the errors of the simulated primary t and of the result against `exact`:
  in ulps of the type (of the exact value), as relative error, and as
  digits correct, -log10(relative error), at most the type's own digits.

Planes, shading and shadow rays are the engine's in every formula: only the
primary ray's sphere test changes. Every case uses one channel (grey), the
default material and no Phong, so the result is the sum over the lights of
(I*D)/(r*sqrt(|K|^2)).

The output is deterministic (mpmath's raw libmp arithmetic with explicit
precision and rounding, numbers formatted by this script from exact
rationals), the same bytes with mpmath 1.2.1 and 1.3.0.
"""

import json
import math
import os
import struct
import sys
from fractions import Fraction

sys.dont_write_bytecode = True  # no __pycache__ in the source tree (the CTest check runs this script)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_reference import decimal_text, libmp, raw_to_fraction  # noqa: E402

EXACT_PREC = 4096
TIE_BITS = 3500
BOUND_PREC = 80
UP = libmp.round_ceiling
DOWN = libmp.round_floor
NEAREST = libmp.round_nearest

# name, significand bits, emax, emin (normal range [2^emin, 2^(emax+1)))
TYPES = [("float", 24, 127, -126), ("double", 53, 1023, -1022),
         ("long-double", 64, 16383, -16382), ("quad", 113, 16383, -16382)]
TYPE_DIGITS = {name: p * math.log10(2) for name, p, _, _ in TYPES}
ROUND_TRIP_DIGITS = {"float": 9, "double": 17, "long-double": 21, "quad": 36}
FORMULAS = ["article", "stable", "fma", "geometric"]
EXACT_DIGITS = 40

ZERO = libmp.fzero
ONE = libmp.fone


def mpf(x):
    if isinstance(x, int):
        return libmp.from_int(x)
    if isinstance(x, float):
        return libmp.from_float(x)
    if isinstance(x, Fraction):
        return libmp.from_rational(x.numerator, x.denominator, EXACT_PREC, NEAREST)
    return x


def fr(raw):
    return raw_to_fraction(raw)


# --------------------------------------------------------------------------
# Two kinds of numbers: Exact (4096 bits) and Rounded (the type's precision,
# with a running error bound).


class Tie(Exception):
    pass


class Ctx:
    """An arithmetic: prec is the significand's bits (None: exact)."""

    def __init__(self, name, prec, emax=None, emin=None):
        self.name, self.prec, self.emax, self.emin = name, prec, emax, emin
        self.ties = []
        self.decisions = []
        if prec is not None:
            self.u = libmp.from_man_exp(1, -prec)  # unit roundoff 2^-p

    def num(self, raw, err=ZERO):
        return Num(self, mpf(raw), err)

    def rnd(self, raw):
        if self.prec is None:
            return libmp.mpf_pos(raw, EXACT_PREC, NEAREST)
        v = libmp.mpf_pos(raw, self.prec, NEAREST)
        if v != ZERO:
            _, man, exp, bc = v
            top = exp + bc - 1  # 2^top <= |v| < 2^(top+1)
            if top > self.emax or top < self.emin:
                raise OverflowError("%s: %s leaves the type's normal range (not modelled)"
                                    % (self.name, decimal_text(fr(v), 5)))
        return v

    # The comparisons the engine makes; the exact context sees a tie when
    # the two values agree to TIE_BITS bits (only an exact equality does).
    def cmp(self, a, b, what):
        d = libmp.mpf_sub(a.v, b.v)  # exact
        if d == ZERO:
            c = 0
            if self.prec is None:
                self.ties.append(what)
        else:
            c = -1 if d[0] else 1
            if self.prec is None:
                scale = max(libmp.mpf_abs(a.v), libmp.mpf_abs(b.v), key=lambda r: fr(r))
                if libmp.mpf_lt(libmp.mpf_abs(d), libmp.mpf_mul(scale, libmp.from_man_exp(1, -TIE_BITS))):
                    self.ties.append(what)
                    c = 0
        return c


def addb(*xs):
    s = ZERO
    for x in xs:
        s = libmp.mpf_add(s, x, BOUND_PREC, UP)
    return s


def mulb(a, b):
    return libmp.mpf_mul(libmp.mpf_abs(a), libmp.mpf_abs(b), BOUND_PREC, UP)


INF = libmp.finf


class Num:
    def __init__(self, ctx, v, e=ZERO):
        self.ctx, self.v, self.e = ctx, v, e

    def _round(self, exact, e_in):
        v = self.ctx.rnd(exact)
        if self.ctx.prec is None:
            return Num(self.ctx, v)
        # one rounding: u|v|, or nothing when the operation was exact
        e = e_in if v == exact else addb(e_in, mulb(self.ctx.u, v))
        return Num(self.ctx, v, e)

    def _coerce(self, o):
        return o if isinstance(o, Num) else self.ctx.num(o)

    def __add__(self, o):
        o = self._coerce(o)
        return self._round(libmp.mpf_add(self.v, o.v), addb(self.e, o.e))

    def __sub__(self, o):
        o = self._coerce(o)
        return self._round(libmp.mpf_sub(self.v, o.v), addb(self.e, o.e))

    def __mul__(self, o):
        o = self._coerce(o)
        return self._round(libmp.mpf_mul(self.v, o.v), addb(mulb(self.v, o.e), mulb(o.v, self.e), mulb(self.e, o.e)))

    def __truediv__(self, o):
        o = self._coerce(o)
        if self.ctx.prec is None:
            return Num(self.ctx, libmp.mpf_div(self.v, o.v, EXACT_PREC, NEAREST))
        v = self.ctx.rnd(libmp.mpf_div(self.v, o.v, self.ctx.prec, NEAREST))  # correctly rounded
        if libmp.mpf_mul(v, o.v) == self.v:
            return Num(self.ctx, v, self._quotient_error(o, v, exact=True))
        return Num(self.ctx, v, self._quotient_error(o, v, exact=False))

    def _quotient_error(self, o, v, exact):
        if self.e == ZERO and o.e == ZERO:
            return ZERO if exact else mulb(self.ctx.u, v)
        # |a^/b^ - a/b| <= (e_a + |a^/b^| e_b) / (|b^| - e_b), for |b^| > e_b
        den = libmp.mpf_sub(libmp.mpf_abs(o.v), o.e, BOUND_PREC, DOWN)
        if not libmp.mpf_gt(den, ZERO):
            return INF
        q = libmp.mpf_div(libmp.mpf_abs(self.v), libmp.mpf_abs(o.v), BOUND_PREC, UP)
        e = libmp.mpf_div(addb(self.e, mulb(q, o.e)), den, BOUND_PREC, UP)
        return e if exact else addb(e, mulb(self.ctx.u, v))

    def __neg__(self):
        return Num(self.ctx, libmp.mpf_neg(self.v), self.e)

    def sqrt(self):
        if self.ctx.prec is None:
            return Num(self.ctx, libmp.mpf_sqrt(self.v, EXACT_PREC, NEAREST))
        v = self.ctx.rnd(libmp.mpf_sqrt(self.v, self.ctx.prec, NEAREST))
        if self.e == ZERO and libmp.mpf_mul(v, v) == self.v:
            return Num(self.ctx, v, ZERO)
        # |sqrt(a^) - sqrt(a)| <= min(sqrt(e_a), e_a / sqrt(a^))
        e = libmp.mpf_sqrt(self.e, BOUND_PREC, UP)
        if libmp.mpf_gt(self.v, ZERO):
            e2 = libmp.mpf_div(self.e, libmp.mpf_sqrt(self.v, BOUND_PREC, DOWN), BOUND_PREC, UP)
            if libmp.mpf_lt(e2, e):
                e = e2
        return Num(self.ctx, v, addb(e, mulb(self.ctx.u, v)))

    def fma(self, b, c):
        """self*b + c with one rounding."""
        b, c = self._coerce(b), self._coerce(c)
        exact = libmp.mpf_add(libmp.mpf_mul(self.v, b.v), c.v)
        return self._round(exact, addb(mulb(self.v, b.e), mulb(b.v, self.e), mulb(self.e, b.e), c.e))

    def sign(self):
        return 0 if self.v == ZERO else (-1 if self.v[0] else 1)

    # comparisons with a Num or a number
    def _c(self, o, what):
        return self.ctx.cmp(self, self._coerce(o), what)

    def gt(self, o, what):
        r = self._c(o, what) > 0
        self.ctx.decisions.append((what, r))
        return r

    def le(self, o, what):
        return not self.gt(o, what)

    def lt(self, o, what):
        r = self._c(o, what) < 0
        self.ctx.decisions.append((what, r))
        return r

    def eq(self, o, what):
        r = self._c(o, what) == 0
        self.ctx.decisions.append((what, r))
        return r


def vdot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def vsub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def vscale(t, a):
    return (t * a[0], t * a[1], t * a[2])


def vdiv(a, t):
    return (a[0] / t, a[1] / t, a[2] / t)


def vneg(a):
    return (-a[0], -a[1], -a[2])


# --------------------------------------------------------------------------
# Inputs in a type


def round_to(raw, prec):
    return libmp.mpf_pos(raw, prec, NEAREST)


def type_inputs(scene, w, i, j, tname, prec):
    """The scene's doubles rounded to the type, and the pane point computed in
    it (render/pane.hpp: -(2i+1)/w + 1 and (2j+1)/w - 1)."""
    def r(x):
        return round_to(mpf(float(x)), prec)

    def rv(v):
        return tuple(r(c) for c in v)
    q1 = round_to(libmp.mpf_div(libmp.from_int(-(2 * i + 1)), libmp.from_int(w), prec, NEAREST), prec)
    y = libmp.mpf_add(q1, ONE, prec, NEAREST)
    q2 = libmp.mpf_div(libmp.from_int(2 * j + 1), libmp.from_int(w), prec, NEAREST)
    x = libmp.mpf_add(q2, libmp.mpf_neg(ONE), prec, NEAREST)
    return {
        "E": (x, y, r(scene["z_E"])),
        "spheres": [{"S": rv(s["S"]), "r": r(s["r"])} for s in scene.get("spheres", [])],
        "planes": [{"Q": rv(p["Q"]), "n": rv(p["n"])} for p in scene.get("planes", [])],
        "lights": [{"L": rv(l["L"]), "I": r(l.get("I", 1))} for l in scene["lights"]],
        "shadows": bool(scene.get("shadows", False)),
    }


def article_stage(scene):
    """render/stages.cpp: the article's kernel (near root only) for one sphere,
    no plane, the eye outside (|S|^2 - r^2 > 0 in double), one light, no
    shadows (the hard cases use no materials or colours)."""
    spheres, planes = scene.get("spheres", []), scene.get("planes", [])
    if len(spheres) != 1 or planes or len(scene["lights"]) != 1 or scene.get("shadows", False):
        return False
    S, r = [float(c) for c in spheres[0]["S"]], float(spheres[0]["r"])
    return (S[0] * S[0] + S[1] * S[1] + S[2] * S[2]) - r * r > 0


# --------------------------------------------------------------------------
# The sphere formulas. Each returns (t, inside, log) for a ray from the eye
# through E, or (None, None, log) for no hit in front of the eye; log holds
# the engine's trace keys (delta, t, t_far) with their values.


def sphere_article(ctx, E, S, r, article_kernel):
    log = []
    EE, SS, C = vdot(E, E), vdot(S, S), vdot(E, S)
    delta = C * C - EE * (SS - r * r)
    log.append(("delta", delta))
    if delta.le(0, "delta > 0"):
        return None, None, log, delta
    root = delta.sqrt()
    t = (C - root) / EE
    log.append(("t", t))
    if t.gt(0, "t > 0"):
        return t, False, log, delta
    if article_kernel:
        return None, None, log, delta  # behind the eye: the article's kernel takes no far root
    t_far = (C + root) / EE
    log.append(("t_far", t_far))
    if t_far.gt(0, "t_far > 0"):
        return t_far, True, log, delta
    return None, None, log, delta


def nearest_root_ahead(roots):
    """geometry/sphere.hpp's nearest_root_ahead: of two roots (either order)
    the nearer if it is > 0, else the farther if it is > 0 (returned as the
    far root: the eye inside), else none. The engine's stable, fma and
    geometric formulas choose so in either kernel (render/tracer.hpp)."""
    a, b = roots
    near, far = (a, b) if a.lt(b, "root order") else (b, a)
    if near.gt(0, "t > 0"):
        return near, False
    if far.gt(0, "t_far > 0"):
        return far, True
    return None, None


# The other formulas follow the engine's operation order exactly
# (src/geometry/sphere_stable.hpp, sphere_fma.hpp, sphere_geometric.hpp) and
# log the scalar values the engine records under the same keys.


def coefficients(E, S, r):
    """sphere_coefficients: EE, SS, C as the article's, c_0 = SS - r*r."""
    EE, SS, C = vdot(E, E), vdot(S, S), vdot(E, S)
    return EE, SS, C, SS - r * r


def cancellation_free_roots(C, root_term, c_0, EE, log):
    q = C + root_term if C.sign() >= 0 else C - root_term
    log.append(("q", q))
    t_q = q / EE
    log.append(("t_q", t_q))
    t_c = c_0 / q
    log.append(("t_c", t_c))
    return nearest_root_ahead((t_q, t_c))


def sphere_stable(ctx, E, S, r, article_kernel):
    log = []
    EE, SS, C, c_0 = coefficients(E, S, r)
    delta = C * C - EE * c_0
    log.append(("delta", delta))
    if delta.le(0, "delta > 0"):
        return None, None, log, delta
    t, inside = cancellation_free_roots(C, delta.sqrt(), c_0, EE, log)
    return t, inside, log, delta


def sphere_fma(ctx, E, S, r, article_kernel):
    log = []
    EE, SS, C, c_0 = coefficients(E, S, r)
    w = EE * c_0
    log.append(("w_fma", w))
    e = (-EE).fma(c_0, w)
    log.append(("e_fma", e))
    delta = C.fma(C, -w) + e
    log.append(("delta_fma", delta))
    if delta.le(0, "delta > 0"):
        return None, None, log, delta
    root = delta.sqrt()
    t = (C - root) / EE
    log.append(("t", t))
    t_far = (C + root) / EE
    log.append(("t_far", t_far))
    t, inside = nearest_root_ahead((t, t_far))
    return t, inside, log, delta


def sphere_geometric(ctx, E, S, r, article_kernel):
    log = []
    EE, SS, C, c_0 = coefficients(E, S, r)
    t_mid = C / EE
    log.append(("t_mid", t_mid))
    l = vsub(vscale(t_mid, E), S)
    ll = vdot(l, l)
    log.append(("ll", ll))
    delta = r * r - ll
    log.append(("delta_g", delta))
    if delta.le(0, "delta > 0"):
        return None, None, log, delta
    t, inside = cancellation_free_roots(C, (EE * delta).sqrt(), c_0, EE, log)
    return t, inside, log, delta


SPHERE = {"article": sphere_article, "stable": sphere_stable, "fma": sphere_fma, "geometric": sphere_geometric}


# --------------------------------------------------------------------------
# One pixel, the conventions of docs/conventions.md


def sphere_blocks(P, K, KK, S, r, log):
    SP = vsub(S, P)
    b = vdot(K, SP)
    c = vdot(SP, SP) - r * r
    delta_s = b * b - KK * c
    log.append(("delta_s", delta_s))
    if delta_s.le(0, "delta_s > 0"):
        return False, None
    q = delta_s.sqrt()
    s1 = (b - q) / KK
    s2 = (b + q) / KK
    log.append(("s_1", s1))
    log.append(("s_2", s2))
    return (s1.gt(0, "s_1 > 0") and s1.lt(1, "s_1 < 1")) or (s2.gt(0, "s_2 > 0") and s2.lt(1, "s_2 < 1")), (s1, s2)


def trace(ctx, inputs, formula, article_kernel, naive_own=False):
    """Returns a dict: branch, hit, t, P, N, result, log (primary and shading
    keys), deltas (the hit sphere's discriminant)."""
    num = ctx.num
    E = tuple(num(c) for c in inputs["E"])
    spheres = [{"S": tuple(num(c) for c in s["S"]), "r": num(s["r"])} for s in inputs["spheres"]]
    planes = []
    for p in inputs["planes"]:
        n = tuple(num(c) for c in p["n"])
        n_hat = vdiv(n, vdot(n, n).sqrt())
        planes.append({"n_hat": n_hat, "NQ": vdot(n_hat, tuple(num(c) for c in p["Q"]))})
    lights = [{"L": tuple(num(c) for c in l["L"]), "I": num(l["I"])} for l in inputs["lights"]]
    log = []
    out = {"log": log}
    best = None  # (t, kind, index, inside/NE)
    sphere_deltas = []
    for k, s in enumerate(spheres):
        t, inside, slog, delta = SPHERE[formula](ctx, E, s["S"], s["r"], article_kernel)
        sphere_deltas.append(delta)
        log.extend(("sphere %d %s" % (k, key), v) for key, v in slog)
        if t is not None and (best is None or t.lt(best[0], "nearest")):
            best = (t, 1, k, inside)
    for k, p in enumerate(planes):
        NE = vdot(p["n_hat"], E)
        log.append(("plane %d NE" % k, NE))
        if NE.eq(0, "NE = 0"):
            continue
        t = p["NQ"] / NE
        log.append(("plane %d t_plane" % k, t))
        if t.gt(0, "t_plane > 0") and (best is None or t.lt(best[0], "nearest")):
            best = (t, 2, k, NE)
    out["sphere_deltas"] = sphere_deltas
    if best is None:
        out.update(branch="miss", hit="", result=None)
        return out
    t, kind, index, extra = best
    if not article_kernel or formula != "article":
        log.append(("t_hit", t))  # the article's kernel has no nearest-hit step for its own formula
    P = vscale(t, E)
    if kind == 1:
        N = vsub(P, spheres[index]["S"])
        r = spheres[index]["r"]
        # The article's kernel takes the normal P - S whatever the root
        # (render/tracer.hpp: an eye outside, a far root only by rounding).
        inside = extra and not article_kernel
        if inside:
            N = vneg(N)
    else:
        N = planes[index]["n_hat"]
        r = num(1)
        inside = False
        if extra.gt(0, "NE > 0"):
            N = vneg(N)
    out.update(hit="%s %d" % ("sphere" if kind == 1 else "plane", index), t=t, P=P, N=N, inside=inside)
    I_P = num(0)
    faces_any = lit_any = False
    naive = []
    for l, light in enumerate(lights):
        K = vsub(light["L"], P)
        KK = vdot(K, K)
        D = vdot(N, K)
        log.append(("light %d D" % l, D))
        faces = D.gt(0, "D > 0")
        blocked = False
        if inputs["shadows"] and faces:
            for k, s in enumerate(spheres):
                if kind == 1 and k == index:
                    if naive_own:  # what a numerical test against its own surface would find
                        b, s1 = sphere_blocks(P, K, KK, s["S"], s["r"], [])
                        naive.append((b, s1))
                    two_D = D * 2
                    log.append(("light %d 2D" % l, two_D))
                    log.append(("light %d KK" % l, KK))
                    b = inside and two_D.lt(KK, "2D < KK")
                else:
                    b, _ = sphere_blocks(P, K, KK, s["S"], s["r"], [])
                blocked = blocked or b
            for k, p in enumerate(planes):
                if kind == 2 and k == index:
                    continue
                NK = vdot(p["n_hat"], K)
                if NK.eq(0, "NK = 0"):
                    continue
                s_ = (p["NQ"] - vdot(p["n_hat"], P)) / NK
                blocked = blocked or (s_.gt(0, "s > 0") and s_.lt(1, "s < 1"))
        reaches = faces and not blocked
        faces_any = faces_any or faces
        lit_any = lit_any or reaches
        if reaches:
            diffuse = light["I"] * D / (r * KK.sqrt())
            I_P = I_P + diffuse  # 0 + x and the factors 1 of the default material are exact
    out["naive_own"] = naive
    out["branch"] = "lit" if lit_any else "shadowed" if faces_any else "dark"
    out["result"] = I_P
    return out


# --------------------------------------------------------------------------
# The cases


def tangent_scene(name, w, i, j, alpha, s, quad_vec, z_E_num=None, light=(1.5, 1, 1)):
    """A sphere tangent to the ray through pane point (i, j) of w: S = alpha*E
    + s*p with p . E = 0 and |p| = r = s*m exactly (p from the Pythagorean
    quadruple quad_vec = (a, b, c, m), a^2 + b^2 + c^2 = m^2, c a power of
    two; the signs of a and b are taken opposite to x's and y's). z_E is
    chosen so that p . E = 0: z_E = -(a x + b y)/c > 0. Every input is checked
    to be an exact double, so delta = 0 holds exactly in rational arithmetic
    of the double inputs."""
    a, b, c, m = quad_vec
    x = Fraction(2 * j + 1, w) - 1
    y = 1 - Fraction(2 * i + 1, w)
    a = -a if x > 0 else a
    b = -b if y > 0 else b
    z = -(a * x + b * y) / c
    assert z > 0
    S = [alpha * x + s * a, alpha * y + s * b, alpha * z + s * c]
    for v in S + [z, s * m, x, y]:
        assert Fraction(float(v)) == v, (name, v)
    E = (x, y, z)
    Sv = tuple(S)
    r = s * m
    EE = sum(e * e for e in E)
    C = sum(e * t for e, t in zip(E, Sv))
    assert C * C - EE * (sum(t * t for t in Sv) - r * r) == 0
    return {"name": name, "z_E": float(z), "background": 0.5, "shadows": False,
            "spheres": [{"S": [float(v) for v in S], "r": float(r)}], "planes": [],
            "lights": [{"L": list(light), "I": 1}]}


def trunc_bits(value, bits):
    """value (a Fraction) truncated to `bits` significant bits."""
    e = math.floor(math.log2(value))
    scale = Fraction(2) ** (bits - 1 - e)
    return Fraction(math.floor(value * scale)) / scale


def far_scene(z):
    return {"name": "far sphere at %g" % z, "z_E": 2, "background": 0.5, "shadows": False,
            "spheres": [{"S": [0, 0, z], "r": 1}], "planes": [], "lights": [{"L": [1.5, 1, 1], "I": 1}]}


def scene(name, spheres, lights, planes=(), z_E=2, shadows=False):
    return {"name": name, "z_E": z_E, "background": 0.5, "shadows": shadows,
            "spheres": [{"S": list(S), "r": r} for S, r in spheres],
            "planes": [{"Q": list(Q), "n": list(n)} for Q, n in planes],
            "lights": [{"L": list(L), "I": I} for L, I in lights]}


def cases():
    out = []

    def add(id_, why, sc, w, i, j, **extra):
        out.append(dict({"id": id_, "why": why, "scene": sc, "pixel": {"w": w, "i": i, "j": j}}, **extra))

    for k, z in enumerate([1e4, 1e5, 1e6, 1e7, 1e8]):
        add("far_1e%d" % (k + 4),
            "A unit sphere on the axis at distance 10^%d: delta = C^2 - |E|^2(|S|^2 - r^2) = 4 is the difference "
            "of two numbers near 4*10^%d, so the article's formula loses %d digits to cancellation (float keeps "
            "about 7, double about 16)." % (k + 4, 2 * (k + 4), 2 * (k + 4)),
            far_scene(z), 1, 0, 0)
    add("huge_near_1e6",
        "A sphere of radius 10^6 whose surface is 1 from the pane: |S|^2 - r^2 = 6000009 is the difference of "
        "two numbers near 10^12, which float holds to about 2^16: float loses most of c, double keeps it exactly.",
        scene("huge sphere 1e6", [((0, 0, 1000003), 1e6)], [((1.5, 1, 1), 1)]), 8, 3, 4)
    add("huge_near_1e9",
        "A sphere of radius 10^9 whose surface is 1 from the pane: in double |S|^2 ~ 10^18 is held to 128, so "
        "|S|^2 - r^2 = 6*10^9 + 9 keeps about 8 digits; in float 10^9 + 3 rounds to 10^9 and the eye lands on "
        "the sphere's surface (the article's kernel then finds t = 0: behind the eye).",
        scene("huge sphere 1e9", [((0, 0, 1000000003), 1e9)], [((1.5, 1, 1), 1)]), 8, 3, 4)
    add("tangent_axis_exact",
        "S = (r, 0, z) with r = 1, z = 10: the axis ray touches the sphere and every quantity is exact in every "
        "type, so delta = 0 exactly: a certain miss (the control for the tangent cases).",
        scene("tangent on the axis, exact", [((1, 0, 10), 1)], [((1.5, 1, 1), 1)]), 1, 0, 0)
    add("tangent_axis_tenth",
        "S = (r, 0, z) with r = 0.1, z = 3.3 (not binary fractions): exactly tangent in rational arithmetic of "
        "the inputs in every type, but r^2 and |S|^2 round, so the computed delta is a rounding residue whose "
        "sign decides hit or miss.",
        scene("tangent on the axis, 0.1", [((0.1, 0, 3.3), 0.1)], [((1.5, 1, 1), 1)]), 1, 0, 0)
    add("tangent_axis_z07",
        "S = (r, 0, z) with r = 0.3, z = 7.7, z_E = 0.7: exactly tangent; C = z_E z and |E|^2 = z_E^2 round as "
        "well, so the residue is larger than for z_E = 2.",
        scene("tangent on the axis, 0.3", [((0.3, 0, 7.7), 0.3)], [((1.5, 1, 1), 1)], z_E=0.7), 1, 0, 0)
    # Off-axis tangents: S = alpha E + s p, p . E = 0, |p| = r, every input an exact double.
    quads = [(1, 4, 8, 9), (3, 6, 2, 7), (4, 7, 4, 9), (10, 11, 2, 15)]
    specs = [(8, 1, 5, Fraction(11.9), Fraction(1, 4), quads[1], 46),
             (8, 6, 1, Fraction(11.9), Fraction(1, 4), quads[0], 40),
             (16, 3, 9, Fraction(3.7), Fraction(1, 8), quads[1], 46),
             (8, 2, 2, Fraction(5.3), Fraction(1, 4), quads[2], 46),
             (16, 12, 13, Fraction(2.45), Fraction(1, 32), quads[3], 12)]
    for n, (w, i, j, alpha, s, qv, bits) in enumerate(specs):
        alpha = trunc_bits(alpha, bits)
        sc = tangent_scene("tangent off the axis %d" % (n + 1), w, i, j, alpha, s, qv)
        exact_in = "float and double" if bits <= 12 else "double (float rounds S)"
        add("tangent_off_axis_%d" % (n + 1),
            "S = alpha E + p with p perpendicular to E and |p| = r = %s exactly (a Pythagorean quadruple), alpha "
            "with %d significant bits: delta = 0 exactly in rational arithmetic of the %s inputs, but the "
            "products in C, |E|^2 and |S|^2 round." % (fmt_fraction(s * qv[3]), bits, exact_in),
            sc, w, i, j)
    add("grazing_float",
        "S = (1 - 2^-24, 0, 5), r = 1: the axis ray passes 2^-24 inside the silhouette, a hit; the exact "
        "delta = 4(1 - a^2) ~ 4.8e-7 against terms of 100 (8.3 digits lost): in float |S|^2 = a^2 + 25 rounds "
        "to 26, delta to 0, and the sphere's edge is lost. The light is on the hit side.",
        scene("grazing, float", [((1 - 2**-24, 0, 5), 1)], [((-1.5, 1, 1), 1)]), 1, 0, 0)
    add("grazing_double",
        "S = (1 - 2^-53, 0, 5), r = 1: 2^-53 inside the silhouette; the exact delta ~ 4.4e-16 against terms "
        "of 100 (17.1 digits lost): double rounds |S|^2 to 26 and misses; in float S rounds to (1, 0, 5), an "
        "exact tangent (a miss in exact arithmetic too).",
        scene("grazing, double", [((1 - 2**-53, 0, 5), 1)], [((-1.5, 1, 1), 1)]), 1, 0, 0)
    add("eye_on_surface",
        "|S| = r exactly (S = (0, 0.375, 0.5), r = 0.625): the near root is exactly 0, so the answer is the far "
        "root (the inside). The computed delta is fl(C^2), and in binary arithmetic sqrt(fl(C^2)) = |C| "
        "exactly, so C - sqrt(delta) is exactly 0 in every type: safe, by a theorem, not by luck.",
        scene("eye on the surface", [((0, 0.375, 0.5), 0.625)], [((0, 0.375, 0.5), 1)]), 7, 2, 3)
    add("eye_just_outside",
        "r = 0.625 - 2^-53 and |S| = 0.625: the eye is outside by 2^-53, so the exact near root is a tiny "
        "positive t ~ 6e-17 (the eye sees the surface at its own position); the article's formula computes it "
        "as C - sqrt(delta), two numbers near 1.1 that agree to 16 digits: double keeps about one digit of t, "
        "long double four. In float r rounds to 0.625: the eye is on the surface and t = 0 is 'behind'.",
        scene("eye just outside", [((0, 0.375, 0.5), 0.625 - 2**-53)], [((0, -1, 0), 1)]), 7, 2, 3)
    add("eye_inside",
        "The eye inside a sphere of radius 3: the near root is negative, the far root is taken and the normal "
        "flipped; shadows on: the sphere's own test from inside (2D < |K|^2) with the light inside too.",
        scene("eye inside", [((0.25, -0.5, 1), 3)], [((-0.5, 0.5, 1.5), 1)], z_E=1.5, shadows=True), 8, 2, 6)
    add("sphere_behind",
        "A sphere behind the eye (S = (0, 0, -5)): delta > 0 and the article's program would draw it with "
        "t = -3; promyk rejects the root (t <= 0, 'behind') and shows the background.",
        scene("sphere behind the eye", [((0, 0, -5), 1)], [((1.5, 1, 1), 1)]), 1, 0, 0)
    add("light_on_surface_inside",
        "The eye inside, the light on the surface (|L - S| = r = 3 exactly): 2D = |K|^2 exactly at every "
        "point, the boundary of the sphere's own-shadow test; exact: not blocked (lit); computed: the rounding "
        "decides.",
        scene("light on the surface, inside", [((0, 0, 1), 3)], [((1, 2, 3), 1)], z_E=1, shadows=True), 8, 5, 2)
    add("light_on_surface_outside",
        "The light on the surface (|L - S| = r = 0.75 exactly), the eye outside: D = -|K|^2/2 exactly, so the "
        "whole outside is dark, and the ray passes near the light.",
        scene("light on the surface, outside", [((0, 0, 4), 0.75)], [((0.25, 0.5, 3.5), 1)]), 8, 3, 4)
    add("light_inside",
        "The light inside the sphere, the eye outside: every outside point turns away from it (D < 0): dark.",
        scene("light inside", [((0, 0, 3.2), 1.1)], [((0.2, 0.1, 3), 1)]), 8, 3, 4)
    add("shadow_own_surface",
        "Shadows on, a point on the sphere's lit side: a numerical shadow test against its own surface would "
        "find the root s = 0 as a rounding residue (acne when positive); promyk never tests the hit sphere "
        "against its own point. `naive_own` records what the numerical test would find: the roots s_1, s_2 (one "
        "is the residue of s = 0) and whether it would call the point blocked (acne).",
        scene("own surface", [((0, 0, 3.2), 1.1)], [((1.5, 3, 1), 1)], planes=[((0, -1.1, 0), (0, 1, 0))],
              shadows=True), 16, 8, 7, naive_own=True)
    add("plane_nearly_parallel",
        "The floor y = -1 seen 1/2049 below the horizon (w = 2049, the row below the middle): y_E = -(2i+1)/w + "
        "1 cancels in the pane (about 3 digits of y_E lost in every type; the exact values here take the pane "
        "point as computed), and t ~ 1024.",
        scene("nearly parallel floor", [], [((0, 5, 1000), 1)], planes=[((0, -1, 0), (0, 1, 0))]), 2049, 1025, 1024)
    add("plane_tilted_parallel",
        "A tilted plane (n = (0, 3, 4)) and the ray through y_E = -0.4, z_E = 0.3, parallel to it in decimal "
        "arithmetic: n_hat.E = 0.6 y_E + 0.8 z_E is only the residue of rounding n_hat, y_E and z_E (about "
        "1e-8 in float, 1e-17 in double), so t = NQ/NE is huge and its sign is the residue's: the computed "
        "NE keeps few or no digits of the exact one (NE_digits_lost).",
        scene("tilted plane", [], [((0, 5, 0), 1)], planes=[((0, -1, 0), (0, 3, 4))], z_E=0.3), 5, 3, 2)
    # The article's own scene (Fig. 5) and the lessons' three pixels: nothing
    # is hard here. The baseline: every type and formula must reach its own
    # precision, so the reference covers the article's scene in every type.
    article = scene("article", [((0, 0, 3.2), 1.1)], [((1.5, 1, 1), 1)])
    for id_, (i, j), what in [("article_lit", (3, 4), "lit"), ("article_dark", (5, 1), "on the dark side"),
                              ("article_miss", (0, 0), "a miss")]:
        add(id_,
            "The article's scene and its pixel (%d, %d) at w = 8, %s: no cancellation worth the name. The "
            "baseline: every type and formula computes it to its own precision." % (i, j, what),
            article, 8, i, j)
    return out


def fmt_fraction(f):
    return str(f.numerator) if f.denominator == 1 else "%d/%d" % (f.numerator, f.denominator)


# --------------------------------------------------------------------------
# Measuring


def ulp_of(x, prec):
    """The ulp of the exact value x (a Fraction, non-zero) in a p-bit type."""
    e = math.floor(math.log2(abs(x)))
    while Fraction(2) ** e > abs(x):
        e -= 1
    while Fraction(2) ** (e + 1) <= abs(x):
        e += 1
    return Fraction(2) ** (e - prec + 1)


def error_record(sim, exact, prec, tname):
    s, x = fr(sim.v), fr(exact.v)
    err = abs(s - x)
    cap = TYPE_DIGITS[tname]
    rec = {}
    if x == 0:
        rec["ulps"] = 0.0 if err == 0 else None
        rec["relative"] = 0.0 if err == 0 else None
        rec["digits"] = round(cap, 1) if err == 0 else 0.0
    else:
        rel = err / abs(x)
        rec["ulps"] = sig(float(err / ulp_of(x, prec)))
        rec["relative"] = sig(float(rel))
        digits = cap if rel == 0 else -(math.log10(rel.numerator) - math.log10(rel.denominator))
        rec["digits"] = round(min(cap, max(0.0, digits)), 1)
    if sim.e is not None and sim.e != ZERO and sim.e != INF:
        rec["bound"] = decimal_text(fr(sim.e), 6)
    elif sim.e == INF:
        rec["bound"] = "inf"
    else:
        rec["bound"] = "0"
    assert sim.e == INF or err <= fr(sim.e), ("error above its bound", tname)
    return rec


def sig(x):
    """Three significant digits; errors below 2^-200 of the value (the exact
    values' own 4096-bit rounding) count as 0."""
    return 0.0 if abs(x) < 2.0**-200 else float("%.3g" % x)


def typed_text(raw, tname):
    return decimal_text(fr(raw), ROUND_TRIP_DIGITS[tname])


def ex_text(raw):
    return decimal_text(fr(raw), EXACT_DIGITS)


def vec_text(v, f):
    return [f(c.v) for c in v]


def cancellation_digits(EE, SS, C, r):
    """Digits lost in delta = C^2 - EE (SS - r^2) (exact values): log10 of the
    larger term over |delta|; None when delta is exactly 0 (all digits)."""
    c = SS - r * r
    delta = C * C - EE * c
    if delta == 0:
        return None
    big = max(C * C, abs(EE * c))
    return max(0.0, round(math.log10(float(big / abs(delta))), 1))


def delta_fraction(E, S, r):
    EE = sum(e * e for e in E)
    SS = sum(s * s for s in S)
    C = sum(e * s for e, s in zip(E, S))
    return EE, SS, C


def case_record(case):
    sc = case["scene"]
    w, i, j = case["pixel"]["w"], case["pixel"]["i"], case["pixel"]["j"]
    article_kernel = article_stage(sc)
    rec = {"id": case["id"], "why": case["why"], "scene": sc, "pixel": case["pixel"],
           "kernel": "article" if article_kernel else "general",
           "pane_rational": [fmt_fraction(Fraction(2 * j + 1, w) - 1), fmt_fraction(1 - Fraction(2 * i + 1, w))],
           "types": {}}
    for tname, prec, emax, emin in TYPES:
        inputs = type_inputs(sc, w, i, j, tname, prec)
        xctx = Ctx("exact", None)
        ex = trace(xctx, inputs, "article", article_kernel)
        # The discriminants with Fractions: the 4096-bit delta must be exact.
        E = [fr(c) for c in inputs["E"]]
        sph = []
        for k, s in enumerate(inputs["spheres"]):
            EE, SS, C = delta_fraction(E, [fr(c) for c in s["S"]], fr(s["r"]))
            r = fr(s["r"])
            d = C * C - EE * (SS - r * r)
            assert fr(ex["sphere_deltas"][k].v) == d, (case["id"], tname, "delta not exact")
            sph.append({"delta": decimal_text(d, EXACT_DIGITS),
                        "delta_digits_lost": cancellation_digits(EE, SS, C, r),
                        "eye_inside": SS - r * r < 0, "eye_on_surface": SS - r * r == 0})
        planes = []
        Ex = ex_tuple(xctx, inputs["E"])
        for p in inputs["planes"]:
            n = ex_tuple(xctx, p["n"])
            n_hat = vdiv(n, vdot(n, n).sqrt())
            terms = [fr(a.v) * fr(b.v) for a, b in zip(n_hat, Ex)]
            NE = sum(terms)
            planes.append({"NE": decimal_text(NE, EXACT_DIGITS),
                           "NE_digits_lost": None if NE == 0 else max(0.0, round(
                               math.log10(float(max(abs(x) for x in terms) / abs(NE))), 1))})
        trec = {"inputs": {"E": vec_text(ex_tuple(xctx, inputs["E"]), lambda v: typed_text(v, tname)),
                           "spheres": [{"S": [typed_text(c, tname) for c in s["S"]],
                                        "r": typed_text(s["r"], tname)} for s in inputs["spheres"]]},
                "exact": exact_record(ex, xctx, sph, planes), "formulas": {}}
        for f in FORMULAS:
            ctx = Ctx(tname, prec, emax, emin)
            sim = trace(ctx, inputs, f, article_kernel, naive_own=case.get("naive_own", False))
            trec["formulas"][f] = sim_record(sim, ex, prec, tname)
        rec["types"][tname] = trec
    return rec


def ex_tuple(ctx, raws):
    return tuple(ctx.num(c) for c in raws)


def exact_record(ex, ctx, sph, planes):
    r = {"branch": ex["branch"], "hit": ex["hit"], "spheres": sph, "planes": planes}
    if ex["branch"] != "miss":
        r["t"] = ex_text(ex["t"].v)
        r["P"] = vec_text(ex["P"], ex_text)
        r["N"] = vec_text(ex["N"], ex_text)
        r["result"] = ex_text(ex["result"].v)
    if ctx.ties:
        r["ties"] = sorted(set(ctx.ties))
    return r


def sim_record(sim, ex, prec, tname):
    r = {"branch": sim["branch"], "hit": sim["hit"], "branch_correct": sim["branch"] == ex["branch"] and
         sim["hit"] == ex["hit"],
         "steps": [[k, typed_text(v.v, tname)] for k, v in sim["log"]]}
    if sim["branch"] != "miss":
        r["t"] = typed_text(sim["t"].v, tname)
        r["result"] = typed_text(sim["result"].v, tname)
    if r["branch_correct"] and sim["branch"] != "miss":
        r["t_error"] = error_record(sim["t"], ex["t"], prec, tname)
        r["result_error"] = error_record(sim["result"], ex["result"], prec, tname)
    if sim.get("naive_own"):
        r["naive_own"] = [{"blocks": b, "s": None if s12 is None else [typed_text(x.v, tname) for x in s12]}
                          for b, s12 in sim["naive_own"]]
    return r


# --------------------------------------------------------------------------
# Families: the far sphere's edge, and many exact tangents


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


def far_misses_float(z):
    """The article's delta for the on-axis unit sphere at z (z_E = 2, w = 1)
    in float: each operation in double and rounded to float is the correctly
    rounded float operation (53 >= 2*24 + 2)."""
    zE = 2.0
    EE = f32(f32(f32(0.0 + 0.0) + 0.0) + f32(zE * zE))
    SS = f32(f32(0.0 + 0.0) + f32(z * z))
    C = f32(zE * z)
    delta = f32(f32(C * C) - f32(EE * f32(SS - 1.0)))
    return delta <= 0


def far_misses_double(z):
    zE = 2.0
    EE = zE * zE
    SS = z * z
    C = zE * z
    return C * C - EE * (SS - 1.0) <= 0


def far_edges():
    """The smallest whole distance z at which the article's formula misses the
    unit sphere on the axis (z_E = 2, pixel (0, 0) of w = 1), and how many of
    the next 1000 whole distances it misses too. Below 4096 (float) and
    2^26.5 (double) every operation is exact (z^2 < 2^24, resp. 2^53), so
    delta = 4 exactly: the scans start there."""
    out = {}
    for name, misses, start in (("float", far_misses_float, 4000), ("double", far_misses_double, 94906000)):
        z = start
        while not misses(float(z)):
            z += 1
        lost = sum(misses(float(k)) for k in range(z, z + 1000))
        out[name] = {"first_miss": z, "misses_in_next_1000": lost}
    return out


class Lcg:
    def __init__(self, seed):
        self.x = seed

    def next(self, n):
        self.x = (self.x * 6364136223846793005 + 1442695040888963407) % 2**64
        return (self.x >> 33) % n


def tangent_family(bits, types, count=200):
    """`count` exactly tangent rays (off axis, constructed as the
    tangent_off_axis cases with a deterministic pseudo-random pixel of w = 16,
    quadruple, alpha and s): how often each formula reports a hit (a false
    hit: the exact delta is 0), per type. alpha has `bits` significant bits;
    with 12 the scene is exact in float as well, with 46 only from double
    on (float rounds S: its rays are not tangent and are not counted)."""
    quads = [(1, 4, 8, 9), (3, 6, 2, 7), (4, 7, 4, 9), (10, 11, 2, 15), (4, 1, 8, 9), (9, 12, 8, 17)]
    rng = Lcg(2019 + bits)
    results = {t: {f: 0 for f in FORMULAS} for t in types}
    made = 0
    while made < count:
        w = 16
        i, j = rng.next(w), rng.next(w)
        qv = quads[rng.next(len(quads))]
        alpha = trunc_bits(Fraction(1 + rng.next(1 << 30), 1 << 26), bits)
        s = Fraction(1, 1 << rng.next(4))
        try:
            sc = tangent_scene("family", w, i, j, alpha, s, qv)
        except AssertionError:
            continue
        values = sc["spheres"][0]["S"] + [sc["spheres"][0]["r"], sc["z_E"]]
        if "float" in types and any(f32(v) != v for v in values):
            continue
        made += 1
        for tname, prec, emax, emin in TYPES:
            if tname not in types:
                continue
            inputs = type_inputs(sc, w, i, j, tname, prec)
            for f in FORMULAS:
                sim = trace(Ctx(tname, prec, emax, emin), inputs, f, True)
                if sim["branch"] != "miss":
                    results[tname][f] += 1
    return {"rays": count, "alpha_bits": bits,
            "construction": "w = 16; pixel (i, j), Pythagorean quadruple, alpha (%d significant bits, about 1 to "
                            "16) and s = 2^-k (k < 4) from a fixed 64-bit LCG (seed %d); S = alpha E + s p, "
                            "p . E = 0, |p| = r = s m; every input exact in %s, so delta = 0 exactly there"
                            % (bits, 2019 + bits, ", ".join(types)),
            "false_hits": results}


def tangent_families():
    return [tangent_family(12, ["float", "double", "long-double", "quad"]),
            tangent_family(46, ["double", "long-double", "quad"])]


# --------------------------------------------------------------------------
# Output


def header():
    return {
        "format": "promyk hard cases reference",
        "format_version": 1,
        "generator": "tests/reference/make_hard_cases.py (python3 with mpmath); regenerate with: "
                     "python3 tests/reference/make_hard_cases.py tests/reference/hard_cases_reference.json",
        "types": {name: {"bits": p, "digits": round(TYPE_DIGITS[name], 2)} for name, p, _, _ in TYPES},
        "inputs": "each scene number rounded to nearest in the type (exact for long double and quad); the pane "
                  "point -(2i+1)/w + 1, (2j+1)/w - 1 computed in the type; written with enough digits to read "
                  "back exactly in the type (9, 17, 21, 36)",
        "exact": "The computation of docs/conventions.md (the article's sphere formula) carried out exactly on the type's inputs "
                 "(4096-bit mpmath: + - * exact, / and sqrt to 4096 bits), %d significant digits; ties "
                 "(values equal to 3500 bits) decided as exact equality" % EXACT_DIGITS,
        "formulas": "per sphere formula, the program with every operation correctly rounded to nearest in the "
                    "type (mpmath at the type's precision, one rounding per operation; overflow and underflow "
                    "not modelled, and no value leaves the normal range); values in round-trip digits; `steps`: "
                    "the primary ray's tests and the shading's D, as the engine names them (delta, t, t_far per "
                    "sphere, NE and t_plane per plane, t_hit, D per light)",
        "errors": "t_error and result_error (when the branch is right and there is a hit): ulps of the type at "
                  "the exact value, relative error, digits correct (-log10 of the relative error, at most the "
                  "type's digits), and bound: the running error bound (README in this folder)",
    }


def catalogue(records, edges, family):
    out = {"format": "promyk hard cases catalogue", "format_version": 1,
           "about": "Hard cases for the sphere formulas, each a scene and a pixel. `expected` gives, per formula "
                    "and type, the branch the formula takes with correctly rounded arithmetic in that type, whether "
                    "it is the exact branch, and the digits correct in t and in the result (null when the branch "
                    "is wrong or there is no hit). Made by tests/reference/make_hard_cases.py --catalogue from "
                    "the measurements in tests/reference/hard_cases_reference.json.",
           "far_sphere_edge": edges, "tangent_families": family, "cases": []}
    for rec in records:
        exp = {}
        for f in FORMULAS:
            exp[f] = {}
            for t in ("float", "double"):
                s = rec["types"][t]["formulas"][f]
                ex = rec["types"][t]["exact"]
                exp[f][t] = {"branch": s["branch"], "exact_branch": ex["branch"],
                             "branch_correct": s["branch_correct"],
                             "t_digits": s["t_error"]["digits"] if "t_error" in s else None,
                             "result_digits": s["result_error"]["digits"] if "result_error" in s else None}
        out["cases"].append({"id": rec["id"], "why": rec["why"], "scene": rec["scene"], "pixel": rec["pixel"],
                             "expected": exp})
    return out


def main(argv):
    want_catalogue = len(argv) == 3 and argv[1] == "--catalogue"
    if len(argv) != 2 and not want_catalogue:
        sys.stderr.write("usage: make_hard_cases.py [--catalogue] OUTPUT.json\n")
        return 2
    if argv[-1].startswith("-"):
        # An option misread as the output would write a file named like it
        # (a 257 KB file '--help' was committed once).
        sys.stderr.write(f"{argv[0]}: the output path must not begin with '-': {argv[-1]}\n")
        return 2
    records = [case_record(c) for c in cases()]
    edges = far_edges()
    family = tangent_families()
    if want_catalogue:
        doc = catalogue(records, edges, family)
        text = json.dumps(doc, indent=1, ensure_ascii=True) + "\n"
    else:
        lines = ["{"]
        for key, value in header().items():
            lines.append(" %s: %s," % (json.dumps(key), json.dumps(value, ensure_ascii=True)))
        lines.append(' "far_sphere_edge": %s,' % json.dumps(edges))
        lines.append(' "tangent_families": %s,' % json.dumps(family))
        lines.append(' "cases": [')
        lines.append(",\n".join(json.dumps(r, separators=(",", ":")) for r in records))
        lines.append(" ]")
        lines.append("}")
        text = "\n".join(lines) + "\n"
    with open(argv[-1], "w", encoding="ascii", newline="\n") as out:
        out.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
