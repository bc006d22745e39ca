#!/usr/bin/env python3
"""Checks a QTI 2.1 content package written by `epure export qti` against its set's key.json
(the schemas are checked by xmllint, in tests/cli/export_test.sh):
  - every file the manifest names is in the zip, and every file of the zip is named by it;
  - every entry has the fixed timestamp (1980-01-01 00:00), so that reruns are byte-identical;
  - the test has one section per exercise, each with <selection select="1"/> and one item per sheet;
  - every item is titled `<n>. <title> — <sheet id>`; every declared response is used by an
    interaction and by the response processing, and every interaction's response is declared;
  - a float response's correct value is the key's, matched by <equal toleranceMode="absolute">
    with <correct> first and a tolerance no looser than the key's rule; the points added up are
    the key's; every modalFeedback is set by the response processing;
  - every <img> of an item is in the package.
usage: qti_check.py QTI.zip KEY.json EXTRACT_DIR
"""
import json
import math
import os
import re
import sys
import zipfile
import xml.etree.ElementTree as ET

QTI = '{http://www.imsglobal.org/xsd/imsqti_v2p1}'
CP = '{http://www.imsglobal.org/xsd/imscp_v1p1}'


def rule_width(tol, at):
    if tol['rule'] == 'isclose':
        return max(tol['rel'] * abs(at), tol['abs'])
    if tol['rule'] == 'distance':
        return tol['abs'] / math.sqrt(2)
    return 0.0


def main(argv):
    zpath, key_path, out_dir = argv[1], argv[2], argv[3]
    failures = []
    fail = lambda where, what: failures.append(f'{where}: {what}')
    key = json.load(open(key_path, encoding='utf-8'))
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
    for sec, n in zip(sections, slots):
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
            if not re.match(rf'^{ex["n"]}\. .+ \u2014 {re.escape(sheet["id"])}$', item.get('title', '')):
                fail(where, f'title {item.get("title")!r}')
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
            # responses in the key's order
            qs = ex['questions']
            if len(declared) != len(qs):
                fail(where, f'{len(declared)} responses for {len(qs)} questions')
                continue
            conditions = processing.findall(QTI + 'responseCondition')
            total = 0.0
            for i, (kq, cond) in enumerate(zip(qs, conditions)):
                rid = f'R{i + 1}'
                d = declared[rid]
                e = kq['expected']
                first = cond.find(QTI + 'responseIf')
                score = first.find(f'.//{QTI}baseValue[@baseType="float"]')
                total += float(score.text)
                if abs(float(score.text) - kq['points']) > 1e-9:
                    fail(f'{where} {kq["id"]}', f'{score.text} points, not {kq["points"]}')
                if isinstance(e, (int, float)) and not isinstance(e, bool):
                    if d.get('baseType') != 'float':
                        fail(f'{where} {kq["id"]}', f'baseType {d.get("baseType")}')
                        continue
                    value = float(d.find(f'{QTI}correctResponse/{QTI}value').text)
                    if value != float(e):
                        fail(f'{where} {kq["id"]}', f'correct {value!r} is not the key\'s {e!r}')
                    eq = first.find(QTI + 'equal')
                    if eq is None or eq.get('toleranceMode') != 'absolute' or list(eq)[0].tag != QTI + 'correct':
                        fail(f'{where} {kq["id"]}', 'not an absolute <equal> with <correct> first')
                        continue
                    t = [float(x) for x in eq.get('tolerance').split()]
                    if max(t) > rule_width(kq['tolerance'], e) or min(t) < 0.99 * rule_width(kq['tolerance'], e):
                        fail(f'{where} {kq["id"]}', f'tolerance {t} against the key\'s {rule_width(kq["tolerance"], e)}')
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
