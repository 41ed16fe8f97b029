#!/usr/bin/env python3
"""The public contracts of certbox, read from the headers (include/cbx_api.h for
both families, include/certbox.h for the binary64-only functions), split into
clauses.  Used by scripts/evidence.py; run alone it lists every clause key.

A clause key is BEHAVIOR/KIND/LABEL: the behavior ('-' outside any), the
clause kind (requires, assigns, assumes, ensures, complete, disjoint) and its
label (its ACSL name, or its position among the unnamed clauses of that kind
in that behavior: 1, 2, ...)."""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def macro(name):
    """The parameters and body of a contract macro of specs/ (MACROS)."""
    text = ''.join(open(os.path.join(ROOT, 'specs', f), encoding='utf-8').read()
                   for f in MACRO_FILES)
    m = re.search(r'#define %s\(([^)]*)\)\s*\\\n(.*?)(?<!\\)\n' % name, text, re.S)
    params = [p.strip() for p in m.group(1).split(',')]
    body = re.sub(r'\\\n', '\n', m.group(2))
    return params, body


MACROS = ('CBX_BOX_BEHAVIORS', 'CBX_BATCH_POST', 'CBX_TIGHT_NEAR')
MACRO_FILES = ('cbx_logic.h', 'cbx_tight_gap.h')


def expand(contract):
    """Expand the contract macros (MACROS) used in a contract."""
    def rep(m):
        params, body = macro(m.group(1))
        args = [a.strip() for a in m.group(2).split(',')]
        for p, a in zip(params, args):
            body = re.sub(r'\b%s\b' % re.escape(p), lambda _m, a=a: a, body)
        return body
    return re.sub(r'\b(%s)\(([^)]*)\)' % '|'.join(MACROS), rep, contract)


def functions():
    """[(name, family, doc comment, contract text, prototype)]; family: 'both'
    (cbx_api.h), '64' (certbox.h) or '32' (certbox.h's binary32 twins)"""
    out = []
    for fname, fam in (('cbx_api.h', 'both'), ('certbox.h', '64')):
        text = open(os.path.join(ROOT, 'include', fname), encoding='utf-8').read()
        for m in re.finditer(r'((?:/\*(?!@)(?:[^*]|\*(?!/))*\*/\s*)*)/\*@(.*?)\*/\s*\n'
                             r'((?:cbx_status|cbx_class|unsigned|void|const char \*)\s+(cbx_\w+)\((?:[^;])*\);)',
                             text, re.S):
            doc = m.group(1).strip()
            docs = re.findall(r'/\*(?:[^*]|\*(?!/))*\*/', doc)
            doc = docs[-1] if docs else ''
            doc = re.sub(r'^/\*\s?|\s*\*/$', '', doc)
            doc = '\n'.join(re.sub(r'^\s*\* ?', '', l) for l in doc.splitlines()).strip()
            proto = ' '.join(m.group(3).split())
            # certbox.h's binary32 twins (float inputs over a binary64 call)
            own = '32' if fam == '64' and 'cbx_projf' in proto else fam
            out.append((m.group(4), own, doc, expand(m.group(2)), proto))
    return out


def clauses(contract):
    """[(key, kind, text)] in order."""
    text = re.sub(r'//[^\n]*', '', contract)
    out = []
    bhv = '-'
    count = {}
    pieces = []
    for raw in text.split(';'):
        # a quantifier's binder (\forall integer k;) ends in ';' too
        if pieces and (re.search(r'\\(forall|exists)\s+[\w\s,]*$', pieces[-1])
                       or re.search(r'\\let\s+\w+\s*=[^;]*$', pieces[-1])):
            pieces[-1] += ';' + raw
        else:
            pieces.append(raw)
    for raw in pieces:
        c = ' '.join(raw.split())
        if not c:
            continue
        m = re.match(r'behavior (\w+):\s*(.*)$', c)
        if m:
            bhv = m.group(1)
            c = m.group(2)
            if not c:
                continue
        kind = c.split()[0]
        if kind == 'complete' or kind == 'disjoint':
            out.append(('-/%s/behaviors' % kind, kind, c))
            continue
        body = c[len(kind):].strip()
        m = re.match(r'(\w+)\s*:(?!:)\s*(.*)$', body)
        if m and kind in ('requires', 'ensures', 'assumes'):
            label, body = m.group(1), m.group(2)
        else:
            n = count.get((bhv, kind), 0) + 1
            count[(bhv, kind)] = n
            label = str(n)
        out.append(('%s/%s/%s' % (bhv, kind, label), kind, '%s %s;' % (kind, body) if kind != 'assigns' else c + ';'))
    return out


if __name__ == '__main__':
    for name, fam, doc, contract, proto in functions():
        print('[%s] (%s) %s' % (name, fam, proto))
        for key, kind, text in clauses(contract):
            print('  %-28s %s' % (key, text[:90]))
    sys.exit(0)
