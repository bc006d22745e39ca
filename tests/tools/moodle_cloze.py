#!/usr/bin/env python3
"""Checks a Moodle XML file written by `epure export moodle` against its set's key.json, reading
every Cloze question the way Moodle's importer does (question/type/multianswer/questiontype.php,
qtype_multianswer_extract_question), with its regular expressions:

  ANSWER_REGEX = \\{([0-9]*):(TYPE):(ALTERNATIVE(~ALTERNATIVE)*)\\}
  ALTERNATIVE  = (=|%(-?[0-9]+(?:[.,][0-9]*)?)%)?(.+?(?<!\\\\|&|&amp;)(?=[~#}]|$))(#(.*?(?<!\\\\)(?=[~}]|$)))?
  NUMERICAL    = ^(NUMBER)(:NUMBER)?$, NUMBER = -?(([0-9]+[.,]?[0-9]*|[.,][0-9]+)([eE][-+]?[0-9]+)?)

(Python's look-behind needs a fixed width: (?<!\\\\|&|&amp;) is written as three look-behinds.)
Then, for every sheet of the key and every exercise:
  - the question `<heading> — <sheet id>` (idnumber `<sheet id>-<n>`) is there, once, in the
    category `…/<heading>`, the heading the same on every sheet and naming the number its
    question ids start with (one numbering: "Exercise 3, question 3" for 3.3.t);
  - its parts are the key's questions in order (a point: x then y), each weighted by its points;
  - a number's first answer is `=` the key's value, exactly, with a tolerance that Moodle's own
    widening (question/type/numerical/question.php: + 10^-14·max(tol, |value|)) keeps within the
    key's rule at that value, and not needlessly tighter (≥ 99 % of it); Moodle's answer matching,
    simulated, accepts the key's value and values just inside, refuses values just outside;
  - the last answer of a number is a wrong one at least as wide as every other;
  - every other answer is a named mistake: 0 %, not the key's value, with a feedback that is one
    of the paper feedback's sentences (templates/text/<lang>/grading.toml);
  - choices have one right option; a set of faces is one list of every set of the sides (as the
    sheet lets any boxes be ticked), the key's set right, no part marks; every fraction one of
    Moodle's grades;
  - a field the sheet prints and the case does not ask is a weight-0 part: a box that takes a
    dash and says "not marked" for anything else, or a list whose right option is "— (does not
    apply)"; in each exercise every variant shows the same boxes (same widths) and the same
    lists, so that the question's shape does not tell the case;
  - every diagram is a base64 PNG (or SVG) <file> the text references as @@PLUGINFILE@@/name;
  - the general feedback is this variant's worked solution: its diagrams embedded in the
    feedback itself (as the importer reads generalfeedback/file), one table row per answer at
    least, and every number the key expects printed there rounded as the sheet asks (so that the
    feedback of another sheet, or an empty one, fails).
Exit status 0 when everything holds; otherwise every failure is printed.

usage: moodle_cloze.py MOODLE.xml KEY.json GRADING.toml [--summary]
"""
import base64
import html
import json
import math
import os
import re
import sys
import tomllib
import xml.etree.ElementTree as ET

FRACTION = r'=|%(-?[0-9]+(?:[.,][0-9]*)?)%'
ANSWER = r'.+?(?<!\\)(?<!&)(?<!&amp;)(?=[~#}]|$)'
FEEDBACK = r'.*?(?<!\\)(?=[~}]|$)'
ALTERNATIVE = '(' + FRACTION + ')?' + '(' + ANSWER + ')' + '(#(' + FEEDBACK + '))?'
NUMBER = r'-?(([0-9]+[.,]?[0-9]*|[.,][0-9]+)([eE][-+]?[0-9]+)?)'
NUMERICAL = '^(' + NUMBER + ')(:' + NUMBER + ')?$'
TYPES = ('(NUMERICAL|NM)|(MULTICHOICE|MC)|(MULTICHOICE_V|MCV)|(MULTICHOICE_H|MCH)|'
         '(SHORTANSWER|SA|MW)|(SHORTANSWER_C|SAC|MWC)|'
         '(MULTICHOICE_S|MCS)|(MULTICHOICE_VS|MCVS)|(MULTICHOICE_HS|MCHS)|'
         '(MULTIRESPONSE|MR)|(MULTIRESPONSE_H|MRH)|(MULTIRESPONSE_S|MRS)|(MULTIRESPONSE_HS|MRHS)')
START = r'\{([0-9]*):(' + TYPES + '):'
ANSWER_REGEX = START + '(' + ALTERNATIVE + '(~' + ALTERNATIVE + ')*)' + r'\}'
# group numbers as the importer's constants name them
REGEX_NORM, REGEX_NUMERICAL, REGEX_MULTICHOICE, REGEX_SHORTANSWER, REGEX_MULTIRESPONSE, REGEX_ALTERNATIVES = 1, 3, 4, 7, 12, 16
ALT_FRACTION, ALT_PERCENT, ALT_ANSWER, ALT_FEEDBACK = 1, 2, 3, 5

GRADES = [100, 90, 83.33333, 80, 75, 70, 66.66667, 60, 50, 40, 33.33333, 30, 25, 20, 16.66667,
          14.28571, 12.5, 11.11111, 10, 5, 0]
PHP_EPSILON = 1e-14  # 10^-precision, PHP's default precision 14


def extract(text):
    """qtype_multianswer_extract_question: the parts of a Cloze text, in order."""
    parts = []
    while True:
        m = re.search(ANSWER_REGEX, text, re.S)
        if not m:
            return parts, text
        part = {'weight': m.group(REGEX_NORM) or '1', 'alternatives': []}
        if m.group(REGEX_NUMERICAL):
            part['type'] = 'numerical'
        elif m.group(REGEX_MULTICHOICE):
            part['type'] = 'multichoice'
        elif m.group(REGEX_MULTIRESPONSE):
            part['type'] = 'multiresponse'
        elif m.group(REGEX_SHORTANSWER):
            part['type'] = 'shortanswer'
        else:
            part['type'] = m.group(2)
        remaining = m.group(REGEX_ALTERNATIVES)
        while True:
            a = re.search('~?' + ALTERNATIVE, remaining, re.S)
            if not a:
                break
            if a.group(ALT_FRACTION) == '=':
                fraction, explicit = 1.0, True
            elif a.group(ALT_PERCENT):
                fraction, explicit = 0.01 * float(a.group(ALT_PERCENT).replace(',', '.')), True
            else:
                fraction, explicit = 0.0, False
            feedback = ''
            if a.group(ALT_FEEDBACK) is not None:
                feedback = html.unescape(a.group(ALT_FEEDBACK)).replace('\\}', '}').replace('\\#', '#')
            raw = a.group(ALT_ANSWER)
            alt = {'fraction': fraction, 'percent': a.group(ALT_PERCENT), 'explicit': explicit,
                   'raw': raw, 'feedback': feedback}
            n = re.search(NUMERICAL, raw, re.S) if part['type'] == 'numerical' else None
            if n:
                alt['value'] = float(n.group(1).replace(',', '.'))
                alt['tolerance'] = float(n.group(6).replace(',', '.')) if n.group(6) else 0.0
            else:
                alt['text'] = html.unescape(raw).replace('\\}', '}').replace('\\#', '#')
            part['alternatives'].append(alt)
            remaining = remaining.split(a.group(0), 1)[1]
        parts.append(part)
        text = text.replace(m.group(0), '{#%d}' % len(parts), 1)


def moodle_interval(alt):
    """qtype_numerical_answer::get_tolerance_interval, nominal."""
    t = alt['tolerance'] + PHP_EPSILON * max(abs(alt['tolerance']), abs(alt['value']), PHP_EPSILON)
    return alt['value'] - t, alt['value'] + t


def moodle_grade(part, x):
    """The first answer whose interval holds x, as Moodle's numerical grading tries them."""
    for alt in part['alternatives']:
        if 'value' not in alt:
            continue
        lo, hi = moodle_interval(alt)
        if lo <= x <= hi:
            return alt
    return None


def rule_width(tol, at):
    if tol['rule'] == 'isclose':
        return max(tol['rel'] * abs(at), tol['abs'])
    if tol['rule'] == 'distance':
        return tol['abs'] / math.sqrt(2)
    return 0.0


def strip_tags(s):
    return re.sub(r'<[^>]+>', '', s)


def sentence_patterns(grading_toml):
    """Each paper feedback sentence as a pattern over its text without markup."""
    with open(grading_toml, 'rb') as f:
        texts = tomllib.load(f)
    out = {}
    for code, sentence in texts['grading']['mistake'].items():
        # drop the label markup as the HTML drops its tags: t_{ab} → tab, r^{2} → r2, \vec{AB} → AB
        plain = re.sub(r'\\vec\{([^}]*)\}', r'\1', sentence)
        plain = re.sub(r'[_^]\{([^}]*)\}', r'\1', plain)
        plain = re.sub(r'[_^](.)', r'\1', plain)
        parts = re.split(r'\$\{[a-z_]+\}', plain)
        out[code] = re.compile('^' + '.+?'.join(re.escape(p) for p in parts) + '$', re.S)
    return out


def shape(part):
    """What a student sees of a part: a box and its width (Moodle sizes it after the longest
    answer), or a list and its options in order."""
    if part['type'] in ('numerical', 'shortanswer'):
        return ('box', max(len(a['raw'].split(':')[0]) if 'value' in a else len(a['text']) for a in part['alternatives']))
    return (part['type'], tuple(a['text'] for a in part['alternatives']))


def shown(x, decimals, comma):
    """A number as the key prints it: rounded to the set's decimals, no trailing zeros, the
    language's decimal mark, a real minus sign."""
    t = f'{round(x, decimals):.{decimals}f}'.rstrip('0').rstrip('.')
    if t in ('-0', ''):
        t = '0'
    if comma:
        t = t.replace('.', ',')
    return t.replace('-', '\u2212')


def names_number(heading, number):
    """Whether a heading names the exercise its ids' number stands for: each part of the number
    ("3.3": 3 then 3; "P") is, in order, a word of the heading or a word's first letter(s)
    ("Exercise 3, question 3"; "Preamble")."""
    words = re.findall(r'\w+', heading)
    i = 0
    for part in number.split('.'):
        while i < len(words) and not (words[i] == part or (part.isalpha() and words[i].startswith(part))):
            i += 1
        if i == len(words):
            return False
        i += 1
    return True


def face_set(text, none_word):
    """The set of faces a list option names ("+x, \u2212y"), with the contract's '-'."""
    if text == none_word:
        return set()
    return {f.strip().replace('\u2212', '-') for f in text.split(',')}


def main(argv):
    if len(argv) < 4:
        print(__doc__)
        return 2
    summary = '--summary' in argv
    moodle_path, key_path, grading_path = argv[1], argv[2], argv[3]
    failures = []

    def fail(where, what):
        failures.append(f'{where}: {what}')

    key = json.load(open(key_path, encoding='utf-8'))
    sentences = sentence_patterns(grading_path)
    root = ET.parse(moodle_path).getroot()
    if root.tag != 'quiz':
        fail(moodle_path, f'the root is <{root.tag}>, not <quiz>')

    questions = {}  # (n, sheet id) → (category, question element)
    category = None
    for q in root.findall('question'):
        if q.get('type') == 'category':
            category = q.findtext('category/text')
            continue
        name = q.findtext('name/text')
        m = re.match(r'^(.+) \u2014 (\S+)$', name or '')
        idm = re.match(r'^(\S+)-(\d+)$', q.findtext('idnumber') or '')
        if not m or not idm or idm.group(1) != m.group(2):
            fail(moodle_path, f'a question named {name!r} does not read "<heading> — <sheet id>" with the idnumber '
                              '"<sheet id>-<n>"')
            continue
        k = (int(idm.group(2)), m.group(2))
        if k in questions:
            fail(name, 'twice')
        questions[k] = (category, q, m.group(1))
        if q.get('type') != 'multianswer':
            fail(name, f'type {q.get("type")}, not multianswer')

    counts = {'questions': 0, 'parts': 0, 'numbers': 0, 'mistakes': 0, 'images': 0, 'choices': 0, 'faces': 0,
              'not_asked': 0, 'feedbacks': 0, 'feedback_images': 0}
    shapes = {}  # exercise n → [(where, [shape of each part])]
    with open(grading_path, 'rb') as f:
        export_words = tomllib.load(f)['export']
    does_not_apply = export_words['does_not_apply']
    not_asked_feedback = export_words['not_asked']
    with open(grading_path.replace('grading.toml', 'common.toml'), 'rb') as f:
        none_word = tomllib.load(f)['common']['none']

    def check_not_asked(part, where, fail):
        alts = part['alternatives']
        if part['type'] == 'shortanswer':
            right = [a['text'] for a in alts if a['fraction'] == 1.0]
            if set(right) != {'-', '\u2013', '\u2014', '\u2212'}:
                fail(where, f'a box not asked takes {right}, not the dashes')
            star = [a for a in alts if a['text'] == '*']
            if len(star) != 1 or star[0]['fraction'] != 0 or strip_tags(star[0]['feedback']) != not_asked_feedback:
                fail(where, 'a box not asked does not say so for any other answer')
        elif part['type'] == 'multichoice':
            right = [a['text'] for a in alts if a['fraction'] == 1.0]
            if right != [does_not_apply]:
                fail(where, f'a list not asked has {right} right, not {does_not_apply!r}')
        else:
            fail(where, f'a field not asked as {part["type"]}')

    decimals = key['spec'].get('decimals', 2)
    comma = os.path.basename(os.path.dirname(os.path.abspath(grading_path))) == 'fr'  # the texts' language

    def check_feedback(q, ex, where, fail):
        gf = q.find('generalfeedback')
        if gf is None or gf.get('format') != 'html':
            fail(where, 'no general feedback in HTML')
            return
        text = gf.findtext('text') or ''
        files = {f.get('name'): f for f in gf.findall('file')}
        refs = re.findall(r'@@PLUGINFILE@@/([^"]+)"', text)
        if not refs:
            fail(where, 'the general feedback has no diagram')
        for r in refs:
            f = files.get(r)
            if f is None or f.get('encoding') != 'base64' or f.get('path') != '/':
                fail(where, f'the general feedback shows {r}, which it does not embed')
                continue
            data = base64.b64decode(f.text or '', validate=True)
            if not (data.startswith(b'\x89PNG\r\n\x1a\n') or b'<svg' in data[:2000]):
                fail(where, f'{r} in the general feedback is neither a PNG nor an SVG')
            counts['feedback_images'] += 1
        for name in files:
            if name not in refs:
                fail(where, f'{name} is embedded in the general feedback but not shown')
        plain = html.unescape(re.sub(r'<[^>]+>', '', text))
        if text.count('<tr>') < 1:
            fail(where, 'the general feedback has no answers')
        for kq in ex['questions']:
            e = kq['expected']
            if isinstance(e, (int, float)) and not isinstance(e, bool) and shown(e, decimals, comma) not in plain:
                fail(f'{where} {kq["id"]}', f'the general feedback does not show the key\'s {shown(e, decimals, comma)}')
        counts['feedbacks'] += 1

    codes_seen = set()
    headings = {}  # n → the name the first sheet gives it
    title = key['spec']['title']
    for sheet in key['sheets']:
        for ex in sheet['exercises']:
            where = f'{sheet["id"]} exercise {ex["n"]}'
            if (ex['n'], sheet['id']) not in questions:
                fail(where, 'no question')
                continue
            cat, q, ex_title = questions.pop((ex['n'], sheet['id']))
            counts['questions'] += 1
            expected_cat = f'$course$/top/{title.replace("/", "//")}/{ex_title.replace("/", "//")}'
            if cat != expected_cat:
                fail(where, f'in category {cat!r}, not {expected_cat!r}')
            # one numbering: the name is the sheet's heading, the one its ids' number stands for
            number = ex.get('number', str(ex['n']))
            if not names_number(ex_title, number):
                fail(where, f'named {ex_title!r}, which does not say {number}, the number of its ids')
            if headings.setdefault(ex['n'], ex_title) != ex_title:
                fail(where, f'named {ex_title!r}, another sheet {headings[ex["n"]]!r}')
            if any(not kq['id'].startswith(number + '.') for kq in ex['questions']):
                fail(where, f'a question id does not start with its number {number}')
            text = q.findtext('questiontext/text') or ''
            # images: every <file> referenced, every reference a <file>
            files = {f.get('name'): f for f in q.findall('questiontext/file')}
            refs = re.findall(r'@@PLUGINFILE@@/([^"]+)"', text)
            if not refs:
                fail(where, 'no diagram')
            for r in refs:
                f = files.get(r)
                if f is None:
                    fail(where, f'the text shows {r}, which is not embedded')
                    continue
                if f.get('encoding') != 'base64' or f.get('path') != '/':
                    fail(where, f'{r}: not a base64 file at path /')
                data = base64.b64decode(f.text or '', validate=True)
                if r.endswith('.png') and not data.startswith(b'\x89PNG\r\n\x1a\n'):
                    fail(where, f'{r}: not a PNG')
                if r.endswith('.svg') and b'<svg' not in data[:2000]:
                    fail(where, f'{r}: not an SVG')
                counts['images'] += 1
            for name in files:
                if name not in refs:
                    fail(where, f'{name} is embedded but not shown')

            check_feedback(q, ex, where, fail)

            all_parts, rest = extract(text)
            if re.search(r'\{[0-9]*:[A-Z_]+:', rest):
                fail(where, 'a part the importer would not read is left in the text')
            shapes.setdefault(ex['n'], []).append((where, [shape(p) for p in all_parts]))
            # weight 0: a field the sheet prints and this case does not ask, marked for nothing
            parts = [p for p in all_parts if p['weight'] != '0']
            for p in all_parts:
                if p['weight'] == '0':
                    counts['not_asked'] += 1
                    check_not_asked(p, where, fail)
            qs = ex['questions']
            if len(parts) != len(qs):
                fail(where, f'{len(parts)} parts for {len(qs)} questions')
                continue
            weights = [int(p['weight']) for p in parts]
            scale = weights[0] / qs[0]['points'] if qs[0]['points'] else 1
            for part, kq in zip(parts, qs):
                qwhere = f'{where} {kq["id"]}'
                counts['parts'] += 1
                if abs(int(part['weight']) - kq['points'] * scale) > 1e-9:
                    fail(qwhere, f'weight {part["weight"]} is not the key\'s {kq["points"]} points × {scale}')
                for alt in part['alternatives']:
                    if alt['percent'] is not None and not any(
                            abs(abs(float(alt['percent'].replace(',', '.'))) - g) < 1e-9 for g in GRADES):
                        fail(qwhere, f'fraction {alt["percent"]}% is not one of Moodle\'s grades')
                e = kq['expected']
                alts = part['alternatives']
                if isinstance(e, (int, float)) and not isinstance(e, bool):
                    counts['numbers'] += 1
                    if part['type'] != 'numerical':
                        fail(qwhere, f'a number asked as {part["type"]}')
                        continue
                    # qtype_multianswer_validate_question: every answer of a number a number
                    if any('value' not in a for a in alts):
                        fail(qwhere, 'an answer that is not a number (the import refuses the question)')
                        continue
                    right = alts[0]
                    if right['fraction'] != 1.0 or 'value' not in right:
                        fail(qwhere, 'the first answer is not the right value')
                        continue
                    if right['value'] != float(e):
                        fail(qwhere, f'right value {right["raw"]} is not the key\'s {e!r}')
                    width = rule_width(kq['tolerance'], e)
                    lo, hi = moodle_interval(right)
                    if max(e - lo, hi - e) > width:
                        fail(qwhere, f'tolerance {right["tolerance"]!r} is looser than the key\'s {width!r} once '
                                     'Moodle widens it')
                    if right['tolerance'] < 0.99 * width:
                        fail(qwhere, f'tolerance {right["tolerance"]!r} is needlessly tighter than the key\'s {width!r}')
                    for x in (e, e + 0.999 * right['tolerance'], e - 0.999 * right['tolerance']):
                        if moodle_grade(part, x) is not right:
                            fail(qwhere, f'{x!r} is not accepted as right')
                    for x in (e + width * (1 + 1e-9) + 1e-12, e - width * (1 + 1e-9) - 1e-12):
                        if moodle_grade(part, x) is right:
                            fail(qwhere, f'{x!r}, outside the key\'s rule, is accepted as right')
                    wide = alts[-1]
                    # Moodle sizes the box after the longest answer's value (the part before ':')
                    length = lambda a: len(a['raw'].split(':')[0])
                    if wide['fraction'] != 0 or wide['feedback'] or length(wide) < max(length(a) for a in alts):
                        fail(qwhere, 'the last answer is not a wide wrong one')
                    for alt in alts[1:-1]:
                        counts['mistakes'] += 1
                        if alt['fraction'] != 0 or alt['percent'] != '0':
                            fail(qwhere, f'a mistake worth {alt["fraction"]}')
                        if abs(alt['value'] - e) <= 1e-9 * max(1, abs(e)):
                            fail(qwhere, f'mistake value {alt["raw"]} is the key\'s value')
                        plain = strip_tags(alt['feedback'])
                        codes = [c for c, p in sentences.items() if p.match(plain)]
                        if not codes:
                            fail(qwhere, f'feedback {plain!r} is none of the paper feedback\'s sentences')
                        codes_seen.update(codes)
                elif isinstance(e, list):
                    counts['faces'] += 1
                    # the set as a whole, as the key marks it: one list of the candidate sets
                    if part['type'] != 'multichoice':
                        fail(qwhere, f'a set of faces asked as {part["type"]}')
                        continue
                    texts = [a['text'] for a in alts]
                    right = [a for a in alts if a['fraction'] == 1.0]
                    if len(right) != 1 or any(a['fraction'] not in (0.0, 1.0) for a in alts):
                        fail(qwhere, f'{len(right)} right options, or part marks, among {len(alts)}')
                        continue
                    if face_set(right[0]['text'], none_word) != set(e):
                        fail(qwhere, f'right option {right[0]["text"]!r} is not the key\'s {e}')
                    sets = [face_set(t, none_word) for t in texts if t != does_not_apply]
                    sides = {f for st in sets for f in st}
                    if len(sets) != 2 ** len(sides) or len({frozenset(x) for x in sets}) != len(sets):
                        fail(qwhere, f'{len(sets)} sets of {len(sides)} sides, or a set twice')
                    if len(texts) != len(set(texts)):
                        fail(qwhere, 'an option twice')
                    for alt in alts:
                        if alt['feedback']:
                            counts['mistakes'] += 1
                            codes = [c for c, p in sentences.items() if p.match(strip_tags(alt['feedback']))]
                            if not codes:
                                fail(qwhere, f'feedback {alt["feedback"]!r} is none of the paper sentences')
                            codes_seen.update(codes)
                else:
                    counts['choices'] += 1
                    if part['type'] != 'multichoice':
                        fail(qwhere, f'a choice asked as {part["type"]}')
                        continue
                    right = [a for a in alts if a['fraction'] == 1.0]
                    if len(right) != 1 or len(alts) < 2:
                        fail(qwhere, f'{len(right)} right options among {len(alts)}')
                    for alt in alts:
                        if alt['feedback']:
                            counts['mistakes'] += 1
                            if alt['fraction'] != 0:
                                fail(qwhere, 'a mistake on the right option')
                            codes = [c for c, p in sentences.items() if p.match(strip_tags(alt['feedback']))]
                            if not codes:
                                fail(qwhere, f'feedback {alt["feedback"]!r} is none of the paper sentences')
                            codes_seen.update(codes)
    # the question's shape does not tell the case: in each exercise, every variant has the same
    # boxes (same widths) and lists (same options, whichever is right), in the same order
    for n, variants in shapes.items():
        first_where, first = variants[0]
        for where, sh in variants[1:]:
            if sh != first:
                fail(where, f'its parts look unlike {first_where}\'s: {sh} against {first}')
                break
    for (n, sid), _ in questions.items():
        fail(f'{sid} exercise {n}', 'a question the key does not have')
    if counts['mistakes'] == 0:
        fail(moodle_path, 'no named mistake at all')

    for f in failures[:60]:
        print('FAIL', f)
    if len(failures) > 60:
        print(f'… and {len(failures) - 60} more')
    if summary or failures:
        print(f'{moodle_path}: {counts["questions"]} questions, {counts["parts"]} parts ({counts["numbers"]} numbers, '
              f'{counts["choices"]} choices, {counts["faces"]} face sets, {counts["not_asked"]} fields not asked), '
              f'{counts["mistakes"]} named-mistake answers '
              f'({len(codes_seen)} mistakes: {", ".join(sorted(codes_seen))}), {counts["images"]} images; '
              f'{counts["feedbacks"]} general feedbacks with {counts["feedback_images"]} diagrams; '
              f'{len(failures)} failures')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
