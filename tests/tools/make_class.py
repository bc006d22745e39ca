#!/usr/bin/env python3
"""A class's answers made from a key.json, as a spreadsheet would export them, for the grading
tests: every sheet of the key is one student, who answers each question right with a
probability that depends on the student (an ability drawn from the seed) and on the exercise
(later exercises are harder), else types a wrong value or leaves the cell empty. Deterministic
for a seed (Python's own Mersenne Twister, the same on every platform).

usage: make_class.py KEY.json OUT.csv [--seed S] [--lang fr|en] [--students N]
Writes a CSV with a header `sheet;student;<question ids…>` (';' and decimal commas for fr, ','
and decimal points for en). Answers are the key's values rounded to the key's decimals.
"""
import argparse
import csv
import json
import random


def shown(q, decimals, comma, lang):
    e = q['expected']
    if isinstance(e, bool):
        return ('oui' if e else 'non') if lang == 'fr' else ('yes' if e else 'no')
    if isinstance(e, list):
        return ' '.join(e) if e else ('aucun' if lang == 'fr' else 'none')
    if isinstance(e, str):
        return e
    s = f"{round(e, decimals):.{decimals}f}"
    return s.replace('.', ',') if comma else s


def wrong(q, decimals, comma, lang, rng):
    e = q['expected']
    if isinstance(e, bool):
        return shown({'expected': not e}, decimals, comma, lang)
    if isinstance(e, list):
        faces = ['+x', '-x', '+y', '-y']
        return rng.choice([f for f in faces if f not in e] or ['+x'])
    if isinstance(e, str):
        return 'miss' if e != 'miss' else 'behind'
    v = e * rng.choice([1.5, -1, 0.5]) + rng.choice([0.7, -1.3, 2.1])
    s = f"{round(v, decimals):.{decimals}f}"
    return s.replace('.', ',') if comma else s


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('key')
    ap.add_argument('out')
    ap.add_argument('--seed', type=int, default=1)
    ap.add_argument('--lang', default='fr')
    ap.add_argument('--students', type=int, default=0)
    a = ap.parse_args()
    key = json.load(open(a.key, encoding='utf-8'))
    decimals = key['spec'].get('decimals', 2)
    comma = a.lang == 'fr'
    rng = random.Random(a.seed)
    sheets = key['sheets'][: a.students or None]
    ids = []
    for s in sheets:
        for e in s['exercises']:
            for q in e['questions']:
                if q['id'] not in ids:
                    ids.append(q['id'])
    rows = []
    for i, s in enumerate(sheets):
        ability = rng.uniform(0.35, 0.98)
        cells = {}
        for e in s['exercises']:
            hardness = 1 - 0.06 * e['n']
            for q in e['questions']:
                r = rng.random()
                if r < ability * hardness:
                    cells[q['id']] = shown(q, decimals, comma, a.lang)
                elif r < ability * hardness + 0.1:
                    cells[q['id']] = ''
                else:
                    cells[q['id']] = wrong(q, decimals, comma, a.lang, rng)
        rows.append([s['id'], f"Étudiant {i + 1:02d}" if a.lang == 'fr' else f"Student {i + 1:02d}"] +
                    [cells.get(id, '') for id in ids])
    with open(a.out, 'w', encoding='utf-8', newline='') as f:
        w = csv.writer(f, delimiter=';' if comma else ',')
        w.writerow(['sheet', 'student'] + ids)
        w.writerows(rows)


if __name__ == '__main__':
    main()
