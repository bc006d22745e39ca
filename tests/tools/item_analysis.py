#!/usr/bin/env python3
"""An independent reference for `epure grade`'s item analysis (src/grading/item_analysis.h):
recomputes, from the per-question marks of a --json report, every figure of its
statistics.items — facility and item–rest discrimination per question, Cronbach's α over the
exercises, facility per branch and Welch's one-sided t-test of each branch against the others of
its exercise (its p-value from a numerical integration of Student's t density, not the
incomplete beta function epure uses), the named mistakes per code and exercise and the
follow-through credit — by the textbook two-pass formulas, and compares them.

usage: item_analysis.py MARKS.json      (exit 1 and a list of differences when they disagree)
"""
import json
import math
import sys


def mean(xs):
    return sum(xs) / len(xs)


def var(xs):  # sample variance
    if len(xs) < 2:
        return 0.0
    m = mean(xs)
    return sum((x - m) ** 2 for x in xs) / (len(xs) - 1)


def pearson(xs, ys):
    if len(xs) < 3:
        return None
    mx, my = mean(xs), mean(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    syy = sum((y - my) ** 2 for y in ys)
    if sxx <= 1e-12 * len(xs) or syy <= 1e-12 * len(xs):
        return None
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / math.sqrt(sxx * syy)


def t_upper(t, df):
    """P(T >= t) for Student's t with df degrees of freedom, by integrating its density from 0
    to |t| with composite Simpson's rule (after the substitution x = tan θ, which makes the
    integrand smooth and the interval finite)."""
    if math.isinf(t):
        return 0.0 if t > 0 else 1.0
    c = math.exp(math.lgamma((df + 1) / 2) - math.lgamma(df / 2)) / math.sqrt(df * math.pi)
    a = math.atan(abs(t))

    def f(th):  # density(tan θ) · sec² θ
        x = math.tan(th)
        return c * (1 + x * x / df) ** (-(df + 1) / 2) / math.cos(th) ** 2

    n = 20000
    h = a / n
    s = f(0) + f(a) + sum((4 if i % 2 else 2) * f(i * h) for i in range(1, n))
    half = s * h / 3  # P(0 <= T <= |t|)
    upper = 0.5 - half
    return upper if t >= 0 else 1 - upper


def welch_lower(a, b):
    if len(a) < 2 or len(b) < 2:
        return None
    e1, e2 = var(a) / len(a), var(b) / len(b)
    m1, m2 = mean(a), mean(b)
    if e1 + e2 == 0:
        return (math.inf if m1 < m2 else 0.0, len(a) + len(b) - 2, 0.0 if m1 < m2 else 1.0)
    t = (m2 - m1) / math.sqrt(e1 + e2)
    df = (e1 + e2) ** 2 / (e1 ** 2 / (len(a) - 1) + e2 ** 2 / (len(b) - 1))
    return t, df, t_upper(t, df)


def main(path):
    report = json.load(open(path, encoding='utf-8'))
    subs = [s for s in report['submissions'] if s['marked']]
    items = report['statistics']['items']
    problems = []

    def close(what, got, want, tol=1e-9):
        if want is None or got is None:
            if (want is None) != (got is None):
                problems.append(f"{what}: epure {got}, reference {want}")
            return
        if not (abs(got - want) <= tol * max(1.0, abs(want))):
            problems.append(f"{what}: epure {got}, reference {want}")

    # questions
    per_q = {}
    for s in subs:
        for q in s['questions']:
            if q['verdict'] == 'to_check':
                continue
            x = q['points'] / q['max_points'] if q['max_points'] > 0 else 0.0
            per_q.setdefault(q['id'], []).append((x, s['score'] - q['points']))
    got_q = {q['id']: q for q in items['questions']}
    for qid, pairs in per_q.items():
        g = got_q.get(qid)
        if g is None:
            problems.append(f"question {qid} missing")
            continue
        xs, rs = [p[0] for p in pairs], [p[1] for p in pairs]
        if g['answers'] != len(xs):
            problems.append(f"{qid} answers: epure {g['answers']}, reference {len(xs)}")
        close(f"{qid} facility", g['facility'], mean(xs))
        close(f"{qid} discrimination", g['discrimination'], pearson(xs, rs), 1e-9)
    # exercises and alpha
    k = len(subs[0]['exercises']) if subs else 0
    ys = [[s['exercises'][j]['points'] for s in subs] for j in range(k)]
    totals = [s['score'] for s in subs]
    alpha = None
    if len(subs) >= 2 and k >= 2 and var(totals) > 1e-12:
        alpha = k / (k - 1) * (1 - sum(var(y) for y in ys) / var(totals))
    close("alpha", items['alpha'], alpha, 1e-9)
    # branches
    by_branch = {}
    for s in subs:
        for e in s['exercises']:
            share = e['points'] / e['max_points'] if e['max_points'] > 0 else 0.0
            by_branch.setdefault(e['n'], {}).setdefault(e['branch'], []).append(share)
    got_b = {(b['exercise'], b['branch']): b for b in items['branches']}
    for n, branches in by_branch.items():
        tested = 0
        results = {}
        for name, shares in branches.items():
            others = [x for o, xs in branches.items() if o != name for x in xs]
            w = welch_lower(shares, others)
            results[name] = (shares, others, w)
            tested += w is not None
        for name, (shares, others, w) in results.items():
            g = got_b.get((n, name))
            if g is None:
                problems.append(f"branch {n} {name} missing")
                continue
            close(f"exercise {n} {name} facility", g['facility'], mean(shares))
            if w is None:
                if g['p'] is not None:
                    problems.append(f"exercise {n} {name}: epure tested it, the reference does not")
                continue
            # an infinite t (both groups constant) is written null
            close(f"exercise {n} {name} t", g['t'], None if math.isinf(w[0]) else w[0], 1e-9)
            close(f"exercise {n} {name} df", g['df'], w[1], 1e-9)
            close(f"exercise {n} {name} p", g['p'], w[2], 1e-7)
            harder = w[2] < 0.05 / tested
            if g['harder'] != harder or g['tested'] != tested:
                problems.append(f"exercise {n} {name}: harder {g['harder']} (m = {g['tested']}), reference {harder} (m = {tested})")
    # mistakes and follow-through
    counts, ft, ft_points = {}, 0, 0.0
    for s in subs:
        for q in s['questions']:
            if q['verdict'] == 'to_check':
                continue
            if q['mistake']:
                counts[q['mistake']] = counts.get(q['mistake'], 0) + 1
            if q['verdict'] == 'follow_through':
                ft += 1
                ft_points += q['points']
    got_m = {m['code']: m['count'] for m in items['mistakes']}
    if got_m != counts:
        problems.append(f"mistakes: epure {got_m}, reference {counts}")
    if items['follow_through'] != ft:
        problems.append(f"follow-through answers: epure {items['follow_through']}, reference {ft}")
    close("follow-through points", items['follow_through_points'], ft_points)
    for p in problems:
        print("item analysis:", p)
    print(f"item analysis: {len(per_q)} questions, {len(got_b)} branches, α, mistakes and follow-through "
          f"checked against the reference: {'OK' if not problems else f'{len(problems)} differences'}")
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1]))
