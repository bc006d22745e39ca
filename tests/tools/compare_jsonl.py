#!/usr/bin/env python3
"""Compare `epure solve` output with expected JSON Lines, by the contract's acceptance rules.

usage: compare_jsonl.py ACTUAL EXPECTED [--input INPUT] [--ulps N] [--stats]
Booleans, strings and the set of `faces` match exactly; a number agrees within
max(1e-9, 1e-9*|expected|) and must not print more significant digits than the shortest
round-trip text of its double; the field sets must be equal; an expected error line needs a
non-empty "error" string. Prints one line per mismatch, then for each line that disagrees its
input (with --input: the solve input, whose blank lines have no output), expected and actual
text; exit 1 if any.

--ulps N (needs --input) also bounds every number by N ulps of the figure's scale, the
contract's accuracy (README, "epure solve"): S is the largest absolute coordinate, radius or
half-size of the line (1 at least for the canonical square and cube); a point, t, t_proj and the
half chord are within N·ulp(max(S, |value|)); a line parameter t_ab, t_cd or the projection's t
within N·ulp(max(S, |t|·‖AB‖)) as the length it gives along its segment; d2 within
N·ulp(max(S, √d2))·2·max(S, √d2); N within N·max(ulp(1), ulp(S)/size) (N·size is a length,
size the radius or the smallest radius or half-size); cos and sin within N·ulp(1); dot, cross within N ulps of
the sum of the magnitudes of their products; norms within N·ulp of themselves; angle_deg within
N·ulp(180). Ellipses and rectangles whose carried ray is rounded (an angle not a multiple of
90°, a size not a power of two, A − C inexact, or a number written that is not its double) are
held to the same: their decisions exact, their values within N ulps (turned_written.cpp checks
the carried ray's values against the decimals in double-double); at an angle of no exact field
a refusal is counted apart ("refused or right"). --stats prints the largest error in ulps per
kind and field.
"""
import math
from fractions import Fraction
import json
import re
import sys

NUMBER = re.compile(r'-?(?:0|[1-9]\d*)(?:\.\d+)?(?:[eE][+-]?\d+)?')


def significant_digits(text):
    mantissa = re.split(r'[eE]', text)[0].lstrip('-').replace('.', '').lstrip('0')
    return len(mantissa.rstrip('0')) or 1


def check_number_spelling(line_text, where, problems):
    # every number literal must be no longer than the shortest round-trip spelling of its value
    for m in NUMBER.finditer(re.sub(r'"(?:[^"\\]|\\.)*"', '""', line_text)):
        text = m.group(0)
        shortest = repr(float(text))
        if significant_digits(text) > significant_digits(shortest.replace('inf', '0')):
            problems.append(f"{where}: number {text} longer than shortest {shortest}")


def same(actual, expected, path, problems):
    if isinstance(expected, bool) or isinstance(actual, bool):
        if actual is not expected:
            problems.append(f"{path}: {actual!r} != {expected!r}")
    elif isinstance(expected, (int, float)):
        if not isinstance(actual, (int, float)):
            problems.append(f"{path}: {actual!r} is not a number")
        elif abs(actual - expected) > max(1e-9, 1e-9 * abs(expected)):
            problems.append(f"{path}: {actual!r} != {expected!r}")
    elif isinstance(expected, str):
        if actual != expected:
            problems.append(f"{path}: {actual!r} != {expected!r}")
    elif isinstance(expected, list):
        if path.endswith('.faces'):
            if not isinstance(actual, list) or sorted(actual) != sorted(expected):
                problems.append(f"{path}: {actual!r} != {expected!r} (as sets)")
        elif not isinstance(actual, list) or len(actual) != len(expected):
            problems.append(f"{path}: {actual!r} != {expected!r}")
        else:
            for i, (a, e) in enumerate(zip(actual, expected)):
                same(a, e, f"{path}[{i}]", problems)
    elif isinstance(expected, dict):
        if not isinstance(actual, dict):
            problems.append(f"{path}: {actual!r} is not an object")
            return
        if 'error' in expected:
            if not isinstance(actual.get('error'), str) or not actual['error']:
                problems.append(f"{path}: expected an error, got {actual!r}")
            return
        if set(actual) != set(expected):
            problems.append(f"{path}: fields {sorted(actual)} != {sorted(expected)}")
        for k in expected:
            if k in actual:
                same(actual[k], expected[k], f"{path}.{k}", problems)


def ulp(x):
    return math.ulp(abs(x)) if x != 0 else math.ulp(0.0)


def figure_scale(fig):
    kind = fig.get("kind")
    values = []
    for key in ("A", "B", "C", "D", "r", "radii", "half"):
        v = fig.get(key)
        if v is None:
            continue
        values.extend(v if isinstance(v, list) else [v])
    if kind in ("ray_square", "ray_cube"):
        values.append(1.0)
    return max([abs(float(x)) for x in values] + [0.0])


def is_power_of_two(x):
    x = abs(float(x))
    return x > 0 and math.frexp(x)[0] == 0.5


def binary_text(x):
    """Whether a number of the line (read as its text, TextNumber) is its double exactly: the
    turned figures carry the doubles nearest the decimals (README, "What a number means")."""
    if isinstance(x, list):
        return all(binary_text(y) for y in x)
    if isinstance(x, TextNumber):
        return not math.isfinite(x) or Fraction(x.text) == Fraction(float(x))
    return True


class TextNumber(float):
    """A JSON float that keeps its text."""
    def __new__(cls, text):
        n = super().__new__(cls, text)
        n.text = text
        return n


def bounded(fig):
    """Whether the contract makes this line's decisions exact and bounds its values in ulps:
    every kind but an ellipse or a rectangle whose ray, carried into the canonical frame, is
    rounded (an angle not a multiple of 90°, a size not a power of two, A − C inexact, or a
    number written that is not its double)."""
    if fig.get("kind") in ("ray_ellipse", "ray_rectangle"):
        try:
            if not all(binary_text(v) for v in fig.values()):
                return False
            sizes = fig.get("radii") or fig.get("half")
            A, C = fig["A"], fig["C"]
            exact_offset = all(float(a) - float(c) + float(c) == float(a) and
                               float(a) - (float(a) - float(c)) == float(c)
                               for a, c in zip(A, C))
            return (float(fig.get("angle", 0)) % 90 == 0 and all(map(is_power_of_two, sizes))
                    and exact_offset)
        except (TypeError, ValueError, KeyError):
            return True
    return True


def decided_as_written(fig):
    """Whether the contract decides this turned figure exactly on the decimals although its
    carried ray is rounded: every ellipse and rectangle (turned_written.h). Its values are
    measured."""
    return fig.get("kind") in ("ray_ellipse", "ray_rectangle")


def may_refuse(fig):
    """Whether the contract may refuse this turned figure rather than decide it: an angle whose
    cos and sin are in no exact field of ours (not a whole multiple of 30° or 45° as written),
    unequal sizes. Such a line is "refused or right": a refusal is counted, never a wrong answer."""
    def written(x):  # the decimal as written (a TextNumber's text; str() would give its double)
        return Fraction(getattr(x, "text", str(x)))

    try:
        if fig.get("kind") == "ray_ellipse" and written(fig["radii"][0]) == written(fig["radii"][1]):
            return False
        angle = written(fig["angle"])
        exact = (angle % 30 == 0 or angle % 45 == 0) and abs(angle) <= 2**53
        return fig.get("kind") in ("ray_ellipse", "ray_rectangle") and not exact
    except (TypeError, ValueError, KeyError, IndexError, ZeroDivisionError):
        return False


def decisions(result, kind):
    """What a turned figure's answer decides: inside, hit, a hit at A itself (t = 0), and for a
    rectangle at a quarter turn the side hit (its normal's signs; N is an axis there)."""
    if not isinstance(result, dict) or "error" in result:
        return ("error",)
    t = result.get("t")
    N = result.get("N")
    side = tuple(round(x) for x in N) if kind == "ray_rectangle" and isinstance(N, list) and all(abs(abs(x) - round(abs(x))) < 1e-6 for x in N) else None
    return (result.get("inside"), result.get("hit"), t == 0 if t is not None else None, side)


def ulp_errors(fig, actual, expected):
    """(field, error in ulps of its bound) for every number of a result."""
    kind = fig["kind"]
    S = figure_scale(fig)
    out = []

    def add(name, a, e, unit):
        if isinstance(a, (int, float)) and not isinstance(a, bool):
            out.append((name, abs(a - e) / unit if unit > 0 else (0.0 if a == e else math.inf)))

    for key, e in expected.items():
        if key not in actual or isinstance(e, (bool, str)):
            continue
        a = actual[key]
        if kind == "vectors":
            u, v = fig["u"], fig["v"]
            if key in ("dot", "cross"):
                terms = abs(u[0] * v[0]) + abs(u[1] * v[1]) if key == "dot" else \
                    abs(u[0] * v[1]) + abs(u[1] * v[0])
                add(key, a, e, ulp(terms))
            elif key in ("norm_u", "norm_v"):
                add(key, a, e, ulp(e))
            elif key == "angle_deg":
                add(key, a, e, ulp(180.0))
            else:
                add(key, a, e, ulp(1.0))
        elif key in ("t_ab", "t_cd") or (kind == "projection" and key == "t"):
            P, Q = ("A", "B") if key != "t_cd" else ("C", "D")
            length = math.hypot(fig[Q][0] - fig[P][0], fig[Q][1] - fig[P][1])
            add(key, a * length, e * length, ulp(max(S, abs(e) * length)))
        elif key == "d2":
            size = max(S, math.sqrt(abs(e)))
            add(key, a, e, ulp(size) * 2 * size)
        elif key == "N":
            # N·size is a length: within the bound of a point, over the figure's size
            size = fig.get("r") or min(fig.get("radii") or fig.get("half") or [1.0])
            for i, (x, y) in enumerate(zip(a, e)):
                add(f"N[{i}]", x, y, max(ulp(1.0), ulp(S) / float(size)))
        elif isinstance(e, list):
            for i, (x, y) in enumerate(zip(a, e)):
                if isinstance(y, str) or isinstance(x, str):
                    continue
                add(f"{key}[{i}]", x, y, ulp(max(S, abs(y))))
        else:
            add(key, a, e, ulp(max(S, abs(e))))
    return out


def main():
    args = sys.argv[1:]
    ulps = None
    stats = '--stats' in args
    if stats:
        args.remove('--stats')
    if '--ulps' in args:
        i = args.index('--ulps')
        ulps = float(args[i + 1])
        del args[i:i + 2]
    inputs = None
    if '--input' in args:
        i = args.index('--input')
        text = open(args[i + 1], 'rb').read().decode('utf-8', errors='replace')
        # the lines epure solves: '\n'-separated, a trailing '\r' dropped, blank ones skipped
        inputs = [l for l in (x[:-1] if x.endswith('\r') else x for x in text.split('\n'))
                  if l.strip(' \t')]
        del args[i:i + 2]
    actual_lines = open(args[0], encoding='utf-8').read().splitlines()
    expected_lines = open(args[1], encoding='utf-8').read().splitlines()
    problems = []
    worst = {}
    carried = {}  # lines of a rounded carried ray (not bounded) that differ, by kind
    refused = {}  # turned lines at an angle of no exact field that epure refused, by kind
    if len(actual_lines) != len(expected_lines):
        problems.append(f"{len(actual_lines)} lines, expected {len(expected_lines)}")
    for n, (a, e) in enumerate(zip(actual_lines, expected_lines), start=1):
        try:
            actual = json.loads(a)
        except ValueError as err:
            problems.append(f"line {n}: not JSON ({err}): {a}")
            continue
        check_number_spelling(a, f"line {n}", problems)
        expected = json.loads(e)
        fig = None
        if inputs is not None and n <= len(inputs):
            try:
                fig = json.loads(inputs[n - 1], parse_float=TextNumber)
            except ValueError:
                fig = None
        if ulps is not None and isinstance(fig, dict) and not bounded(fig):
            if isinstance(actual, dict) and 'error' in actual and 'error' not in expected and may_refuse(fig):
                refused[fig.get("kind")] = refused.get(fig.get("kind"), 0) + 1
                continue
            mine = []
            same(actual, expected, f"line {n}", mine)
            if decided_as_written(fig) and decisions(actual, fig["kind"]) != decisions(expected, fig["kind"]):
                problems.append(f"line {n}: decided {decisions(actual, fig['kind'])}, exactly "
                                f"{decisions(expected, fig['kind'])} "
                                "(inside, hit, t = 0, side)")
                problems.extend(mine)
            elif mine and not decided_as_written(fig):
                carried[fig.get("kind")] = carried.get(fig.get("kind"), 0) + 1
            elif 'error' not in expected and 'error' not in actual:
                # its decisions exact, its values those of the decimal figure within the bound
                # (turned_written.cpp's double-double check), which at a scale S far from 1
                # is wider than the 1e-9 rule, which is then not asked
                for name, err in ulp_errors(fig, actual, expected):
                    key = (f"{fig['kind']} (carried)", name.split('[')[0])
                    worst[key] = max(worst.get(key, 0.0), err)
                    if decided_as_written(fig) and err > ulps:
                        problems.append(f"line {n}: {name} off by {err:.1f} ulps of its bound "
                                        f"(> {ulps:g}; a turned figure)")
            continue
        same(actual, expected, f"line {n}", problems)
        if ulps is not None and inputs is not None and n <= len(inputs) and \
                isinstance(actual, dict) and 'error' not in expected and 'error' not in actual:
            if not isinstance(fig, dict):
                continue
            kind = fig.get("kind")
            for name, err in ulp_errors(fig, actual, expected):
                key = (kind if bounded(fig) else f"{kind} (any angle)", name.split('[')[0])
                worst[key] = max(worst.get(key, 0.0), err)
                if bounded(fig) and err > ulps:
                    problems.append(f"line {n}: {name} off by {err:.1f} ulps of its bound "
                                    f"(> {ulps:g})")
    for p in problems:
        print(p)
    bad = sorted({int(m.group(1)) for m in (re.match(r'line (\d+)\b', p) for p in problems) if m})
    for n in bad:
        print(f"line {n}:")
        if inputs is not None and n <= len(inputs):
            print(f"  input:    {inputs[n - 1]}")
        print(f"  expected: {expected_lines[n - 1]}")
        print(f"  actual:   {actual_lines[n - 1]}")
    for kind, count in sorted(carried.items()):
        print(f"measured, not bounded: {count} {kind} lines with a rounded carried ray differ "
              f"from the exact figure")
    for kind, count in sorted(refused.items()):
        print(f"refused, not wrong: {count} {kind} lines at an angle of no exact field")
    if stats:
        for (kind, name), err in sorted(worst.items()):
            print(f"ulps: {kind:28} {name:10} {err:.2f}")
    print(f"{len(expected_lines) - len(bad)} of {len(expected_lines)} lines agree, "
          f"{len(bad)} disagree ({len(problems)} problems)")
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
