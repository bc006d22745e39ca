#!/usr/bin/env python3
"""Cases for the exact decimal arithmetic of the geometry core (src/geometry/big_integer.h,
decimal.h), each answered by Python's exact integers and fractions: an independent reference.
tests/geometry/decimal_arithmetic_test.cpp reads them from tests/geometry/decimal_arithmetic.txt
(written by `decimal_arithmetic.py 35 200`), which tests/cli/solve_decimal.sh checks this script
still writes.

usage: decimal_arithmetic.py SEED N        (N cases of each operation, on stdout)

One case a line, fields separated by spaces:
  read TEXT HI REST          TEXT's double (correctly rounded) and its rest TEXT − HI, rounded
  add A B M E                A + B = M·10^E exactly (M without trailing zeros; 0 0 for zero)
  mul A B M E                A·B = M·10^E
  pow2 A K M E               A·2^K = M·10^E
  sign A B C D S             the sign S of A·B − C·D (often zero, or nearly)
Numbers are written as decimal texts, in every form a JSON number takes (integers, fractions,
exponents, up to 60 digits, powers of ten from 10^-400 to 10^400).
"""
import math
import random
import sys
from fractions import Fraction



def text_of(rng):
    """A decimal text: short or long, any sign, any exponent form."""
    digits = rng.choice([1, 2, 3, 5, 9, 15, 17, 19, 20, 25, 40, 60])
    m = rng.randrange(10 ** (digits - 1), 10**digits) if digits > 1 else rng.randrange(0, 10)
    sign = "-" if rng.random() < 0.5 else ""
    form = rng.random()
    if form < 0.3:
        e = rng.choice([0, 0, 1, 3, 10, 22, 25, 100, 300, -1, -3, -10, -22, -25, -100, -300, -330, -400])
        return f"{sign}{m}e{e}" if e else f"{sign}{m}"
    s = str(m)
    point = rng.randrange(0, len(s) + 1)
    if point == 0:
        return f"{sign}0.{'0' * rng.randrange(0, 30)}{s}"
    if point == len(s):
        return f"{sign}{s}"
    return f"{sign}{s[:point]}.{s[point:]}"


def finite(text):
    try:
        return math.isfinite(float(Fraction(text)))
    except OverflowError:
        return False


def exact(text):
    return Fraction(text)


def decimal_form(x):
    """x = M·10^E, M an integer without trailing zeros ('0 0' for zero)."""
    if x == 0:
        return "0 0"
    e = 0
    while x.denominator != 1:
        x *= 10
        e -= 1
    m = x.numerator
    while m % 10 == 0:
        m //= 10
        e += 1
    return f"{m} {e}"


def hexf(x):
    return float(x).hex()


def read_case(rng):
    while True:
        t = text_of(rng)
        if finite(t):
            break
    x = exact(t)
    hi = float(x)  # correctly rounded (Fraction → float rounds the quotient once)
    rest = x - Fraction(hi)
    return f"read {t} {hi.hex()} {float(rest).hex()}"


def near_product(rng, a, b):
    """C, D with C·D equal to A·B, or one unit of their last digit off."""
    p = exact(a) * exact(b)
    # C a divisor-friendly decimal: A times 10^k, D = B / 10^k
    k = rng.randint(-3, 3)
    c = exact(a) * Fraction(10) ** k
    d = p / c if c != 0 else Fraction(0)
    if rng.random() < 0.5 and d != 0:
        d += Fraction(rng.choice([-1, 1]), 10 ** rng.randint(20, 80))
    return c, d


def text_exact(x):
    """The exact decimal text of a Fraction with a power-of-ten denominator."""
    m, e = decimal_form(x).split()
    return f"{m}e{e}" if e != "0" else m


def main():
    seed, n = int(sys.argv[1]), int(sys.argv[2])
    rng = random.Random(seed)
    out = []
    for _ in range(n):
        out.append(read_case(rng))
    for _ in range(n):
        a, b = text_of(rng), text_of(rng)
        out.append(f"add {a} {b} {decimal_form(exact(a) + exact(b))}")
        out.append(f"mul {a} {b} {decimal_form(exact(a) * exact(b))}")
        k = rng.randint(-1100, 1100) if rng.random() < 0.05 else rng.randint(-200, 200)
        out.append(f"pow2 {a} {k} {decimal_form(exact(a) * Fraction(2) ** k)}")
    for _ in range(n):
        a, b = text_of(rng), text_of(rng)
        c, d = near_product(rng, a, b)
        s = exact(a) * exact(b) - c * d
        out.append(f"sign {a} {b} {text_exact(c)} {text_exact(d)} {(s > 0) - (s < 0)}")
    sys.stdout.write("".join(line + "\n" for line in out))


if __name__ == "__main__":
    main()
