#!/usr/bin/env python3
"""Adversarial input lines for `epure solve`: every kind, every branch, and every kind of error.

usage: adversarial_cases.py SEED N      (prints N lines of JSON Lines, blank lines included)

The kinds and their fields are the registry's (`$EPURE kinds --json`: each kind's solve input and
its schema's fields; $EPURE defaults to build/epure beside these sources).

Deterministic for a seed (random.Random(SEED), nothing else random). The figures go where a
double-precision solver is fragile: coordinates around 1e-8 and 1e8, a small figure far from the
origin, directions of length 1e-6 and 1e6, nearly parallel segments (sin of the angle 1e-6 to
1e-12) and exactly parallel ones, nearly tangent rays (d − r ≈ ±1e-9·r), origins inside, origins
exactly on the boundary heading in and out, corners of the square and cube, rotated ellipses and
rectangles; plus bad lines of every kind.

Decidability margin. Every "nearly" figure is built in doubles, so its exact branch is whatever
the rounding made it; it is kept only when that branch is robust: the reference's branch
signature (inside, hit, reason, position, faces, the side hit, which end of its segment each
parameter lies beyond, the side of ±180°) must stay the same under six random moves of the
figure and their six opposites, where every point coordinate, radius and half-size moves by up
to 2^-40·S ≈ 9e-13·S (S the largest of them, 1 at least for the canonical square and cube),
every direction component by up to 2^-40·|u|∞ and the angle by up to 2^-40·512°, each number
uniformly within its bound. A random move reaches a good tenth of the worst move of its size,
so a kept branch survives any move of about 1e-13 relative: ten times the 1e-14 within which no
branch here may flip, and far above epure's own rounding tolerance (32ε ≈ 7e-15). That keeps
nearly parallel segments down to sin ≈ 1e-11 and nearly tangent rays down to |d − r| ≈ 1e-12·r
when the figure is not small beside its distance from the origin.
Figures exactly on a boundary (exactly parallel, collinear, touching, tangent, starting on the
figure) are built on a binary grid, where the doubles are the exact values meant; they are not
filtered, and their other branches are chosen far from any threshold.

Only branches are filtered, not numbers: a result must match the exact one within
max(1e-9, 1e-9·|x|) even where plain double arithmetic loses digits (an exact tangent, a ray
from 1e8 onto a figure of size 1).
"""
import json
import math
import os
import random
import subprocess
import sys
from fractions import Fraction

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import reference_solve as ref  # noqa: E402

MARGIN = Fraction(1, 2**40)  # ≈ 9.1e-13
PAIRS = 6


def registry_kinds():
    """The kinds as the registry describes them (`epure kinds --json`), but a kind that shares its
    solve kind with another (the preamble in space, the contract's `vectors` with three
    components), which solve_vectors_3d.sh covers."""
    here = os.path.dirname(os.path.abspath(__file__))
    epure = os.environ.get("EPURE") or os.path.join(here, "..", "..", "build", "epure")
    out = subprocess.run([epure, "kinds", "--json"], check=True, capture_output=True, text=True).stdout
    return [k for k in json.loads(out) if k["solve_kind"] == k["name"]]


KINDS = registry_kinds()
# Each kind's solve fields and their components (0 for a number).
FIELDS = {k["name"]: {f["field"]: f["dim"] if f["dim"] > 1 else 0 for f in k["data"]} for k in KINDS}
# The fields that place or size the figure (points, radii, half-sizes), and the directions, by
# their schema roles: a move of the figure moves the first by its scale, the second by its own.
POSITIONAL = {f["field"] for k in KINDS for f in k["data"] if f["role"] in ("point", "radius", "axes")}
DIRECTIONAL = {f["field"] for k in KINDS for f in k["data"] if f["role"] == "direction"}


# ---- decidability ----------------------------------------------------------------------------

def signature(figure):
    """What must not flip: the discrete part of the reference's answer."""
    try:
        res = ref.solve_object(figure)
    except ref.BadLine:
        return ("error",)
    sig = []
    for key in ("inside", "hit", "reason", "position", "intersects", "_side"):
        if key in res:
            sig.append((key, res[key]))
    if "faces" in res:
        sig.append(("faces", tuple(sorted(res["faces"]))))
    for key in ("t_ab", "t_cd"):
        if key in res:  # which end a parameter is beyond, or none
            sig.append((key, (res[key] >= 0) + (res[key] > 1)))
    if res["kind"] == "vectors" and res["cos"] < 0:
        sig.append(("upper", res["_angle_positive"]))
    return tuple(sig)


def power_of_two_above(x):
    """The least power of two ≥ x > 0, as a Fraction: keeps the moved numbers' denominators
    binary, and the exact arithmetic on them fast."""
    return Fraction(2) ** (math.frexp(float(x))[1]) if x > 0 else Fraction(1)


def moves(figure, rng):
    """A random move of every number of the figure within its bound (see the module's text),
    as {key: [delta, ...]}; uniform rather than ±bound, so that two moves of opposite effect
    do not cancel exactly."""
    numbers = {k: v if isinstance(v, list) else [v] for k, v in figure.items() if k != "kind"}
    square = figure["kind"] in ("ray_square", "ray_cube")
    scale = power_of_two_above(max([abs(x) for k in POSITIONAL if k in numbers for x in numbers[k]]
                                   + [1.0 if square else 0.0]))
    deltas = {}
    for key, values in numbers.items():
        if key in POSITIONAL:
            bound = MARGIN * scale
        elif key in DIRECTIONAL:
            bound = MARGIN * power_of_two_above(max(abs(x) for x in values))
        elif key == "angle":
            bound = MARGIN * 512  # ≥ 360°
        else:
            continue
        deltas[key] = [Fraction(rng.randint(-1024, 1024), 1024) * bound for _ in values]
    return deltas


def moved(figure, deltas, sign):
    out = dict(figure)
    for key, ds in deltas.items():
        v = figure[key]
        new = [Fraction(x) + sign * d for x, d in zip(v if isinstance(v, list) else [v], ds)]
        out[key] = new if isinstance(v, list) else new[0]
    return out


def robust(figure, rng):
    """The branch signature survives PAIRS random moves and their opposites."""
    base = signature(figure)
    for _ in range(PAIRS):
        deltas = moves(figure, rng)
        if any(signature(moved(figure, deltas, sign)) != base for sign in (1, -1)):
            return False
    return True


# ---- writing lines ---------------------------------------------------------------------------

def spell(x, rng):
    """A JSON spelling of the double x: shortest, integer, or 17-digit exponent form."""
    if isinstance(x, str):
        return x  # already text (1e999, a wrong literal)
    if isinstance(x, bool) or x is None:
        return json.dumps(x)
    if isinstance(x, int):
        return str(x)
    if x == 0 and math.copysign(1, x) < 0:
        return "-0.0"
    roll = rng.random()
    if x.is_integer() and abs(x) < 1e15 and roll < 0.3:
        return str(int(x))
    if roll > 0.9:
        return f"{x:.16e}"
    return repr(x)


def dump(value, rng, spaced):
    sep, colon = (", ", ": ") if spaced else (",", ":")
    if isinstance(value, dict):
        items = (json.dumps(k) + colon + dump(v, rng, spaced) for k, v in value.items())
        return "{" + sep.join(items) + "}"
    if isinstance(value, list):
        return "[" + sep.join(dump(v, rng, spaced) for v in value) + "]"
    if isinstance(value, str) and not value.startswith("\x00"):
        return json.dumps(value)
    return spell(value[1:] if isinstance(value, str) else value, rng)


def raw(text):
    """A number spelled as given (1e999): marked so that dump() writes it verbatim."""
    return "\x00" + text


# ---- building blocks -------------------------------------------------------------------------

class Cases:
    def __init__(self, rng):
        self.rng = rng

    def u(self, lo=-1.0, hi=1.0):
        return self.rng.uniform(lo, hi)

    def magnitude(self):
        return self.rng.choice((1e-8, 1e-6, 1e-3, 1.0, 1.0, 1.0, 10.0, 1e3, 1e6, 1e8)) * \
            self.rng.uniform(0.5, 2.0)

    def offset(self, size):
        """How far from the origin a figure of this size sits: at it, near it, or far away, up
        to 1e8 times its size (a small figure far away) but never beyond 1e9 (doubles near
        1e8 still resolve a figure of size 1)."""
        far = size * self.rng.choice((0.0, 1.0, 1e3, 1e6, 1e8))
        return min(far, max(1e9, size))

    def tiny(self, lo=-12, hi=-6):
        return 10 ** self.rng.uniform(lo, hi) * self.rng.choice((-1, 1))

    def length(self):
        """A direction's length: 1e-6, 1e6 and their neighbours as often as ordinary ones."""
        return self.rng.choice((1e-6, 1e6, 1.0, 3.0, 10 ** self.u(-6, 6), 10 ** self.u(-6, 6)))

    def unit(self, dim):
        while True:
            v = [self.rng.gauss(0, 1) for _ in range(dim)]
            n = math.sqrt(sum(c * c for c in v))
            if n > 1e-3:
                return [c / n for c in v]

    def direction(self, dim):
        k = self.length()
        return [k * c for c in self.unit(dim)]

    def point(self, dim, scale, centre=None):
        centre = centre or [0.0] * dim
        return [c + self.u(-scale, scale) for c in centre]

    def grid(self, scale):
        """A binary unit near scale/64 and an offset on it: grid points are exact doubles."""
        unit = 2.0 ** round(math.log2(scale / 64))
        return unit

    def grid_offset(self, dim, unit):
        far = self.rng.choice((0, 0, 2**10, 2**20, 2**36))
        return [unit * self.rng.randint(-far, far) for _ in range(dim)]

    def angle(self):
        r = self.rng.random()
        if r < 0.15:
            return float(self.rng.choice((0, 90, 180, 270, -90, 360, 450, -270)))
        if r < 0.3:
            return float(self.rng.randint(-720, 720))
        if r < 0.4:
            return self.rng.choice((1e6, -1e8, 3600.0)) + self.u(0, 360)
        if r < 0.45:
            return self.tiny(-12, -6)
        return self.u(-360, 360)


def aim(g, A, target):
    """A direction from A through target, of a random length."""
    k = g.length()
    return [k * (t - a) for a, t in zip(A, target)]


def rot2(v, angle_deg):
    c, s = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg))
    return [c * v[0] - s * v[1], s * v[0] + c * v[1]]


def perp(v):
    return [-v[1], v[0]]


def plus(p, v, k=1.0):
    return [a + k * b for a, b in zip(p, v)]


# ---- the figures: each returns (figure, exact?) ----------------------------------------------

def vectors(g):
    r = g.rng.random()
    if r < 0.3:
        return {"kind": "vectors", "u": g.direction(2), "v": g.direction(2)}, False
    if r < 0.6:
        u = g.direction(2)
        v = [-c * g.length() for c in rot2(u, math.degrees(g.tiny()))]
        return {"kind": "vectors", "u": u, "v": v}, False
    if r < 0.75:
        # exact: opposite, same, perpendicular, on a binary grid
        unit = g.grid(g.magnitude())
        a, b = g.rng.randint(-64, 64), g.rng.randint(-64, 64) or 1
        u = [a * unit, b * unit]
        k = 2.0 ** g.rng.randint(-20, 20)
        v = g.rng.choice(([-k * c for c in u], [k * c for c in u], [-k * u[1], k * u[0]],
                          [k * u[1], -k * u[0]]))
        return {"kind": "vectors", "u": u, "v": v}, True
    if r < 0.85:
        # signed zeros: the angle of opposite vectors is 180 whatever the zeros' signs
        x, y = g.magnitude(), g.magnitude()
        z1, z2 = g.rng.choice((0.0, -0.0)), g.rng.choice((0.0, -0.0))
        u, v = g.rng.choice((([x, z1], [-y, z2]), ([z1, x], [z2, -y]), ([-x, z1], [y, z2]),
                             ([z1, -x], [z2, y]), ([x, z1], [y, z2]), ([z1, x], [-y, z2])))
        return {"kind": "vectors", "u": u, "v": v}, True
    # far from unit: 1e-150 against 1e150
    return {"kind": "vectors", "u": [c * 10.0 ** g.rng.randint(-150, 150) for c in g.unit(2)],
            "v": [c * 10.0 ** g.rng.randint(-150, 150) for c in g.unit(2)]}, False


def projection(g):
    r = g.rng.random()
    s = g.magnitude()
    centre = g.point(2, g.offset(s))
    if r < 0.35:
        A, B, C = (g.point(2, s, centre) for _ in range(3))
        return {"kind": "projection", "A": A, "B": B, "C": C}, False
    if r < 0.7:
        A, B = g.point(2, s, centre), g.point(2, s, centre)
        AB = [b - a for a, b in zip(A, B)]
        t = g.rng.choice((0.0, 1.0)) + g.tiny(-11, -4)
        C = plus(plus(A, AB, t), perp(AB), g.u(-3, 3))
        return {"kind": "projection", "A": A, "B": B, "C": C}, False
    # exact: t = 0, 1, 1/2 or any, on a binary grid
    unit = g.grid(s)
    off = g.grid_offset(2, unit)
    A = plus(off, [unit * g.rng.randint(-64, 64) for _ in range(2)])
    AB = [unit * g.rng.randint(-64, 64) for _ in range(2)]
    if AB == [0, 0]:
        AB = [unit, 0.0]
    B = plus(A, AB)
    base = g.rng.choice((A, B, plus(A, AB, 0.5), plus(A, AB, -2.0), plus(A, AB, 3.0)))
    C = plus(base, perp(AB), g.rng.randint(-3, 3))
    return {"kind": "projection", "A": A, "B": B, "C": C}, True


def segments(g):
    r = g.rng.random()
    s = g.magnitude()
    centre = g.point(2, g.offset(s))
    if r < 0.25:
        A, B, C, D = (g.point(2, s, centre) for _ in range(4))
        return {"kind": "segments", "A": A, "B": B, "C": C, "D": D}, False
    if r < 0.55:
        # nearly parallel, crossing at I inside or outside the segments
        AB = [s * c for c in g.unit(2)]
        CD = [c * g.u(0.2, 2) * g.rng.choice((-1, 1)) for c in rot2(AB, math.degrees(g.tiny()))]
        I = g.point(2, s, centre)
        t_ab = g.rng.choice((g.u(0, 1), g.u(-2, 3), g.rng.choice((0.0, 1.0)) + g.tiny(-10, -4)))
        t_cd = g.rng.choice((g.u(0, 1), g.u(-2, 3)))
        A, C = plus(I, AB, -t_ab), plus(I, CD, -t_cd)
        return {"kind": "segments", "A": A, "B": plus(A, AB), "C": C, "D": plus(C, CD)}, False
    if r < 0.65:
        # nearly touching at an end: a gap or an overlap of a tiny fraction
        A, B = g.point(2, s, centre), g.point(2, s, centre)
        AB = [b - a for a, b in zip(A, B)]
        C = plus(g.rng.choice((A, B)), perp(AB), g.tiny(-11, -5))
        D = plus(C, g.unit(2), s * g.u(0.2, 2))
        return {"kind": "segments", "A": A, "B": B, "C": C, "D": D}, False
    # exact, on a binary grid: parallel, collinear (overlapping or not), touching, crossing
    unit = g.grid(s)
    off = g.grid_offset(2, unit)
    A = plus(off, [unit * g.rng.randint(-64, 64) for _ in range(2)])
    AB = [unit * g.rng.randint(-32, 32) for _ in range(2)]
    if AB == [0, 0]:
        AB = [0.0, unit]
    B = plus(A, AB)
    case = g.rng.choice(("parallel", "collinear", "touch", "end", "T", "near_collinear"))
    if case == "parallel":
        C = plus(plus(A, AB, g.rng.randint(-3, 3)), perp(AB), g.rng.choice((-2, -1, 1, 2)))
        D = plus(C, AB, g.rng.choice((-2.0, -1.0, 0.5, 1.0, 4.0)))
    elif case == "near_collinear":
        # exactly parallel, the lines 2^-24·|AB| apart: near the origin (no far offset), so
        # that C stays an exact double and the gap ≥ 2^-32 of the figure, a decidable one
        A = [unit * g.rng.randint(-64, 64) for _ in range(2)]
        B = plus(A, AB)
        C = plus(plus(A, AB, g.rng.randint(-3, 3)), perp(AB), g.rng.choice((-1, 1)) * 2.0**-24)
        D = plus(C, AB, g.rng.choice((-2.0, 1.0, 0.5)))
    elif case == "collinear":
        C = plus(A, AB, g.rng.choice((-2.0, -0.5, 0.25, 1.0, 1.5, 3.0)))
        D = plus(A, AB, g.rng.choice((-1.0, 0.5, 2.0, 4.0)))
        if C == D:
            D = plus(C, AB)
    elif case == "touch":
        # C on (AB) at an end or inside, D off the line
        C = plus(A, AB, g.rng.choice((0.0, 1.0, 0.5, 0.25)))
        D = plus(C, [unit * g.rng.randint(-16, 16) for _ in range(2)])
        if D == C or AB[0] * (D[1] - C[1]) == AB[1] * (D[0] - C[0]):
            D = plus(C, perp(AB))
    elif case == "end":
        C = g.rng.choice((A, B))
        D = plus(C, perp(AB), g.rng.choice((-1.0, 1.0, 0.5)))
    else:
        # crossing at a grid point of both
        C = plus(plus(A, AB, 0.5), perp(AB), -1.0)
        D = plus(plus(A, AB, 0.5), perp(AB), g.rng.choice((1.0, -0.5, 0.75)))
    return {"kind": "segments", "A": A, "B": B, "C": C, "D": D}, True


PYTHAGOREAN_2D = ((3, 4, 5), (5, 12, 13), (8, 15, 17), (7, 24, 25), (20, 21, 29), (1, 0, 1))
PYTHAGOREAN_3D = ((1, 2, 2, 3), (2, 3, 6, 7), (1, 4, 8, 9), (4, 4, 7, 9), (2, 6, 9, 11),
                  (1, 0, 0, 1))


def signed_permutation(g, v):
    v = list(v)
    g.rng.shuffle(v)
    return [c * g.rng.choice((-1, 1)) for c in v]


def ball(g, dim):
    kind = "ray_circle" if dim == 2 else "ray_sphere"
    r = g.rng.random()
    radius = g.magnitude()
    C = g.point(dim, g.offset(radius))
    if r < 0.25:
        # from anywhere, aimed near the figure
        A = g.point(dim, radius * g.rng.choice((0.5, 3, 100, 1e6)), C)
        target = g.point(dim, 1.5 * radius, C)
        u = aim(g, A, target)
        return {"kind": kind, "A": A, "u": u, "C": C, "r": radius}, False
    if r < 0.5:
        # nearly tangent: the line passes at r·(1 + ζ) from C, ζ ≈ ±1e-12 to ±1e-7
        w = g.unit(dim)
        n = g.unit(dim)
        dn = sum(a * b for a, b in zip(w, n))
        n = [a - dn * b for a, b in zip(n, w)]
        nn = math.sqrt(sum(c * c for c in n))
        n = [c / nn for c in n]
        foot = plus(C, n, radius * (1 + g.tiny(-12, -7)))
        A = plus(foot, w, -radius * g.rng.choice((1.5, 10, 1e3, -0.5)))
        return {"kind": kind, "A": A, "u": [g.length() * c for c in w], "C": C, "r": radius}, False
    if r < 0.65:
        # inside, anywhere, heading anywhere
        A = plus(C, g.unit(dim), radius * g.u(0, 0.999))
        return {"kind": kind, "A": A, "u": g.direction(dim), "C": C, "r": radius}, False
    if r < 0.75:
        # outside and heading away: behind, whether or not the line misses
        A = plus(C, g.unit(dim), radius * g.u(1.01, 5))
        AC = [c - a for a, c in zip(A, C)]
        u = [-c + g.u(-0.9, 0.9) * radius for c in AC]
        return {"kind": kind, "A": A, "u": u, "C": C, "r": radius}, False
    # exact: A on the sphere (a Pythagorean point on a binary grid), heading in, out, or tangent
    unit = g.grid(radius) * 8
    Cg = plus(g.grid_offset(dim, unit), [unit * g.rng.randint(-64, 64) for _ in range(dim)])
    triple = g.rng.choice(PYTHAGOREAN_2D if dim == 2 else PYTHAGOREAN_3D)
    k = unit * 2.0 ** g.rng.randint(-2, 2)
    CA = [k * c for c in signed_permutation(g, triple[:dim])]
    A = plus(Cg, CA)
    how = g.rng.choice(("in", "out", "tangent", "tangent_far"))
    if how in ("tangent", "tangent_far"):
        # u ⊥ CA exactly (integer multiples of k): tangent at A (t = 0), or from 4 steps back
        # along the tangent, a tangent hit at A from outside
        if dim == 2:
            u = [-CA[1], CA[0]]
        else:
            u = cross_int(CA, [1, 2, 3])
            u = u if any(u) else cross_int(CA, [3, 1, 2])
        if how == "tangent_far":
            A = plus(A, u, -4.0)
        return {"kind": kind, "A": A, "u": u, "C": Cg, "r": k * triple[dim]}, True
    while True:
        u = g.direction(dim)
        cosine = sum(a * b for a, b in zip(u, CA)) / (
            math.sqrt(sum(c * c for c in u)) * k * triple[dim])
        if abs(cosine) > 0.05 and (cosine < 0) == (how == "in"):
            break
    return {"kind": kind, "A": A, "u": u, "C": Cg, "r": k * triple[dim]}, True


def cross_int(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def box(g, dim):
    kind = "ray_square" if dim == 2 else "ray_cube"
    r = g.rng.random()
    if r < 0.3:
        far = g.rng.choice((1.5, 3.0, 10.0, 1e3, 1e8))
        A = g.point(dim, far)
        target = g.point(dim, g.rng.choice((1.05, 1.3)))
        u = aim(g, A, target)
        return {"kind": kind, "A": A, "u": u}, False
    if r < 0.45:
        # inside, some of it at 1e-8 from the centre
        A = g.point(dim, g.rng.choice((0.999, 1e-8, 0.5)))
        u = g.direction(dim)
        if g.rng.random() < 0.3:
            u[g.rng.randrange(dim)] = 0.0
        return {"kind": kind, "A": A, "u": u}, False
    if r < 0.65:
        # nearly through a corner (or an edge of the cube): a hit beside it or a near miss
        corner = [g.rng.choice((-1.0, 1.0)) for _ in range(dim)]
        target = [c + g.tiny(-11, -5) for c in corner]
        if dim == 3 and g.rng.random() < 0.5:
            target[g.rng.randrange(3)] = g.u(-0.9, 0.9)  # an edge
        A = plus(target, g.unit(dim), g.rng.choice((-2.0, -5.0, -1e3)))
        u = aim(g, A, target)
        return {"kind": kind, "A": A, "u": u}, False
    if r < 0.75:
        # outside along axis directions: zero components, hit or miss by a margin
        A = [g.u(-0.95, 0.95) if g.rng.random() < 0.6 else g.u(1.05, 3) * g.rng.choice((-1, 1))
             for _ in range(dim)]
        k = g.rng.randrange(dim)
        A[k] = g.rng.choice((-1, 1)) * g.u(1.5, 1e6)
        u = [0.0] * dim
        u[k] = -math.copysign(g.length(), A[k])
        return {"kind": kind, "A": A, "u": u}, False
    # exact: A on a side (heading in or out), or at a corner, coordinates on a binary grid
    A = [g.rng.randint(-15, 15) / 16 for _ in range(dim)]
    k = g.rng.randrange(dim)
    side = g.rng.choice((-1.0, 1.0))
    A[k] = side
    u = g.direction(dim)
    if abs(u[k]) < 0.05 * max(abs(c) for c in u):
        u[k] = 0.5 * max(abs(c) for c in u) * g.rng.choice((-1, 1))
    how = g.rng.choice(("in", "out", "corner_out", "corner_touch"))
    if how == "in":
        u[k] = -side * abs(u[k])
    elif how == "out":
        u[k] = side * abs(u[k])
    else:
        A = [g.rng.choice((-1.0, 1.0)) for _ in range(dim)]
        u = [a * abs(c) for a, c in zip(A, u)]  # every component outward
        if how == "corner_touch":
            u[0] = -u[0]  # one component inward: touches the corner at t = 0, enters nowhere
    return {"kind": kind, "A": A, "u": u}, True


def ellipse(g):
    r = g.rng.random()
    s = g.magnitude()
    C = g.point(2, g.offset(s))
    a, b = s * g.u(0.2, 2), s * g.u(0.2, 2) * g.rng.choice((1, 1, 1e-2, 1e2))
    angle = g.angle()
    if r < 0.35:
        A = g.point(2, max(a, b) * g.rng.choice((0.5, 3, 100, 1e5)), C)
        # aimed at a point of the figure's box, a little enlarged: mostly hits, some misses
        target = plus(C, rot2([a * g.u(-1.1, 1.1), b * g.u(-1.1, 1.1)], angle))
        u = aim(g, A, target)
        return {"kind": "ray_ellipse", "A": A, "u": u, "C": C, "radii": [a, b],
                "angle": angle}, False
    if r < 0.7:
        # nearly tangent at a point of the ellipse, in its own axes then rotated
        th = g.u(0, 2 * math.pi)
        P = [a * math.cos(th), b * math.sin(th)]
        T = [-a * math.sin(th), b * math.cos(th)]
        n = [math.cos(th) / a, math.sin(th) / b]
        nn, tn = math.hypot(*n), math.hypot(*T)
        n, T = [c / nn for c in n], [c / tn for c in T]
        zeta = g.tiny(-12, -7) * min(a, b)
        start = plus(plus(P, n, zeta), T, -max(a, b) * g.rng.choice((2, 10, 1e3)))
        A = plus(C, rot2(start, angle))
        u = [g.length() * c for c in rot2(T, angle)]
        return {"kind": "ray_ellipse", "A": A, "u": u, "C": C, "radii": [a, b],
                "angle": angle}, False
    if r < 0.8:
        th = g.u(0, 2 * math.pi)
        k = g.u(0, 0.999)
        A = plus(C, rot2([k * a * math.cos(th), k * b * math.sin(th)], angle))
        return {"kind": "ray_ellipse", "A": A, "u": g.direction(2), "C": C, "radii": [a, b],
                "angle": angle}, False
    # exact: angle a multiple of 90°, A on the ellipse at a Pythagorean point
    unit = g.grid(s) * 8
    Cg = plus(g.grid_offset(2, unit), [unit * g.rng.randint(-64, 64) for _ in range(2)])
    ka, kb = unit * 2.0 ** g.rng.randint(-3, 3), unit * 2.0 ** g.rng.randint(-3, 3)
    x, y, h = g.rng.choice(PYTHAGOREAN_2D)
    if g.rng.random() < 0.5:
        x, y = y, x
    local = [x * ka * g.rng.choice((-1, 1)), y * kb * g.rng.choice((-1, 1))]
    quarter = g.rng.randrange(4)
    angle = float(90 * quarter + 360 * g.rng.randint(-2, 2))
    world = local
    for _ in range(quarter):
        world = [-world[1], world[0]]
    A = plus(Cg, world)
    normal = [local[0] / (h * ka) ** 2, local[1] / (h * kb) ** 2]
    how = g.rng.choice(("in", "out", "tangent"))
    if how == "tangent":
        # along the tangent (−n_y, n_x), scaled to exact doubles
        t = [-local[1] * ka * ka, local[0] * kb * kb]
        m = 2.0 ** round(math.log2(max(abs(c) for c in t)))  # a power of two keeps it exact
        u_local = [c / m for c in t]
    else:
        while True:
            u_local = g.direction(2)
            c = (u_local[0] * normal[0] + u_local[1] * normal[1]) / (
                math.hypot(*u_local) * math.hypot(*normal))
            if abs(c) > 0.05 and (c < 0) == (how == "in"):
                break
    u = u_local
    for _ in range(quarter):
        u = [-u[1], u[0]]
    return {"kind": "ray_ellipse", "A": A, "u": u, "C": Cg, "radii": [h * ka, h * kb],
            "angle": angle}, True


def rectangle(g):
    r = g.rng.random()
    s = g.magnitude()
    C = g.point(2, g.offset(s))
    w, h = s * g.u(0.2, 2), s * g.u(0.2, 2) * g.rng.choice((1, 1, 1e-2, 1e2))
    angle = g.angle()
    if r < 0.35:
        A = g.point(2, max(w, h) * g.rng.choice((0.5, 3, 100, 1e5)), C)
        target = plus(C, rot2([w * g.u(-1.2, 1.2), h * g.u(-1.2, 1.2)], angle))
        u = aim(g, A, target)
        return {"kind": "ray_rectangle", "A": A, "u": u, "C": C, "half": [w, h],
                "angle": angle}, False
    if r < 0.6:
        # nearly through a corner, in the rectangle's axes then rotated
        corner = [g.rng.choice((-1, 1)) * w, g.rng.choice((-1, 1)) * h]
        target = [corner[0] * (1 + g.tiny(-11, -5)), corner[1] * (1 + g.tiny(-11, -5))]
        start = plus(target, g.unit(2), -max(w, h) * g.rng.choice((2, 10, 1e3)))
        A = plus(C, rot2(start, angle))
        u = [g.length() * c for c in rot2([t - p for p, t in zip(start, target)], angle)]
        return {"kind": "ray_rectangle", "A": A, "u": u, "C": C, "half": [w, h],
                "angle": angle}, False
    if r < 0.75:
        A = plus(C, rot2([w * g.u(-0.999, 0.999), h * g.u(-0.999, 0.999)], angle))
        return {"kind": "ray_rectangle", "A": A, "u": g.direction(2), "C": C, "half": [w, h],
                "angle": angle}, False
    # exact: angle a multiple of 90°, A on a side (heading in or out) or at a corner heading out
    unit = g.grid(s) * 8
    Cg = plus(g.grid_offset(2, unit), [unit * g.rng.randint(-64, 64) for _ in range(2)])
    half = [unit * g.rng.randint(1, 16), unit * g.rng.randint(1, 16)]
    k = g.rng.randrange(2)
    local = [half[0] * g.rng.randint(-15, 15) / 16, half[1] * g.rng.randint(-15, 15) / 16]
    side = g.rng.choice((-1, 1))
    local[k] = side * half[k]
    u_local = g.direction(2)
    if abs(u_local[k]) < 0.05 * max(map(abs, u_local)):
        u_local[k] = max(map(abs, u_local))
    how = g.rng.choice(("in", "out", "corner_out"))
    if how == "in":
        u_local[k] = -side * abs(u_local[k])
    elif how == "out":
        u_local[k] = side * abs(u_local[k])
    else:
        local = [g.rng.choice((-1, 1)) * half[0], g.rng.choice((-1, 1)) * half[1]]
        u_local = [math.copysign(abs(c), p) for c, p in zip(u_local, local)]
    quarter = g.rng.randrange(4)
    angle = float(90 * quarter + 360 * g.rng.randint(-2, 2))
    world, u = local, u_local
    for _ in range(quarter):
        world, u = [-world[1], world[0]], [-u[1], u[0]]
    return {"kind": "ray_rectangle", "A": plus(Cg, world), "u": u, "C": Cg, "half": half,
            "angle": angle}, True


# ---- at 1, 2 and 3 ulps from a decision boundary ---------------------------------------------
#
# Each figure starts exactly on a boundary (on a binary grid, where the doubles are the values
# meant: C at the foot of A, an end of one segment on the other, parallel segments, A on the
# circle, a tangent line, a line perpendicular to AC, A on a side of the square, a ray through a
# corner), then one of its numbers moves by 0, ±1, ±2 or ±3 ulps. The exact branch is whatever
# that made it, and none is filtered: epure's decisions must be the exact ones however close.

def nudged(x, k):
    """x moved by k ulps (k < 0: down)."""
    for _ in range(abs(k)):
        x = math.nextafter(x, math.inf if k > 0 else -math.inf)
    return x


def nudge_one(g, v):
    """A copy of the list v with one non-zero coordinate moved by up to 3 ulps. (A zero moved
    by an ulp is a subnormal: products with it underflow, which the contract leaves out.)"""
    v = list(v)
    nonzero = [i for i, x in enumerate(v) if x != 0] or list(range(len(v)))
    i = g.rng.choice(nonzero)
    if v[i] == 0:
        return v
    v[i] = nudged(v[i], g.rng.choice((-3, -2, -1, 0, 1, 2, 3)))
    return v


def grid_point(g, dim, unit, off):
    return plus(off, [unit * g.rng.randint(-64, 64) for _ in range(dim)])


def boundary_projection(g):
    unit = g.grid(g.magnitude())
    off = g.grid_offset(2, unit)
    A = grid_point(g, 2, unit, off)
    AB = [unit * g.rng.randint(-32, 32) for _ in range(2)]
    if AB == [0, 0]:
        AB = [unit, 0.0]
    B = plus(A, AB)
    C = plus(g.rng.choice((A, B)), perp(AB), g.rng.randint(-4, 4))
    fig = {"kind": "projection", "A": A, "B": B, "C": C}
    key = g.rng.choice(("A", "B", "C", "C"))
    fig[key] = nudge_one(g, fig[key])
    return fig, True


def boundary_segments(g):
    unit = g.grid(g.magnitude())
    off = g.grid_offset(2, unit)
    A = grid_point(g, 2, unit, off)
    AB = [unit * g.rng.randint(-32, 32) for _ in range(2)]
    if AB == [0, 0]:
        AB = [0.0, unit]
    B = plus(A, AB)
    case = g.rng.choice(("touch", "touch", "parallel", "collinear", "end"))
    if case == "touch":  # an end of CD on [AB], at an end of AB or inside
        C = plus(A, AB, g.rng.choice((0.0, 1.0, 0.5, 0.25)))
        D = plus(C, [unit * g.rng.randint(-16, 16) for _ in range(2)])
        if AB[0] * (D[1] - C[1]) == AB[1] * (D[0] - C[0]):
            D = plus(C, perp(AB))
    elif case == "parallel":
        C = plus(plus(A, AB, g.rng.randint(-3, 3)), perp(AB), g.rng.choice((-1, 1)))
        D = plus(C, AB, g.rng.choice((-2.0, 1.0, 0.5)))
    elif case == "collinear":
        C = plus(A, AB, g.rng.choice((-2.0, 0.5, 1.0, 1.5)))
        D = plus(C, AB, g.rng.choice((-1.0, 1.0, 2.0)))
    else:  # CD starts at an end of AB
        C = g.rng.choice((A, B))
        D = plus(C, perp(AB), g.rng.choice((-1.0, 1.0, 0.5)))
    if g.rng.random() < 0.5:
        C, D = D, C
    fig = {"kind": "segments", "A": A, "B": B, "C": C, "D": D}
    key = g.rng.choice("ABCD")
    fig[key] = nudge_one(g, fig[key])
    return fig, True


def boundary_ball(g, dim):
    kind = "ray_circle" if dim == 2 else "ray_sphere"
    unit = g.grid(g.magnitude()) * 8
    C = plus(g.grid_offset(dim, unit), [unit * g.rng.randint(-64, 64) for _ in range(dim)])
    triple = g.rng.choice(PYTHAGOREAN_2D if dim == 2 else PYTHAGOREAN_3D)
    k = unit * 2.0 ** g.rng.randint(-2, 2)
    CA = [k * c for c in signed_permutation(g, triple[:dim])]
    r = k * triple[dim]
    P = plus(C, CA)  # on the sphere
    # a tangent direction at P, exact: perpendicular to CA with integer coordinates
    if dim == 2:
        tangent = [-CA[1], CA[0]]
    else:
        other = [1.0, 0.0, 0.0] if abs(CA[0]) < abs(CA[1]) or abs(CA[0]) < abs(CA[2]) else \
            [0.0, 1.0, 0.0]
        tangent = cross_int(CA, other)
    tangent = [c * g.rng.choice((1, -1)) for c in tangent]
    how = g.rng.choice(("on", "tangent", "tangent", "perpendicular"))
    if how == "on":  # A on the sphere, heading in, out or along
        A = P
        u = g.rng.choice(([-c for c in CA], CA, tangent, plus(tangent, CA, -0.5)))
    elif how == "tangent":  # a tangent line, A some steps back along it
        A = plus(P, tangent, -float(g.rng.choice((1, 2, 4, 1024))))
        u = tangent
    else:  # outside, u ⊥ AC (t_proj = 0)
        A = plus(C, CA, 2.0)
        u = tangent
    fig = {"kind": kind, "A": A, "u": [c * 2.0 ** g.rng.randint(-20, 20) for c in u], "C": C,
           "r": r}
    key = g.rng.choice(("A", "u", "C", "r", "r"))
    if key == "r":
        fig["r"] = nudged(r, g.rng.choice((-3, -2, -1, 0, 1, 2, 3)))
    else:
        fig[key] = nudge_one(g, fig[key])
    return fig, True


def boundary_box(g, dim):
    kind = "ray_square" if dim == 2 else "ray_cube"
    unit = 2.0 ** -g.rng.randint(2, 6)
    far = g.rng.choice((4, 16, 2**20, 2**30))
    how = g.rng.choice(("side", "corner", "corner", "inside_corner"))
    A = [unit * g.rng.randint(-far, far) for _ in range(dim)]
    if how == "side":  # A on a side, heading anywhere
        i = g.rng.randrange(dim)
        A = [unit * g.rng.randint(-int(1 / unit), int(1 / unit)) for _ in range(dim)]
        A[i] = g.rng.choice((-1.0, 1.0))
        u = [unit * g.rng.randint(-8, 8) for _ in range(dim)]
        if all(c == 0 for c in u):
            u[i] = -A[i]
    elif how == "corner":  # from outside through a corner (or an edge's point in 3D)
        corner = [g.rng.choice((-1.0, 1.0)) for _ in range(dim)]
        A = [c + unit * g.rng.randint(1, far) * c for c in corner]
        if dim == 3 and g.rng.random() < 0.5:
            corner[2] = unit * g.rng.randint(-int(1 / unit), int(1 / unit))
        u = [c - a for a, c in zip(A, corner)]
    else:  # from inside towards a corner
        corner = [g.rng.choice((-1.0, 1.0)) for _ in range(dim)]
        A = [unit * g.rng.randint(-int(1 / unit) + 1, int(1 / unit) - 1) for _ in range(dim)]
        u = [c - a for a, c in zip(A, corner)]
        if all(c == 0 for c in u):
            u = corner
    fig = {"kind": kind, "A": A, "u": [c * 2.0 ** g.rng.randint(-20, 20) for c in u]}
    key = g.rng.choice(("A", "u"))
    fig[key] = nudge_one(g, fig[key])
    return fig, True


def boundary_transformed(g):
    """Ellipse or rectangle centred at the origin, radii or half-sizes powers of two and the
    angle a multiple of 90°: the ray carried into the canonical frame is exact, and so are the
    decisions; A starts on the figure (or heads at a corner) and moves by up to 3 ulps."""
    angle = float(g.rng.choice((0, 90, 180, 270, -90, 360)))
    sizes = [2.0 ** g.rng.randint(-3, 3), 2.0 ** g.rng.randint(-3, 3)]
    c, s = {0: (1, 0), 90: (0, 1), 180: (-1, 0), 270: (0, -1)}[int(angle) % 360]
    world = lambda v: [c * v[0] - s * v[1], s * v[0] + c * v[1]]
    if g.rng.random() < 0.5:
        local = g.rng.choice(([1.0, 0.0], [0.0, -1.0], [-1.0, 0.0], [0.6, 0.8]))
        local_u = g.rng.choice(([-1.0, 0.25], [1.0, 0.5], [0.0, 1.0], [-0.75, -1.0]))
        P = world([local[0] * sizes[0], local[1] * sizes[1]])
        u = world(local_u)
        fig = {"kind": "ray_ellipse", "A": P, "u": u, "C": [0.0, 0.0], "radii": sizes,
               "angle": angle}
    else:
        corner = [g.rng.choice((-1.0, 1.0)), g.rng.choice((-1.0, 1.0))]
        local_A = g.rng.choice(([corner[0] * 3, corner[1] * 2], [corner[0], 0.5],
                                [0.25, corner[1]]))
        P = world([local_A[0] * sizes[0], local_A[1] * sizes[1]])
        Q = world([corner[0] * sizes[0], corner[1] * sizes[1]])
        u = [q - p for p, q in zip(P, Q)]
        if all(x == 0 for x in u):
            u = [1.0, 0.0]
        fig = {"kind": "ray_rectangle", "A": P, "u": u, "C": [0.0, 0.0], "half": sizes,
               "angle": angle}
    key = g.rng.choice(("A", "u"))
    fig[key] = nudge_one(g, fig[key])
    return fig, True


def issue_examples(g):
    """The lines of issue 15 that epure once got wrong."""
    return json.loads(g.rng.choice(ISSUE_15)), True


ISSUE_15 = (
    '{"kind":"segments","A":[0,0],"B":[1,0],"C":[2,1e-14],"D":[3,2e-14]}',
    '{"kind":"segments","A":[7,5],"B":[4,5],"C":[7.5,4.999999999999943],"D":[4.5,5]}',
    '{"kind":"ray_circle","A":[-5,1],"u":[1,0],"C":[0,0],"r":1.000000000000001}',
    '{"kind":"ray_circle","A":[-5,1],"u":[1,0],"C":[0,0],"r":0.999999999999999}',
    '{"kind":"ray_circle","A":[3,-6],"u":[-8.470329472543003e-22,1.9073486328125e-06],'
    '"C":[5,-6],"r":2}',
    '{"kind":"ray_square","A":[0,-5],"u":[-0.0009765625000000002,0.00390625]}',
    '{"kind":"projection","A":[0,0],"B":[1,0],"C":[-1e-15,5]}',
    '{"kind":"segments","A":[0,0],"B":[4,0],"C":[1,0],"D":[3,1e-14]}',
    '{"kind":"ray_circle","A":[0,2.9999999999999996],"u":[1,0],"C":[0,0],"r":3}',
    '{"kind":"ray_square","A":[-0.9999999999999999,0],"u":[0,1]}',
    '{"kind":"ray_circle","A":[-15,-13],"u":[-1.4305114518720075e-05,7.62939453125e-06],'
    '"C":[-7,2],"r":17}',
)


FIGURES = (
    (1, vectors), (1, projection), (2, segments), (2, lambda g: ball(g, 2)),
    (2, lambda g: box(g, 2)), (2, ellipse), (2, rectangle), (2, lambda g: ball(g, 3)),
    (2, lambda g: box(g, 3)),
    # at 1, 2 and 3 ulps from a boundary: as many again, unfiltered
    (2, boundary_projection), (3, boundary_segments), (3, lambda g: boundary_ball(g, 2)),
    (3, lambda g: boundary_box(g, 2)), (2, lambda g: boundary_ball(g, 3)),
    (2, lambda g: boundary_box(g, 3)), (2, boundary_transformed), (0.3, issue_examples),
)


# ---- bad lines -------------------------------------------------------------------------------

def bad_line(g, good):
    """Text of a line that must fail, from a good figure of the same kind."""
    kind = good["kind"]
    fields = FIELDS[kind]
    how = g.rng.choice(("json", "object", "kind", "missing", "type", "arity", "finite",
                        "degenerate", "degenerate"))
    fig = dict(good)
    name = g.rng.choice(sorted(fields))
    if how == "json":
        text = dump(good, g.rng, False)
        return g.rng.choice((text[:-1], text[: len(text) // 2], text + " x",
                             text.replace('"', "", 2), text.replace(",", ",,", 1), "hello",
                             "{'kind': 'vectors'}", "{", "}"))
    if how == "object":
        return g.rng.choice(("[1,2,3]", "42", '"ray_circle"', "null", "true",
                             "[" + dump(good, g.rng, False) + "]"))
    if how == "kind":
        choice = g.rng.randrange(4)
        if choice == 0:
            del fig["kind"]
        else:
            wrong = ("ray_torus", "Vectors", "", 3, ["vectors"])[g.rng.randrange(5)]
            fig["kind"] = wrong if choice > 1 else kind + " "
        return dump(fig, g.rng, False)
    if how == "missing":
        del fig[name]
        return dump(fig, g.rng, False)
    if how == "type":
        n = fields[name]
        if n and g.rng.random() < 0.5:
            i = g.rng.randrange(n)
            fig[name] = list(fig[name])
            fig[name][i] = g.rng.choice(("1", True, None, [1.0], {"x": 1}))
        else:
            fig[name] = g.rng.choice(("north", True, False, None, {"x": 1.0}) +
                                     ((1.0,) if n else ([1.0],)))
        return dump(fig, g.rng, False)
    if how == "arity":
        candidates = [k for k, n in fields.items() if n]
        name = g.rng.choice(candidates)
        n = fields[name]
        fig[name] = g.rng.choice(([], [1.0], [1.0] * (n + 1), [1.0] * (5 - n)))
        return dump(fig, g.rng, False)
    if how == "finite":
        numeric = [k for k in fields if k != "kind"]
        name = g.rng.choice(numeric)
        big = raw(g.rng.choice(("1e999", "-1e999", "1E400")))
        if fields[name]:
            fig[name] = list(fig[name])
            fig[name][g.rng.randrange(fields[name])] = big
        else:
            fig[name] = big
        return dump(fig, g.rng, False)
    # a degenerate figure of this kind
    if kind == "vectors":
        fig[g.rng.choice(("u", "v"))] = g.rng.choice(([0.0, 0.0], [-0.0, 0.0], [0, -0.0]))
    elif kind == "projection":
        fig["B"] = list(fig["A"])
    elif kind == "segments":
        if g.rng.random() < 0.5:
            fig["B"] = list(fig["A"])
        else:
            fig["D"] = list(fig["C"])
    elif kind in ("ray_square", "ray_cube") or g.rng.random() < 0.3:
        fig["u"] = [g.rng.choice((0.0, -0.0)) for _ in fig["u"]]
    elif kind in ("ray_circle", "ray_sphere"):
        fig["r"] = g.rng.choice((0.0, -0.0, -1.0, -1e-300, -fig["r"]))
    else:
        key = "radii" if kind == "ray_ellipse" else "half"
        fig[key] = list(fig[key])
        fig[key][g.rng.randrange(2)] = g.rng.choice((0.0, -0.0, -1.0, -fig[key][0]))
    return dump(fig, g.rng, False)


# ---- the stream ------------------------------------------------------------------------------

def figure(g):
    total = sum(w for w, _ in FIGURES)
    pick = g.rng.uniform(0, total)
    for w, make in FIGURES:
        pick -= w
        if pick <= 0:
            break
    while True:
        fig, is_exact = make(g)
        if is_exact or robust(fig, g.rng):
            return fig


def lines(seed, count):
    g = Cases(random.Random(seed))
    produced = 0
    while produced < count:
        roll = g.rng.random()
        if roll < 0.02:
            yield g.rng.choice(("", "   ", "\t", " \t "))
        elif roll < 0.12:
            yield bad_line(g, figure(g))
        else:
            fig = figure(g)
            if g.rng.random() < 0.1:
                items = list(fig.items())
                g.rng.shuffle(items)
                fig = dict(items)
            yield dump(fig, g.rng, g.rng.random() < 0.2)
        produced += 1


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: adversarial_cases.py SEED N")
    for line in lines(int(sys.argv[1]), int(sys.argv[2])):
        print(line)


if __name__ == "__main__":
    main()
