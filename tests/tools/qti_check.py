#!/usr/bin/env python3
"""Checks a QTI 2.1 content package written by `epure export qti` against its set's key.json
(the schemas are checked by xmllint, in tests/cli/export_test.sh):
  - every file the manifest names is in the zip, and every file of the zip is named by it;
  - every entry has the fixed timestamp (1980-01-01 00:00), so that reruns are byte-identical;
  - the test has one section per exercise, each with <selection select="1"/> and one item per sheet;
  - every item is titled `<heading> — <sheet id>`, its section `<heading>`, the heading naming
    the number its question ids start with (one numbering); every declared response is used by an
    interaction and by the response processing, and every interaction's response is declared;
  - a float response's correct value is the key's, matched by <equal toleranceMode="absolute">
    with <correct> first and a tolerance no looser than the key's rule; a point marked as a whole
    (whole_point) by its distance, (x − x₀)² + (y − y₀)² ≤ r², r no larger than the key's; a set of
    faces matched as a whole; the points added up are the key's; every modalFeedback is set by
    the response processing;
  - a field the sheet prints and the case does not ask has a response with no correct value,
    read only to say that it is not marked;
  - every <img> of an item is in the package;
  - every item carries its worked solution: a modalFeedback SOLUTION that the response
    processing sets whatever the answers, with the key's diagrams (in the package), its answers
    as a table, and every number the key expects printed there rounded as the sheet asks.
usage: qti_check.py QTI.zip KEY.json EXTRACT_DIR
"""
import json
import math
import os
import re
import sys
import zipfile
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from moodle_cloze import names_number, shown  # noqa: E402  (one reading of both exports)

QTI = '{http://www.imsglobal.org/xsd/imsqti_v2p1}'
CP = '{http://www.imsglobal.org/xsd/imscp_v1p1}'


def rule_width(tol, at):
    if tol['rule'] == 'isclose':
        return max(tol['rel'] * abs(at), tol['abs'])
    if tol['rule'] == 'distance':
        return tol['abs'] / math.sqrt(2)
    return 0.0


def check_solution(item, processing, ex, where, names, decimals, fail):
    """The item's worked solution: shown whatever the answers, this sheet's own."""
    sol = [mf for mf in item.findall(QTI + 'modalFeedback') if mf.get('identifier') == 'SOLUTION']
    if len(sol) != 1:
        fail(where, 'no worked solution (modalFeedback SOLUTION)')
        return
    unconditional = [b.text for rule in processing.findall(QTI + 'setOutcomeValue')
                     for b in rule.iter(QTI + 'baseValue') if b.get('baseType') == 'identifier']
    if 'SOLUTION' not in unconditional:
        fail(where, 'the worked solution is not set whatever the answers')
    mf = sol[0]
    imgs = list(mf.iter(QTI + 'img'))
    if not imgs:
        fail(where, 'the worked solution has no diagram')
    for img in imgs:
        if os.path.normpath(os.path.join('items', img.get('src'))) not in names:
            fail(where, f'the worked solution\'s image {img.get("src")} is not in the package')
    if mf.find(f'.//{QTI}tr') is None:
        fail(where, 'the worked solution has no answers')
    text = ''.join(mf.itertext())
    comma = item.get('{http://www.w3.org/XML/1998/namespace}lang') == 'fr'
    for kq in ex['questions']:
        e = kq['expected']
        if isinstance(e, (int, float)) and not isinstance(e, bool) and shown(e, decimals, comma) not in text:
            fail(f'{where} {kq["id"]}', f'the worked solution does not show the key\'s {shown(e, decimals, comma)}')


def main(argv):
    zpath, key_path, out_dir = argv[1], argv[2], argv[3]
    failures = []
    fail = lambda where, what: failures.append(f'{where}: {what}')
    key = json.load(open(key_path, encoding='utf-8'))
    decimals = key['spec'].get('decimals', 2)
    z = zipfile.ZipFile(zpath)
    names = z.namelist()
    if len(names) != len(set(names)):
        fail(zpath, 'a name twice')
    for info in z.infolist():
        if info.date_time != (1980, 1, 1, 0, 0, 0):
            fail(info.filename, f'timestamp {info.date_time}')
    z.extractall(out_dir)
    manifest = ET.fromstring(z.read('imsmanifest.xml'))
    named = set()
    resources = {}
    for r in manifest.iter(CP + 'resource'):
        resources[r.get('identifier')] = r
        for f in r.findall(CP + 'file'):
            named.add(f.get('href'))
            if f.get('href') not in names:
                fail('imsmanifest.xml', f'{f.get("href")} is not in the zip')
        if r.get('href') not in names:
            fail('imsmanifest.xml', f'resource {r.get("identifier")}: {r.get("href")} is not in the zip')
        for d in r.findall(CP + 'dependency'):
            if d.get('identifierref') not in {x.get('identifier') for x in manifest.iter(CP + 'resource')}:
                fail('imsmanifest.xml', f'dependency on an unknown resource {d.get("identifierref")}')
    for n in names:
        if n != 'imsmanifest.xml' and n not in named:
            fail(zpath, f'{n} is in the zip but not in the manifest')

    tests = [r for r in resources.values() if r.get('type') == 'imsqti_test_xmlv2p1']
    if len(tests) != 1:
        fail('imsmanifest.xml', f'{len(tests)} tests')
        return report(failures)
    test = ET.fromstring(z.read(tests[0].get('href')))
    sections = test.findall(f'.//{QTI}assessmentSection')
    slots = sorted({e['n'] for s in key['sheets'] for e in s['exercises']})
    if len(sections) != len(slots):
        fail('test', f'{len(sections)} sections for {len(slots)} exercises')
    hrefs = {}
    section_title = {}  # n → the section's title, the exercise's heading
    for sec, n in zip(sections, slots):
        section_title[n] = sec.get('title')
        sel = sec.find(QTI + 'selection')
        if sel is None or sel.get('select') != '1':
            fail(sec.get('identifier'), 'no <selection select="1"/>')
        refs = sec.findall(QTI + 'assessmentItemRef')
        if len(refs) != len(key['sheets']):
            fail(sec.get('identifier'), f'{len(refs)} items for {len(key["sheets"])} sheets')
        for r in refs:
            if r.get('href') not in names:
                fail(sec.get('identifier'), f'{r.get("href")} is not in the zip')
            hrefs[r.get('href')] = n

    items = 0
    for sheet in key['sheets']:
        for ex in sheet['exercises']:
            where = f'{sheet["id"]} exercise {ex["n"]}'
            href = f'items/{sheet["id"]}-{ex["n"]}.xml'
            if href not in names:
                fail(where, f'no {href}')
                continue
            if hrefs.get(href) != ex['n']:
                fail(where, 'not in its exercise\'s section')
            items += 1
            item = ET.fromstring(z.read(href))
            tm = re.match(rf'^(.+) \u2014 {re.escape(sheet["id"])}$', item.get('title', ''))
            number = ex.get('number', str(ex['n']))
            if not tm or not names_number(tm.group(1), number):
                fail(where, f'title {item.get("title")!r}: not "<heading> — <sheet id>" naming {number}')
            elif section_title.get(ex['n']) != tm.group(1):
                fail(where, f'title {item.get("title")!r}, its section {section_title.get(ex["n"])!r}')
            declared = {d.get('identifier'): d for d in item.findall(QTI + 'responseDeclaration')}
            body = item.find(QTI + 'itemBody')
            interactions = [e for e in body.iter() if e.get('responseIdentifier')]
            used_body = {e.get('responseIdentifier') for e in interactions}
            processing = item.find(QTI + 'responseProcessing')
            used_rp = {e.get('identifier') for e in processing.iter() if e.tag in (QTI + 'variable', QTI + 'correct')}
            for r in declared:
                if r not in used_body:
                    fail(where, f'response {r} has no interaction')
                if r not in used_rp:
                    fail(where, f'response {r} is not processed')
            for r in used_body:
                if r not in declared:
                    fail(where, f'interaction for an undeclared response {r}')
            for img in body.iter(QTI + 'img'):
                path = os.path.normpath(os.path.join('items', img.get('src')))
                if path not in names:
                    fail(where, f'image {img.get("src")} is not in the package')
            # responses in the key's order; after them, the fields this case does not ask (no
            # correct response: marked for nothing, a feedback if answered all the same)
            qs = ex['questions']
            asked = [r for r, d in declared.items() if d.find(QTI + 'correctResponse') is not None]
            not_asked = [r for r in declared if r not in asked]
            if asked != [f'R{i + 1}' for i in range(len(qs))]:
                fail(where, f'{len(asked)} responses for {len(qs)} questions, or not first in the key\'s order')
                continue
            conditions = processing.findall(QTI + 'responseCondition')
            read_by = {}  # response → the condition whose first test reads it
            for cond in conditions:
                first = cond.find(QTI + 'responseIf')
                for v in list(first)[0].iter(QTI + 'variable'):
                    read_by.setdefault(v.get('identifier'), cond)
            for r in not_asked:
                cond = read_by.get(r)
                test = list(cond.find(QTI + 'responseIf'))[0] if cond is not None else None
                if test is None or test.tag != QTI + 'not' or cond.find(f'.//{QTI}baseValue[@baseType="float"]') is not None:
                    fail(where, f'{r}: a field not asked is scored, or not read')
            total = 0.0
            seen = set()
            for i, kq in enumerate(qs):
                rid = f'R{i + 1}'
                qwhere = f'{where} {kq["id"]}'
                cond = read_by.get(rid)
                if cond is None:
                    fail(qwhere, 'no condition reads it')
                    continue
                first = cond.find(QTI + 'responseIf')
                score = float(first.find(f'{QTI}setOutcomeValue//{QTI}baseValue').text)
                test = list(first)[0]
                e = kq['expected']
                if test.tag == QTI + 'lte':
                    # a point marked as a whole: (x − x₀)² + (y − y₀)² ≤ r², r within the key's distance
                    if kq['tolerance']['rule'] != 'distance':
                        fail(qwhere, 'marked as a whole point where the key marks coordinates')
                    coords = [v.get('identifier') for v in test.iter(QTI + 'variable')]
                    if id(cond) not in seen:
                        seen.add(id(cond))
                        group = [q for j, q in enumerate(qs) if f'R{j + 1}' in coords]
                        total += score
                        if abs(score - sum(q['points'] for q in group)) > 1e-9:
                            fail(qwhere, f'{score} points for a point worth {sum(q["points"] for q in group)}')
                        values = [float(b.text) for b in test.iter(QTI + 'baseValue') if b.get('baseType') == 'float']
                        if values[:-1] != [float(q['expected']) for q in group]:
                            fail(qwhere, f'the point {values[:-1]} is not the key\'s')
                        r2 = values[-1]
                        if r2 > kq['tolerance']['abs'] ** 2 or r2 < 0.98 * kq['tolerance']['abs'] ** 2:
                            fail(qwhere, f'radius² {r2} against the key\'s {kq["tolerance"]["abs"]}²')
                    continue
                total += score
                if abs(score - kq['points']) > 1e-9:
                    fail(qwhere, f'{score} points, not {kq["points"]}')
                d = declared[rid]
                if isinstance(e, (int, float)) and not isinstance(e, bool):
                    if d.get('baseType') != 'float':
                        fail(qwhere, f'baseType {d.get("baseType")}')
                        continue
                    value = float(d.find(f'{QTI}correctResponse/{QTI}value').text)
                    if value != float(e):
                        fail(qwhere, f'correct {value!r} is not the key\'s {e!r}')
                    if test.tag != QTI + 'equal' or test.get('toleranceMode') != 'absolute' or list(test)[0].tag != QTI + 'correct':
                        fail(qwhere, 'not an absolute <equal> with <correct> first')
                        continue
                    t = [float(x) for x in test.get('tolerance').split()]
                    if max(t) > rule_width(kq['tolerance'], e) or min(t) < 0.99 * rule_width(kq['tolerance'], e):
                        fail(qwhere, f'tolerance {t} against the key\'s {rule_width(kq["tolerance"], e)}')
                elif isinstance(e, list):
                    # a set of faces: the whole set matched, as the key marks it
                    if d.get('cardinality') != 'multiple' or test.tag != QTI + 'match':
                        fail(qwhere, 'a set of faces not matched as a whole')
                    got = {v.text for v in d.iter(QTI + 'value')}
                    want = {('F_p' if f[0] == '+' else 'F_m') + f[1:] for f in e} or {'F_none'}
                    if got != want:
                        fail(qwhere, f'correct {sorted(got)} is not the key\'s {e}')
            if abs(total - sum(q['points'] for q in qs)) > 1e-9:
                fail(where, f'the scores add up to {total}, the key\'s points to {sum(q["points"] for q in qs)}')
            check_solution(item, processing, ex, where, names, decimals, fail)
            set_ids = {b.text for b in processing.iter(QTI + 'baseValue') if b.get('baseType') == 'identifier'}
            for mf in item.findall(QTI + 'modalFeedback'):
                if mf.get('identifier') not in set_ids:
                    fail(where, f'modalFeedback {mf.get("identifier")} is never set')
    print(f'{zpath}: {len(names)} files, {items} items, {len(sections)} sections; {len(failures)} failures')
    return report(failures)


def report(failures):
    for f in failures[:60]:
        print('FAIL', f)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
