#!/usr/bin/env python3
"""The named mistakes of a Moodle export against the paper grading's. For every mistake answer
of every exported number and choice, one submission gives exactly that answer (the other
answers of the exercise left blank: grading names a mistake only where the student's own earlier
answers agree with it, and a right earlier answer where the mistake gives another says the
student did not make it, which a Cloze part, decided alone, cannot see; for a point, its other
coordinate as the same mistake gives it);
`epure grade` marks it, and Moodle's grading is simulated on the exported question (answers tried
in order, the first whose interval holds the value wins, as question/type/numerical does). The
two must agree: right for both, or wrong with the same named mistake (same sentence), or with
another mistake whose own interval in the part holds the value too (two mistakes that give the
same number within its tolerance: nothing in a lone answer tells them apart; counted apart).
A point's coordinates are separate Cloze parts, so Moodle decides each coordinate alone where
grading decides the point as a whole (both coordinates must fit one mistake): there they may name
different mistakes; those are counted and printed, and fail only when grading marks the answer
right (or Moodle does and grading does not). Sets of faces are one list of the candidate sets:
a mistake's set is typed as the list words it ("+x, −y").
usage: mistakes_vs_grading.py EPURE MOODLE.xml KEY.json GRADING.toml WORKDIR
"""
import csv
import json
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(__file__))
from moodle_cloze import extract, moodle_grade, moodle_interval, sentence_patterns, strip_tags  # noqa: E402


def main(argv):
    epure, moodle, key_path, grading, work = argv[1:6]
    key = json.load(open(key_path, encoding='utf-8'))
    patterns = sentence_patterns(grading)
    code_of = lambda fb: next((c for c, p in patterns.items() if p.match(strip_tags(fb))), None)
    root = ET.parse(moodle).getroot()
    by_name = {}
    for q in root.findall('question'):
        if q.get('type') == 'multianswer':
            m = re.match(r'^(\S+)-(\d+)$', q.findtext('idnumber'))
            by_name[(int(m.group(2)), m.group(1))] = q
    ids = []
    for s in key['sheets']:
        for e in s['exercises']:
            for q in e['questions']:
                if q['id'] not in ids:
                    ids.append(q['id'])

    rows, expect = [], []
    for s in key['sheets']:
        for e in s['exercises']:
            q = by_name[(e['n'], s['id'])]
            parts, _ = extract(q.findtext('questiontext/text'))
            parts = [p for p in parts if p['weight'] != '0']  # fields this case does not ask
            part_of = {kq['id']: p for p, kq in zip(parts, e['questions'])}
            # question id → code → (the answer as typed, Moodle's verdict on it, the codes whose
            # intervals hold it too)
            mistakes = {}
            for kq in e['questions']:
                part = part_of[kq['id']]
                mistakes[kq['id']] = {}
                if part['type'] == 'numerical':
                    for alt in part['alternatives'][1:-1]:
                        won = moodle_grade(part, alt['value'])
                        verdict = 'right' if won is part['alternatives'][0] else code_of(won['feedback'])
                        also = {code_of(a['feedback']) for a in part['alternatives'][1:-1]
                                if 'value' in a and moodle_interval(a)[0] <= alt['value'] <= moodle_interval(a)[1]}
                        mistakes[kq['id']].setdefault(code_of(alt['feedback']), (repr(alt['value']), verdict, also))
                elif part['type'] == 'multichoice':
                    for alt in part['alternatives']:
                        if alt['feedback']:
                            mistakes[kq['id']].setdefault(code_of(alt['feedback']),
                                                          (strip_tags(alt['text']), code_of(alt['feedback']), set()))
            for kq in e['questions']:
                for code, (value, verdict, also) in mistakes[kq['id']].items():
                    answers = {kq['id']: value}
                    if kq.get('point'):  # the other coordinate as the same mistake gives it
                        for other in e['questions']:
                            if other.get('point') == kq['point'] and other['id'] != kq['id'] and code in mistakes[other['id']]:
                                answers[other['id']] = mistakes[other['id']][code][0]
                    rows.append({'sheet': s['id'], 'student': f'row{len(rows)}', **answers})
                    expect.append((kq['id'], verdict, bool(kq.get('point')), also))
    answers_csv = os.path.join(work, 'mistakes.csv')
    with open(answers_csv, 'w', newline='', encoding='utf-8') as f:
        w = csv.DictWriter(f, fieldnames=['sheet', 'student'] + ids, delimiter=';')
        w.writeheader()
        w.writerows(rows)
    marks_json = os.path.join(work, 'mistakes.json')
    subprocess.run([epure, 'grade', '--key', key_path, '--answers', answers_csv, '--json', marks_json, '-q'],
                   check=False, capture_output=True)
    marks = json.load(open(marks_json, encoding='utf-8'))
    failures, point_differences = [], []
    subs = {s['student']: s for s in marks['submissions']}
    agree = ambiguous = 0
    for i, (qid, moodle_verdict, point, also) in enumerate(expect):
        sub = subs.get(f'row{i}')
        if sub is None:
            failures.append(f'row{i}: not marked')
            continue
        mark = next((x for x in sub['questions'] if x['id'] == qid), None)
        paper = 'right' if mark['verdict'] in ('right', 'follow_through') else mark['mistake']
        if paper == moodle_verdict:
            agree += 1
            continue
        if moodle_verdict != 'right' and paper in also:
            ambiguous += 1
            continue
        line = f'{sub["sheet"]} {qid} = {mark["given"]}: Moodle says {moodle_verdict}, paper grading says {paper}'
        if point and 'right' not in (paper, moodle_verdict):
            point_differences.append(line)
        else:
            failures.append(line)
    for f in failures[:40]:
        print('FAIL', f)
    for f in point_differences[:10]:
        print('point coordinate decided alone:', f)
    print(f'{moodle}: {len(expect)} mistake answers marked by epure grade and by Moodle\'s rules: {agree} agree, '
          f'{ambiguous} name another mistake that gives the same value, '
          f'{len(point_differences)} point coordinates name another mistake, {len(failures)} disagree')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
