#!/usr/bin/env python3
"""Figures degenerate as the decimals written, and not as their doubles (issue 35).

usage: decimal_cases.py SEED N [--long]      (prints N lines of JSON Lines)

A number means the decimal written ("0.1" is one tenth: README, one meaning for a number). Every
figure here is exactly on a boundary as decimals: segments parallel or collinear, meeting at
t = 0 or t = 1 exactly, a projection foot on an end, a ray tangent to a circle or a sphere, an
origin on the circle or the sphere, a ray through a corner of the square or an edge of the
cube, vectors collinear or orthogonal, at every scale from 1e-8 to 1e8 and far from the origin.
Their doubles are rounded, so that the same figure in binary is off the boundary (most lines) or
on it by chance: an answer that decides on the doubles gets them wrong.

--long: the same figures with 18 to 25 significant digits a number (more than a double holds),
six in ten moved a hair (one unit of a 18th to 30th digit) off their boundary: their values are
made of the digits beyond the doubles.

Deterministic for a seed (random.Random(SEED)). The coordinates are integers on a decimal grid
10^(s-d) (d decimals at the scale 10^s), written exactly ("-4.217e-6", "812.5").
"""
import json
import math
import random
import sys
from fractions import Fraction


def text(x):
    """The exact decimal text of a Fraction whose denominator divides a power of ten."""
    x = Fraction(x)
    if x == 0:
        return "0"
    sign = "-" if x < 0 else ""
    x = abs(x)
    k = 0
    while (x * 10**k).denominator != 1:
        k += 1
        if k > 60:
            raise ValueError(f"not a decimal: {x}")
    digits = str(int(x * 10**k))
    # digits·10^-k, written with an exponent when that is shorter
    exponent = -k
    while digits.endswith("0") and len(digits) > 1:
        digits = digits[:-1]
        exponent += 1
    if -25 <= exponent <= 0 and len(digits) + (-exponent) < 30:
        if exponent == 0:
            return sign + digits
        if len(digits) > -exponent:
            return sign + digits[:exponent] + "." + digits[exponent:]
        return sign + "0." + "0" * (-exponent - len(digits)) + digits
    if 0 < exponent <= 8:
        return sign + digits + "0" * exponent
    mantissa = digits[0] + ("." + digits[1:] if len(digits) > 1 else "")
    return f"{sign}{mantissa}e{exponent + len(digits) - 1}"


def is_double(x):
    return Fraction(float(x)) == x


class Gen:
    def __init__(self, seed):
        self.rng = random.Random(seed)

    def scale(self):
        # the grid step: 10^(s - d), s the figure's decade, d its decimals (1 to 4)
        s = self.rng.randint(-8, 8)
        d = self.rng.randint(1, 4)
        return Fraction(10) ** (s - d), Fraction(10) ** s

    def integer(self, n):
        return self.rng.randint(-n, n)

    def grid_point(self, step, dim, n=99999):
        return tuple(step * self.integer(n) for _ in range(dim))

    def far(self, step, dim):
        # the figure far from the origin one time in four: 1e4 grid steps beyond it
        if self.rng.random() < 0.25:
            return tuple(step * self.integer(10**7) for _ in range(dim))
        return (0,) * dim

    def vector(self, step, dim, n=999):
        while True:
            v = tuple(step * self.integer(n) for _ in range(dim))
            if any(c != 0 for c in v):
                return v


def add(p, v, k=1):
    return tuple(a + k * b for a, b in zip(p, v))


def line(kind, **fields):
    parts = [f'"kind":"{kind}"']
    for name, value in fields.items():
        if isinstance(value, tuple):
            parts.append(f'"{name}":[' + ",".join(text(c) for c in value) + "]")
        else:
            parts.append(f'"{name}":{text(value)}')
    return "{" + ",".join(parts) + "}"


def segments(g):
    step, _ = g.scale()
    o = g.far(step, 2)
    A = add(o, g.grid_point(step, 2))
    w = g.vector(step, 2)
    B = add(A, w, g.rng.randint(1, 9))
    case = g.rng.choice(["parallel", "collinear", "t0", "t1", "cd0"])
    if case == "parallel":
        C = add(A, g.vector(step, 2))
        D = add(C, w, g.rng.choice([-3, -2, -1, 1, 2, 3]) * Fraction(g.rng.randint(1, 9), 10))
    elif case == "collinear":
        C = add(A, w, g.rng.randint(-5, 5))
        D = add(C, w, g.rng.choice([-2, -1, 1, 2]) * Fraction(g.rng.randint(1, 9), 10))
    else:
        # a second line through A (t_ab = 0), through B (t_ab = 1), or from C on AB (t_cd = 0)
        v = g.vector(step, 2)
        while v[0] * w[1] - v[1] * w[0] == 0:
            v = g.vector(step, 2)
        at = A if case == "t0" else B if case == "t1" else add(A, w, Fraction(g.rng.randint(1, 9), 10))
        if case == "cd0":
            C, D = at, add(at, v, g.rng.randint(1, 5))
        else:
            k = g.rng.randint(1, 5)
            C, D = add(at, v, -k), add(at, v, g.rng.randint(1, 5))
    if C == D:
        D = add(C, w)
    return line("segments", A=A, B=B, C=C, D=D)


def projection(g):
    step, _ = g.scale()
    o = g.far(step, 2)
    A = add(o, g.grid_point(step, 2))
    w = g.vector(step, 2)
    B = add(A, w, g.rng.randint(1, 5))
    foot = A if g.rng.random() < 0.5 else B
    n = (-w[1], w[0])
    C = add(foot, n, Fraction(g.rng.randint(-30, 30), 10))
    return line("projection", A=A, B=B, C=C)


# Pythagorean directions: unit vectors with rational (decimal, once times 5, 13, 3 or 7) coordinates
UNIT2 = [(Fraction(3, 5), Fraction(4, 5)), (Fraction(5, 13), Fraction(12, 13)), (Fraction(1), Fraction(0))]
UNIT3 = [(Fraction(1, 3), Fraction(2, 3), Fraction(2, 3)), (Fraction(2, 7), Fraction(3, 7), Fraction(6, 7)),
         (Fraction(0), Fraction(0), Fraction(1))]


def signed(g, v):
    v = list(v)
    g.rng.shuffle(v)
    return tuple(c * g.rng.choice([-1, 1]) for c in v)


def ball(g, dim):
    step, _ = g.scale()
    o = g.far(step, dim)
    C = add(o, g.grid_point(step, dim))
    # r a multiple of 5·13·3·7 grid steps: r times a Pythagorean unit vector is on the grid
    r = step * 1365 * g.rng.randint(1, 40)
    n = signed(g, g.rng.choice(UNIT2 if dim == 2 else UNIT3))
    case = g.rng.choice(["tangent", "on", "on_out"])
    if case == "tangent":
        # the ray along t ⟂ n through the point C + r·n
        if dim == 2:
            t = (-n[1], n[0])
        else:
            # a vector orthogonal to n with rational coordinates: n × e_k
            e = min(range(3), key=lambda k: abs(n[k]))
            ek = tuple(Fraction(1 if i == e else 0) for i in range(3))
            t = (n[1] * ek[2] - n[2] * ek[1], n[2] * ek[0] - n[0] * ek[2], n[0] * ek[1] - n[1] * ek[0])
        T = add(C, n, r)
        s = Fraction(g.rng.randint(2, 40), 10) * r
        A = add(T, t, -s)
        u = tuple(c * step * g.rng.randint(1, 999) * 21 for c in t)  # on the grid: 21 = 3·7
    else:
        A = add(C, n, r)
        inward = tuple(-c for c in n) if case == "on" else n
        u = tuple(step * (g.integer(99) + 400 * c) for c in inward)
    u = tuple(Fraction(round(c / step * 10**4)) * step / 10**4 for c in u)  # decimals, every one
    if all(c == 0 for c in u):
        u = (step,) + (0,) * (dim - 1)
    return line("ray_circle" if dim == 2 else "ray_sphere", A=A, u=u, C=C, r=r)


def box(g, dim):
    if g.rng.random() < 0.3:
        # A a decimal hair (1e-17 to 1e-25) off a side, whose double is on it: a candidate side
        # or not, inside or outside, as written
        k = g.rng.randrange(dim)
        hair = Fraction(g.rng.choice([-1, 1]), 10 ** g.rng.randint(17, 25))
        A = tuple(g.rng.choice([-1, 1]) + hair if i == k else Fraction(g.rng.randint(-9, 9), 10) for i in range(dim))
        u = tuple(Fraction(g.rng.randint(-9, 9) or 1, 10 ** g.rng.randint(0, 3)) for _ in range(dim))
        return line("ray_square" if dim == 2 else "ray_cube", A=A, u=u)
    # a ray through a corner (an edge point in 3D) of [-1, 1]^dim, from outside, on a decimal grid
    step = Fraction(1, 10 ** g.rng.randint(1, 6))
    corner = tuple(Fraction(g.rng.choice([-1, 1])) for _ in range(dim))
    if dim == 3 and g.rng.random() < 0.5:
        k = g.rng.randrange(3)
        corner = tuple(Fraction(g.rng.randint(-9, 9), 10) if i == k else c for i, c in enumerate(corner))
    away = tuple(c * step * g.rng.randint(1, 9999) for c in corner)
    away = tuple(a if a != 0 else step for a in away)
    A = add(corner, away)
    u = tuple(-a * g.rng.randint(1, 9) for a in away)
    return line("ray_square" if dim == 2 else "ray_cube", A=A, u=u)


def vectors(g):
    step, _ = g.scale()
    u = g.vector(step, 3 if g.rng.random() < 0.5 else 2)
    dim = len(u)
    if dim == 2 or g.rng.random() < 0.5:
        k = Fraction(g.rng.randint(-99, 99) or 7, 10)  # one factor for every component
        v = tuple(c * k for c in u)  # collinear
    else:
        w = g.vector(step, 3)
        v = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])  # orthogonal
        if all(c == 0 for c in v):
            v = (u[1], -u[0], 0) if (u[0], u[1]) != (0, 0) else (1, 0, 0)
    if dim == 3 and g.rng.random() < 0.3:
        # a hair (1e-17 to 1e-20 of |v|, below the doubles' ε) off collinear or orthogonal: neither,
        # as written (a smaller one leaves a dot product within ε² of its terms: 1e-9 of itself)
        k = g.rng.randrange(3)
        size = max(abs(c) for c in v)
        v = tuple(c + (size * Fraction(g.rng.choice([-1, 1]), 10 ** g.rng.randint(17, 20)) if i == k else 0)
                  for i, c in enumerate(v))
    return line("vectors", u=u, v=v)


# Quarter turns as written, some beyond one turn or negative: R(θ) is a permutation with signs.
QUARTER_TURNS = [0, 90, 180, 270, -90, -180, 360, 450, 630, -270, 720]


def turn(v, degrees):
    """R(θ)·v for θ a whole number of quarter turns, exactly."""
    x, y = v
    return {0: (x, y), 1: (-y, x), 2: (-x, -y), 3: (y, -x)}[(degrees // 90) % 4]


def near(g, step):
    """0, or a shift far below the grid (1e-9 to 1e-14 of a step) of either sign: figures on a
    boundary, or just off it on a side the doubles cannot see."""
    if g.rng.random() < 0.6:
        return Fraction(0)
    return step * Fraction(g.rng.choice([-1, 1]), 10 ** g.rng.randint(9, 14))


def ellipse(g):
    """A turned ellipse on a boundary as written: a quarter turn with the ray tangent at a vertex,
    or A on the ellipse at a vertex (heading in, out or along it); or equal radii at any angle,
    tangent or A on it at a Pythagorean point. Sometimes a hair off the boundary."""
    step, _ = g.scale()
    C = add(g.far(step, 2), g.grid_point(step, 2))
    if g.rng.random() < 0.35:
        # a circle written as an ellipse: r on the grid of ball()'s Pythagorean points
        r = step * 1365 * g.rng.randint(1, 40)
        angle = g.rng.choice([g.rng.randint(0, 179), Fraction(g.rng.randint(-3600, 3600), 10)])
        n = signed(g, g.rng.choice(UNIT2))
        t = (-n[1], n[0])
        T = add(add(C, n, r), (near(g, step), 0) if abs(n[0]) > abs(n[1]) else (0, near(g, step)))
        if g.rng.random() < 0.5:
            A = add(T, t, -Fraction(g.rng.randint(2, 40), 10) * r)
            u = tuple(c * step * g.rng.randint(1, 999) * 21 for c in t)
        else:
            A = T
            u = tuple(step * (g.integer(99) + 400 * c * g.rng.choice([-1, 1])) for c in n)
        u = tuple(Fraction(round(c / step * 10**4)) * step / 10**4 for c in u)
        if all(c == 0 for c in u):
            u = (step, 0)
        return line("ray_ellipse", A=A, u=u, C=C, radii=(r, r), angle=angle)
    a, b = step * g.rng.randint(1, 9999), step * g.rng.randint(1, 9999)
    angle = g.rng.choice(QUARTER_TURNS)
    # in the ellipse's own frame: a vertex V, the tangent direction there
    k = g.rng.randrange(2)
    sign = g.rng.choice([-1, 1])
    V = (sign * a, 0) if k == 0 else (0, sign * b)
    tangent = (0, 1) if k == 0 else (1, 0)
    outward = (sign, 0) if k == 0 else (0, sign)
    V = add(V, outward, near(g, step))
    if g.rng.random() < 0.5:
        A_local = add(V, tangent, -step * g.rng.randint(1, 99999))
        u_local = tuple(c * step * g.rng.randint(1, 999) for c in tangent)
    else:
        A_local = V
        direction = g.rng.choice([-1, 0, 1])  # inward, along, outward
        u_local = tuple(direction * 400 * o + g.integer(99) * t for o, t in zip(outward, tangent))
        u_local = tuple(step * c for c in u_local)
        if all(c == 0 for c in u_local):
            u_local = tuple(step * t for t in tangent)
    A = add(C, turn(A_local, angle))
    u = turn(u_local, angle)
    return line("ray_ellipse", A=A, u=u, C=C, radii=(a, b), angle=angle)


def ellipse_special(g):
    """An ellipse turned by a multiple of 45° or 30° with A exactly on it as written (cos and sin
    irrational, the decisions not: the angle's field), sometimes a hair off, and at 45° the ray
    along the tangent there (from A, or from behind it: a tangent line)."""
    step, _ = g.scale()
    L = step * g.rng.randint(1, 999)
    C = add(g.far(step, 2), g.grid_point(step, 2))
    if g.rng.random() < 0.5:
        # 45°: b²(x+y)²/2 + a²(y−x)²/2 = a²b² with x + y = ±7L, a = 5L, b = 5|y − x| (1 + 49 = 2·25)
        angle = g.rng.choice([45, 135, 225, 315, -45, 405])
        dx = step * g.integer(9999)
        dy = g.rng.choice([-7, 7]) * L - dx
        a, b = 5 * L, 5 * abs(dy - dx)
        if b == 0:
            b = 5 * L
            dx, dy = 0, g.rng.choice([-7, 7]) * L  # y − x = ±7L: b = 35L, a² = ...: recompute below
            a, b = 5 * L, 35 * L
            # (x + y)² = 49L², (y − x)² = 49L²: b²·49L²/2 + a²·49L²/2 = a²b² holds for a = 5L, b = 35L
        if angle in (135, 315, -45):  # the figure's axes swap roles: the same point, radii swapped
            a, b = b, a
        grad = (b * b * (dx + dy) - a * a * (dy - dx), b * b * (dx + dy) + a * a * (dy - dx))
        if angle in (135, 315, -45):
            grad = (a * a * (dx + dy) - b * b * (dy - dx), a * a * (dx + dy) + b * b * (dy - dx))
        tangent = (-grad[1], grad[0])
        A = add(C, (dx + near(g, step), dy))
        case = g.rng.choice(["along", "before", "any"])
        if case == "along":
            u = tangent
        elif case == "before":
            A = add(A, tangent, -Fraction(g.rng.randint(1, 9), 10))
            u = tangent
        else:
            u = (step * g.integer(999), step * g.integer(999))
    else:
        # 30°-type (30, 150, 210, 330): A − C = (x, 0) with x²(3b² + a²)/4 = a²b²; 60°-type the
        # same with a and b swapped: (a, b, x) = (7, 28, 8) or (91, 21, 39), times L
        a, b, x = g.rng.choice([(7, 28, 8), (91, 21, 39)])
        angle = g.rng.choice([30, 150, 210, 330, -30, 390, 60, 120, 240, 300, -60])
        if angle % 180 in (60, 120):
            a, b = b, a
        a, b, x = a * L, b * L, g.rng.choice([-1, 1]) * x * L
        A = add(C, (x + near(g, step), 0))
        u = (step * g.integer(999), step * g.integer(999))
    if all(c == 0 for c in u):
        u = (step, 0)
    return line("ray_ellipse", A=A, u=u, C=C, radii=(a, b), angle=angle)


def rectangle(g):
    """A rectangle turned by quarter turns: a ray through a corner from outside, A on a side or
    a corner, or a ray along a side; sometimes a hair off."""
    step, _ = g.scale()
    C = add(g.far(step, 2), g.grid_point(step, 2))
    half = (step * g.rng.randint(1, 9999), step * g.rng.randint(1, 9999))
    angle = g.rng.choice(QUARTER_TURNS)
    corner = tuple(g.rng.choice([-1, 1]) * h for h in half)
    case = g.rng.choice(["corner", "on", "along"])
    if case == "corner":
        away = tuple((1 if c > 0 else -1) * step * g.rng.randint(1, 9999) for c in corner)
        A_local = add(add(corner, away), (near(g, step), near(g, step)))
        u_local = tuple(-a * g.rng.randint(1, 9) for a in away)
    elif case == "on":
        k = g.rng.randrange(2)
        A_local = tuple(corner[i] + (near(g, step) if i == k else 0) if i == k
                        else (corner[i] if g.rng.random() < 0.3 else step * g.rng.randint(-1, 1) * g.rng.randint(0, 9999) % half[i])
                        for i in range(2))
        u_local = (step * g.integer(999), step * g.integer(999))
        if all(c == 0 for c in u_local):
            u_local = (step, 0)
    else:
        k = g.rng.randrange(2)  # along the side x_k = corner_k, from beyond the other axis
        j = 1 - k
        A_local = [0, 0]
        A_local[k] = corner[k] + near(g, step)
        A_local[j] = corner[j] + (1 if corner[j] > 0 else -1) * step * g.rng.randint(1, 9999)
        A_local = tuple(A_local)
        u_local = [0, 0]
        u_local[j] = -(1 if corner[j] > 0 else -1) * step * g.rng.randint(1, 999)
        u_local = tuple(u_local)
    A = add(C, turn(A_local, angle))
    u = turn(u_local, angle)
    return line("ray_rectangle", A=A, u=u, C=C, half=half, angle=angle)


def turned_other(g):
    """An ellipse or a rectangle turned by an angle of no exact field (a whole number of degrees
    or a tenth, not a multiple of 15°: cos and sin irrational of degree more than 2): A, or the
    ray's line, 1e-6 to 1e-12 of the figure's size off its boundary, inside or out, on a grid of
    1e-16 of its size. Far beyond the filter's bound (about 1e-15 of the line's largest number),
    so decided, never refused (turned_written.h), and each decision is the 80-digit reference's."""
    step, _ = g.scale()
    # the filter's rounding is relative to the line's largest number (A − C is rounded at A's
    # scale): the figure near the origin and not tiny beside it, the offsets beyond that rounding
    C = g.grid_point(step, 2, 9999)
    while True:
        angle = g.rng.choice([Fraction(g.rng.randint(0, 179)), Fraction(g.rng.randint(-3600, 3600), 10)])
        if angle % 15 != 0:
            break
    a, b = step * g.rng.randint(1000, 9999), step * g.rng.randint(1000, 9999)
    if a == b:
        b += step
    th = math.radians(float(angle))
    c, s = math.cos(th), math.sin(th)
    off = g.rng.choice([-1, 1]) * 10.0 ** -g.rng.randint(6, 12)
    size = float(max(a, b))
    # the local point, turned in doubles and written on a grid of 1e-16 of the size: within
    # 1e-15 of the size of the point meant, 1e-6 to 1e-12 off the boundary
    grid = max(a, b) / 10**16

    def world(x, y):
        return tuple(C[i] + Fraction(round(v / float(grid))) * grid for i, v in enumerate((c * x - s * y, s * x + c * y)))

    def vec(x, y):
        return tuple(Fraction(round(v * 10**8)) / 10**8 * step for v in (c * x - s * y, s * x + c * y))

    if g.rng.random() < 0.5:
        half = (a, b)
        k = g.rng.randrange(2)
        sign = g.rng.choice([-1, 1])
        local = [0.0, 0.0]
        local[k] = sign * float(half[k]) * (1 + off)
        local[1 - k] = g.rng.uniform(-0.95, 0.95) * float(half[1 - k])
        u = vec(-sign * (k == 0) + g.rng.uniform(-1, 1), -sign * (k == 1) + g.rng.uniform(-1, 1))
        if all(v == 0 for v in u):
            u = (step, 0)
        return line("ray_rectangle", A=world(*local), u=u, C=C, half=half, angle=angle)
    phi = g.rng.uniform(0, 2 * math.pi)
    P = (float(a) * math.cos(phi) * (1 + off), float(b) * math.sin(phi) * (1 + off))
    n = (P[0] / float(a) ** 2, P[1] / float(b) ** 2)
    norm = math.hypot(*n)
    n = (n[0] / norm, n[1] / norm)
    t = (-n[1], n[0])
    if g.rng.random() < 0.5:  # the ray's line near the tangent at P: from behind, along it
        back = g.rng.uniform(0.5, 3) * size
        A = world(P[0] - back * t[0], P[1] - back * t[1])
        u = vec(*t)
    else:  # A near the ellipse, heading in, out or along
        A = world(*P)
        w = g.rng.choice([-1, 0, 1])
        u = vec(w * n[0] + 0.3 * g.rng.uniform(-1, 1) * t[0], w * n[1] + 0.3 * g.rng.uniform(-1, 1) * t[1])
    if all(v == 0 for v in u):
        u = (step, 0)
    return line("ray_ellipse", A=A, u=u, C=C, radii=(a, b), angle=angle)


MAKERS = [segments, projection, lambda g: ball(g, 2), lambda g: ball(g, 3), lambda g: box(g, 2),
          lambda g: box(g, 3), vectors, ellipse, ellipse_special, rectangle,
          turned_other]


class LongGen(Gen):
    """Numbers of more digits than a double holds (18 to 25 significant ones): the same figures
    1e12 to 1e17 grid steps from the origin, every boundary kept as written."""

    def far(self, step, dim):
        n = 10 ** self.rng.randint(12, 17)
        return tuple(step * self.rng.randint(-n, n) for _ in range(dim))


def hair(g, text_line):
    """One number of the line moved by one unit of its 18th to 30th significant digit, either
    way: a figure a hair off its boundary as written (t_ab of nearly parallel segments in the
    1e19, a discriminant of 1e-25 of its terms), whose values are made of the digits beyond the
    doubles."""
    numbers = json.loads(text_line, parse_float=Fraction, parse_int=Fraction)
    slots = [(k, i) for k, v in numbers.items() if k not in ("kind", "angle")
             for i in (range(len(v)) if isinstance(v, list) else [None])
             if (v[i] if i is not None else v) != 0]
    if not slots:
        return text_line
    k, i = g.rng.choice(slots)
    x = numbers[k][i] if i is not None else numbers[k]
    unit = Fraction(10) ** (math.floor(math.log10(abs(float(x)))) - g.rng.randint(17, 29))
    moved = x + g.rng.choice([-1, 1]) * unit
    if i is not None:
        numbers[k][i] = moved
    else:
        numbers[k] = moved
    fields = {name: tuple(v) if isinstance(v, list) else v for name, v in numbers.items() if name != "kind"}
    return line(numbers["kind"], **fields)


def lines(seed, count, long=False):
    g = LongGen(seed) if long else Gen(seed)
    out = []
    while len(out) < count:
        text_line = MAKERS[len(out) % len(MAKERS)](g)
        if long and g.rng.random() < 0.6:
            text_line = hair(g, text_line)
        # keep the figures whose doubles are not all the decimals: those test the semantics
        numbers = json.loads(text_line, parse_float=Fraction, parse_int=Fraction)
        values = [x for v in numbers.values() if not isinstance(v, str) for x in (v if isinstance(v, list) else [v])]
        if all(is_double(x) for x in values) and g.rng.random() < 0.9:
            continue
        out.append(text_line)
    return out


def main():
    seed, count = int(sys.argv[1]), int(sys.argv[2])
    long = "--long" in sys.argv[3:]
    sys.stdout.write("".join(l + "\n" for l in lines(seed, count, long)))


if __name__ == "__main__":
    main()
