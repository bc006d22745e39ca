#!/usr/bin/env python3
"""Compare `epure solve` output with expected JSON Lines, by the contract's acceptance rules.

usage: compare_jsonl.py ACTUAL EXPECTED [--input INPUT]
Booleans, strings and the set of `faces` match exactly; a number agrees within
max(1e-9, 1e-9*|expected|) and must not print more significant digits than the shortest
round-trip text of its double; the field sets must be equal; an expected error line needs a
non-empty "error" string. Prints one line per mismatch, then for each line that disagrees its
input (with --input: the solve input, whose blank lines have no output), expected and actual
text; exit 1 if any.
"""
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


def main():
    args = sys.argv[1:]
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
    if len(actual_lines) != len(expected_lines):
        problems.append(f"{len(actual_lines)} lines, expected {len(expected_lines)}")
    for n, (a, e) in enumerate(zip(actual_lines, expected_lines), start=1):
        try:
            actual = json.loads(a)
        except ValueError as err:
            problems.append(f"line {n}: not JSON ({err}): {a}")
            continue
        check_number_spelling(a, f"line {n}", problems)
        same(actual, json.loads(e), f"line {n}", problems)
    for p in problems:
        print(p)
    bad = sorted({int(m.group(1)) for m in (re.match(r'line (\d+)\b', p) for p in problems) if m})
    for n in bad:
        print(f"line {n}:")
        if inputs is not None and n <= len(inputs):
            print(f"  input:    {inputs[n - 1]}")
        print(f"  expected: {expected_lines[n - 1]}")
        print(f"  actual:   {actual_lines[n - 1]}")
    print(f"{len(expected_lines) - len(bad)} of {len(expected_lines)} lines agree, "
          f"{len(bad)} disagree ({len(problems)} problems)")
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
