#!/usr/bin/env python3
"""An independent reference for the `epure solve` contract, in exact arithmetic.

usage: reference_solve.py [FILE]     (JSON Lines on FILE or stdin; results on stdout)
Exit status 1 when some line is bad, as `epure solve`.

Written from the contract (issue 3, README "epure solve"), not from epure's C++. Every input
number is taken as the exact decimal it writes (fractions.Fraction of the JSON number's text,
"0.1" is one tenth: README, one meaning for a number) and every branch is decided on exact
rationals: "strictly inside", "behind", "tangent", "parallel" mean exactly what they say,
without tolerance. Square roots (lengths, the half chord) and the cosine and sine of a rotation
that is not a multiple of 90° are the only inexact steps: they are carried in decimal.Decimal at
80 significant digits, far beyond the double each result is rounded to at the end.

The methods are deliberately not epure's: the circle and sphere by the quadratic in t, the
square and cube by the slab method, the ellipse and rectangle by carrying the ray into the
figure's axes (exact when the angle is a multiple of 90°) and using the implicit equation or the
slabs there.

As a module: `solve_object(dict) -> dict` for parsed figures whose numbers may be floats, ints
or Fractions (the adversarial generator perturbs figures exactly); a result key starting with
'_' is private to the generator and is not part of the contract.
"""
import json
import math
import sys
from decimal import Decimal, getcontext
from fractions import Fraction

getcontext().prec = 80


class BadLine(Exception):
    """The line is not a valid solve input; the message names the field."""


# ---- reading fields --------------------------------------------------------------------------

def written(text):
    """A JSON number's text as the exact decimal it writes; beyond the doubles, not finite."""
    if not math.isfinite(float(text)):
        return float("inf")
    return Fraction(text)


def exact(value, field):
    """A JSON number as the exact rational it denotes (lines are read with `written`; a float
    given by a caller is the double itself)."""
    if isinstance(value, bool) or not isinstance(value, (int, float, Fraction)):
        raise BadLine(f"field '{field}': expected a number, got {type(value).__name__}")
    if isinstance(value, Fraction):
        return value
    try:
        x = float(value)  # JSON integers are read as doubles too
    except OverflowError:
        raise BadLine(f"field '{field}': not a finite number") from None
    if not math.isfinite(x):
        raise BadLine(f"field '{field}': not a finite number")
    return Fraction(x)


def field(figure, name):
    if name not in figure:
        raise BadLine(f"field '{name}': missing")
    return figure[name]


def number(figure, name):
    return exact(field(figure, name), name)


def vector(figure, name, n):
    value = field(figure, name)
    if not isinstance(value, list):
        raise BadLine(f"field '{name}': expected an array of {n} numbers")
    if len(value) != n:
        raise BadLine(f"field '{name}': expected {n} numbers, got {len(value)}")
    return tuple(exact(x, name) for x in value)


def nonzero(v, name):
    if all(c == 0 for c in v):
        raise BadLine(f"field '{name}': zero direction")
    return v


def positive(x, name):
    if x <= 0:
        raise BadLine(f"field '{name}': must be > 0")
    return x


# ---- arithmetic ------------------------------------------------------------------------------

class Surd:
    """p + q·√k exactly (p, q Fractions, k = 2 or 3): cos and sin of a multiple of 45° or 30°
    with the data, so that a figure turned by such an angle is decided exactly."""

    def __init__(self, p, q=0, k=2):
        self.p, self.q, self.k = Fraction(p), Fraction(q), k

    def _of(self, x):
        return x if isinstance(x, Surd) else Surd(x, 0, self.k)

    def __add__(self, o):
        o = self._of(o)
        return Surd(self.p + o.p, self.q + o.q, self.k)

    __radd__ = __add__

    def __neg__(self):
        return Surd(-self.p, -self.q, self.k)

    def __sub__(self, o):
        return self + -self._of(o)

    def __rsub__(self, o):
        return self._of(o) - self

    def __mul__(self, o):
        o = self._of(o)
        return Surd(self.p * o.p + self.k * self.q * o.q, self.p * o.q + self.q * o.p, self.k)

    __rmul__ = __mul__

    def __truediv__(self, o):
        o = self._of(o)
        norm = o.p * o.p - o.k * o.q * o.q  # rational, nonzero for o ≠ 0 (√k irrational)
        return self * Surd(o.p / norm, -o.q / norm, self.k)

    def __rtruediv__(self, o):
        return self._of(o) / self

    def sign(self):
        sp, sq = (self.p > 0) - (self.p < 0), (self.q > 0) - (self.q < 0)
        if sq == 0 or sp == sq:
            return sp or sq
        if sp == 0:
            return sq
        d = self.p * self.p - self.k * self.q * self.q
        return sp * ((d > 0) - (d < 0))

    def _cmp(self, o):
        return (self - self._of(o)).sign()

    def __lt__(self, o): return self._cmp(o) < 0
    def __le__(self, o): return self._cmp(o) <= 0
    def __gt__(self, o): return self._cmp(o) > 0
    def __ge__(self, o): return self._cmp(o) >= 0
    def __eq__(self, o): return self._cmp(o) == 0
    def __ne__(self, o): return self._cmp(o) != 0
    __hash__ = None

    def decimal(self):
        return dec(self.p) + dec(self.q) * Decimal(self.k).sqrt()

    def __float__(self):
        return float(self.decimal())


def dec(x):
    """Fraction, int, Surd or Decimal as a Decimal (rounded to the context's 80 digits)."""
    if isinstance(x, Decimal):
        return x
    if isinstance(x, Surd):
        return x.decimal()
    if isinstance(x, Fraction):
        return Decimal(x.numerator) / Decimal(x.denominator)
    return Decimal(x)


def sqrt(x):
    # an exact Surd ≥ 0 may round below 0 in 80 digits when it is 0
    return max(dec(x), Decimal(0)).sqrt()


def out(x):
    """The double nearest to an exact or 80-digit value (float() rounds both correctly)."""
    return float(x)


def sub(p, q):
    return tuple(a - b for a, b in zip(p, q))


def add(p, q):
    return tuple(a + b for a, b in zip(p, q))


def scale(k, v):
    return tuple(k * c for c in v)


def dot(u, v):
    return sum((a * b for a, b in zip(u, v)), Fraction(0))


def cross2(u, v):
    return u[0] * v[1] - u[1] * v[0]


def cross3(u, v):
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def outs(v):
    return [out(c) for c in v]


# ---- the kinds -------------------------------------------------------------------------------

def solve_vectors_3d(f):
    # in space: u∧v a vector, sin = ‖u∧v‖/(‖u‖‖v‖) ≥ 0, the unsigned angle
    u = nonzero(vector(f, "u", 3), "u")
    v = nonzero(vector(f, "v", 3), "v")
    d, w = dot(u, v), cross3(u, v)
    nu, nv, nw = sqrt(dot(u, u)), sqrt(dot(v, v)), sqrt(dot(w, w))
    cos, sin = dec(d) / (nu * nv), nw / (nu * nv)
    if all(c == 0 for c in w):
        angle = 0.0 if d > 0 else 180.0
    else:
        angle = math.degrees(math.atan2(out(sin), out(cos)))
    return {"dot": out(d), "cross": outs(w), "norm_u": out(nu), "norm_v": out(nv), "cos": out(cos),
            "sin": out(sin), "angle_deg": angle,
            # the contract's decisions, exact on the decimals: 0.3·(0.1, 0.2, 0.3) is collinear
            "collinear": all(c == 0 for c in w), "orthogonal": d == 0}


def solve_vectors(f):
    if isinstance(f.get("u"), list) and len(f["u"]) == 3:
        return solve_vectors_3d(f)
    u = nonzero(vector(f, "u", 2), "u")
    v = nonzero(vector(f, "v", 2), "v")
    d, c = dot(u, v), cross2(u, v)
    nu, nv = sqrt(dot(u, u)), sqrt(dot(v, v))
    # The angle from the exact sign of the cross product: exactly opposite vectors give 180.
    if c == 0:
        angle = 0.0 if d > 0 else 180.0
    else:
        # atan2 of the correctly rounded cos and sin is within an ulp or two of the angle.
        angle = math.degrees(math.atan2(out(dec(c) / (nu * nv)), out(dec(d) / (nu * nv))))
        if angle <= -180.0:  # |sin| below the smallest double: the angle is -180 + 0
            angle = -math.nextafter(180.0, 0.0)
    return {"dot": out(d), "cross": out(c), "norm_u": out(nu), "norm_v": out(nv),
            "cos": out(dec(d) / (nu * nv)), "sin": out(dec(c) / (nu * nv)), "angle_deg": angle,
            "_angle_positive": c > 0 or (c == 0 and d < 0)}


def solve_projection(f):
    A, B, C = vector(f, "A", 2), vector(f, "B", 2), vector(f, "C", 2)
    AB, AC = sub(B, A), sub(C, A)
    if AB == (0, 0):
        raise BadLine("field 'B': degenerate segment, A = B")
    t = dot(AB, AC) / dot(AB, AB)
    position = "before" if t < 0 else "after" if t > 1 else "between"
    return {"t": out(t), "P": outs(add(A, scale(t, AB))), "position": position}


def solve_segments(f):
    A, B, C, D = (vector(f, k, 2) for k in "ABCD")
    AB, CD, AC = sub(B, A), sub(D, C), sub(C, A)
    if AB == (0, 0):
        raise BadLine("field 'B': degenerate segment, A = B")
    if CD == (0, 0):
        raise BadLine("field 'D': degenerate segment, C = D")
    den = cross2(AB, CD)
    if den == 0:
        # Parallel lines: the same line exactly when C lies on (AB).
        reason = "collinear" if cross2(AB, AC) == 0 else "parallel"
        return {"intersects": False, "reason": reason}
    # A + t·AB = C + s·CD; cross with CD, then with AB.
    t_ab = cross2(AC, CD) / den
    t_cd = cross2(AC, AB) / den
    if 0 <= t_ab <= 1 and 0 <= t_cd <= 1:
        return {"intersects": True, "t_ab": out(t_ab), "t_cd": out(t_cd),
                "I": outs(add(A, scale(t_ab, AB)))}
    return {"intersects": False, "reason": "outside", "t_ab": out(t_ab), "t_cd": out(t_cd)}


def solve_ball(f, dim):
    """Circle or sphere: |A + s·u − C|² = r², a quadratic in s (the parameter along u)."""
    A, u = vector(f, "A", dim), vector(f, "u", dim)
    C, r = vector(f, "C", dim), number(f, "r")
    nonzero(u, "u")
    positive(r, "r")
    AC = sub(C, A)
    uu, ua, ac2, r2 = dot(u, u), dot(u, AC), dot(AC, AC), r * r
    norm_u = sqrt(uu)
    d2 = ac2 - ua * ua / uu  # |AC|² − t_proj², exactly (Pythagoras on the unit direction)
    inside = ac2 < r2
    res = {"t_proj": out(dec(ua) / norm_u), "d2": out(d2), "inside": inside}
    if not inside and ua < 0:
        return {**res, "hit": False, "reason": "behind"}
    if d2 > r2:
        return {**res, "hit": False, "reason": "miss"}
    # s² uu − 2 s ua + (ac2 − r2) = 0: roots (ua ∓ √disc) / uu, disc = ua² − uu (ac2 − r2) ≥ 0.
    disc = ua * ua - uu * (ac2 - r2)
    root = sqrt(disc)
    if inside:
        # the larger root; when ua < 0 the product form avoids cancelling
        s = (dec(ua) + root) / dec(uu) if ua >= 0 else dec(r2 - ac2) / (root - dec(ua))
    else:
        # the smaller root, ua ≥ 0 here: (ac2 − r2) / (ua + √disc), zero on the boundary
        s = dec(ac2 - r2) / (dec(ua) + root) if ac2 > r2 else Decimal(0)
    I = tuple(dec(a) + s * dec(c) for a, c in zip(A, u))
    N = tuple((i - dec(c)) / dec(r) for i, c in zip(I, C))
    return {**res, "hit": True, "t": out(s * norm_u), "I": outs(I), "N": outs(N)}


AXES = "xyz"


def box_faces(A, half):
    """The sides whose closed outer half-space contains A."""
    faces = []
    for k, a in enumerate(A):
        if a >= half[k]:
            faces.append("+" + AXES[k])
        if a <= -half[k]:
            faces.append("-" + AXES[k])
    return faces


def slab(A, u, half):
    """The slab method on the box Π[−half_k, half_k] (closed), for the parameter s along u.

    Returns (inside, s, axis, sign) of the hit, or (inside, None, None, None). From outside the
    ray hits where it enters the box, if that is at s ≥ 0 (a ray on the boundary heading in enters
    at s = 0; heading out, it entered at s < 0 and does not hit); from inside it hits where it
    leaves."""
    inside = all(-h < a < h for a, h in zip(A, half))
    enter, leave = None, None  # (s, axis, sign of the side's outer normal)
    for k, (a, c, h) in enumerate(zip(A, u, half)):
        if c == 0:
            if a < -h or a > h:
                return inside, None, None, None
            continue
        s_lo, s_hi = (-h - a) / c, (h - a) / c
        lo, hi = ((s_lo, k, -1), (s_hi, k, +1)) if c > 0 else ((s_hi, k, +1), (s_lo, k, -1))
        if enter is None or lo[0] > enter[0]:
            enter = lo
        if leave is None or hi[0] < leave[0]:
            leave = hi
    if inside:
        return inside, leave[0], leave[1], leave[2]
    if enter[0] <= leave[0] and enter[0] >= 0:
        return inside, enter[0], enter[1], enter[2]
    return inside, None, None, None


def solve_box(f, dim):
    A, u = vector(f, "A", dim), nonzero(vector(f, "u", dim), "u")
    half = (Fraction(1),) * dim
    inside, s, axis, sign = slab(A, u, half)
    res = {"faces": box_faces(A, half), "inside": inside, "hit": s is not None}
    if s is None:
        return res
    I = add(A, scale(s, u))
    N = tuple(Fraction(sign) if k == axis else Fraction(0) for k in range(dim))
    return {**res, "t": out(dec(s) * sqrt(dot(u, u))), "I": outs(I), "N": outs(N),
            "_side": (axis, sign)}


PI = Decimal("3.14159265358979323846264338327950288419716939937510582097494459230781640628620899")


def cos_sin_degrees(angle):
    """cos and sin of an angle in degrees: exact Fractions for multiples of 90°, exact Surds for
    multiples of 45° and 30°, else Decimals."""
    a = angle % 360  # exact on rationals
    if a % 90 == 0:
        return {0: (Fraction(1), Fraction(0)), 90: (Fraction(0), Fraction(1)),
                180: (Fraction(-1), Fraction(0)), 270: (Fraction(0), Fraction(-1))}[int(a)]
    h = Fraction(1, 2)
    if a % 45 == 0:
        cs, ss = (1 if a in (45, 315) else -1), (1 if a < 180 else -1)
        return Surd(0, cs * h, 2), Surd(0, ss * h, 2)
    if a % 30 == 0:
        r3 = {30: (Surd(0, h, 3), Surd(h, 0, 3)), 60: (Surd(h, 0, 3), Surd(0, h, 3))}
        first = a if a < 90 else 180 - a if a < 180 else a - 180 if a < 270 else 360 - a
        c, s = r3[int(first)]
        cs, ss = (1 if a < 90 or a > 270 else -1), (1 if a < 180 else -1)
        return cs * c, ss * s
    if a > 180:
        a -= 360
    x = dec(a) * PI / 180
    # Taylor series, |x| ≤ π: summed until the terms fall below 1e-90.
    c, s, term, k = Decimal(0), Decimal(0), Decimal(1), 0
    while abs(term) > Decimal("1e-90"):
        c += term if k % 4 == 0 else -term if k % 4 == 2 else 0
        s += term if k % 4 == 1 else -term if k % 4 == 3 else 0
        k += 1
        term = term * x / k
    return c, s


def to_frame(f):
    """A and u carried into the figure's axes: A' = R(−θ)(A − C), u' = R(−θ)u. Exact when
    the angle is a multiple of 90°; in 80-digit decimals otherwise."""
    A, u, C = vector(f, "A", 2), nonzero(vector(f, "u", 2), "u"), vector(f, "C", 2)
    angle = number(f, "angle")
    c, s = cos_sin_degrees(angle)
    conv = (lambda x: x) if isinstance(c, (Fraction, Surd)) else dec
    A, u, C = tuple(map(conv, A)), tuple(map(conv, u)), tuple(map(conv, C))
    p = sub(A, C)
    local = lambda v: (c * v[0] + s * v[1], -s * v[0] + c * v[1])
    dc, ds = dec(c), dec(s)
    # back to the world: a direction (the normal), inexact anyway once normalised
    world = lambda v: (dc * dec(v[0]) - ds * dec(v[1]), ds * dec(v[0]) + dc * dec(v[1]))
    return A, u, local(p), local(u), world


def unit(v):
    n = sqrt(dec(v[0]) * dec(v[0]) + dec(v[1]) * dec(v[1]))
    return tuple(dec(x) / n for x in v)


def solve_ellipse(f):
    radii = vector(f, "radii", 2)
    positive(radii[0], "radii")
    positive(radii[1], "radii")
    if radii[0] == radii[1]:
        # equal radii: a circle whatever the angle, decided exactly on the decimals (an 80-digit
        # cosine would turn a tangent line into a near one)
        number(f, "angle")
        circle = solve_ball({"A": f["A"], "u": f["u"], "C": f["C"], "r": radii[0]}, 2)
        return {k: v for k, v in circle.items() if k in ("inside", "hit", "t", "I", "N")}
    A, u, p, q, world = to_frame(f)
    conv = (lambda x: x) if isinstance(p[0], (Fraction, Surd)) else dec
    a2, b2 = conv(radii[0]) ** 2, conv(radii[1]) ** 2
    # (p + s q) on x²/a² + y²/b² = 1:  α s² + 2β s + γ = 0
    alpha = q[0] * q[0] / a2 + q[1] * q[1] / b2
    beta = p[0] * q[0] / a2 + p[1] * q[1] / b2
    gamma = p[0] * p[0] / a2 + p[1] * p[1] / b2 - 1
    inside = gamma < 0
    res = {"inside": inside}
    disc = beta * beta - alpha * gamma
    # From outside (γ ≥ 0) both roots have the sign of −β: heading away (β > 0) is no hit, as a
    # circle's "behind"; a negative discriminant misses; a zero one is tangent, a hit.
    if not inside and (beta > 0 or disc < 0):
        return {**res, "hit": False}
    root = sqrt(disc)
    B, G, Al = dec(beta), dec(gamma), dec(alpha)
    if inside:
        s = (root - B) / Al if beta <= 0 else -G / (B + root)
    else:
        s = G / (root - B) if gamma > 0 else Decimal(0)
    I = tuple(dec(a) + s * dec(c) for a, c in zip(A, u))
    local_i = (dec(p[0]) + s * dec(q[0]), dec(p[1]) + s * dec(q[1]))
    n_local = (local_i[0] / dec(a2), local_i[1] / dec(b2))  # the gradient of the equation
    N = unit(world(n_local))
    return {**res, "hit": True, "t": out(s * sqrt(dec(u[0]) ** 2 + dec(u[1]) ** 2)),
            "I": outs(I), "N": outs(N)}


def solve_rectangle(f):
    half = vector(f, "half", 2)
    positive(half[0], "half")
    positive(half[1], "half")
    A, u, p, q, world = to_frame(f)
    conv = (lambda x: x) if isinstance(p[0], (Fraction, Surd)) else dec
    inside, s, axis, sign = slab(p, q, tuple(map(conv, half)))
    res = {"inside": inside, "hit": s is not None}
    if s is None:
        return res
    I = add(A, scale(s, u))
    N = world((sign, 0) if axis == 0 else (0, sign))
    return {**res, "t": out(dec(s) * sqrt(dec(u[0]) ** 2 + dec(u[1]) ** 2)), "I": outs(I),
            "N": outs(unit(N)), "_side": (axis, sign)}


SOLVERS = {
    "vectors": solve_vectors,
    "projection": solve_projection,
    "segments": solve_segments,
    "ray_circle": lambda f: solve_ball(f, 2),
    "ray_square": lambda f: solve_box(f, 2),
    "ray_ellipse": solve_ellipse,
    "ray_rectangle": solve_rectangle,
    "ray_sphere": lambda f: solve_ball(f, 3),
    "ray_cube": lambda f: solve_box(f, 3),
}


# The fields each kind scales together (its figure: points and sizes) and the ones it scales
# alone (directions, vectors); an angle is no length. The square's and the cube's half side, 1,
# is a size of their figure.
SCALED = {
    "vectors": ([], ["u", "v"], 0), "projection": (["A", "B", "C"], [], 0),
    "segments": (["A", "B", "C", "D"], [], 0), "ray_circle": (["A", "C", "r"], ["u"], 0),
    "ray_sphere": (["A", "C", "r"], ["u"], 0), "ray_square": (["A"], ["u"], 1),
    "ray_cube": (["A"], ["u"], 1), "ray_ellipse": (["A", "C", "radii"], ["u"], 0),
    "ray_rectangle": (["A", "C", "half"], ["u"], 0),
}


def number_span(figure, kind):
    """The contract's one limit (README, Accurate values): a line is refused when the smallest
    non-zero number of a group, scaled by the power of two that brings the group's largest into
    [1, 2), has a square below 2^-969 (products of the line's numbers would underflow). A number
    whose double is zero is below every double."""
    def numbers(name):
        v = figure.get(name)
        items = v if isinstance(v, list) else [v]
        return [x for x in items if isinstance(x, (int, float, Fraction)) and not isinstance(x, bool)
                and math.isfinite(x) and x != 0]

    def check(names, size):
        largest, smallest, at = float(size), None, None
        for name in names:
            for x in numbers(name):
                h = abs(float(x))
                largest = max(largest, h)
                small = h if h != 0 else 2.0 ** -1075
                if smallest is None or small < smallest:
                    smallest, at = small, name
        if smallest is None:
            return
        scaled = math.ldexp(smallest, -(math.frexp(largest)[1] - 1)) if largest > 0 else 0.0
        if scaled * scaled < 2.0 ** -969:
            raise BadLine(f"field '{at}': too small beside the largest number it is scaled with "
                          "(products would underflow)")

    figure_names, alone, size = SCALED[kind]
    for name in alone:
        check([name], 0)
    check(figure_names, size)


def solve_object(figure):
    """The result of one parsed line, with private '_' keys; raises BadLine."""
    if not isinstance(figure, dict):
        raise BadLine("line: expected a JSON object")
    kind = field(figure, "kind")
    if not isinstance(kind, str):
        raise BadLine("field 'kind': expected a string")
    if kind not in SOLVERS:
        raise BadLine(f"field 'kind': unknown kind '{kind}'")
    result = SOLVERS[kind](figure)  # its own refusals first (a radius ≤ 0, a degenerate figure)
    number_span(figure, kind)
    return {"kind": kind, **result}


def solve_line(line):
    """(result text, ok) for one non-blank line."""
    try:
        try:
            figure = json.loads(line, parse_float=written, parse_int=written)
        except ValueError as e:
            raise BadLine(f"line: not valid JSON ({e})") from None
        result = solve_object(figure)
    except BadLine as e:
        return json.dumps({"error": str(e)}), False
    return json.dumps({k: v for k, v in result.items() if not k.startswith("_")},
                      separators=(",", ":")), True


def is_blank(line):
    return line.strip(" \t\r") == ""


def main():
    # bytes, split on '\n' only, as epure reads them (a lone '\r' is not a line break)
    data = open(sys.argv[1], "rb").read() if len(sys.argv) > 1 else sys.stdin.buffer.read()
    failed = False
    results = []
    for line in data.decode("utf-8", errors="replace").split("\n"):
        line = line[:-1] if line.endswith("\r") else line
        if is_blank(line):
            continue
        text, ok = solve_line(line)
        failed |= not ok
        results.append(text)
    sys.stdout.write("".join(r + "\n" for r in results))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
