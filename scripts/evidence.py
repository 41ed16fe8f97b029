#!/usr/bin/env python3
"""make evidence: the evidence pack an assessor asks for, in build/evidence/
(under build/: making the pack changes no tracked file).

  build/evidence/index.md       the pack for a reader (claims, proof, tests,
                                coverage, coding standard, tools, hashes)
  build/evidence/evidence.json  the same, machine-readable
  build/evidence/raw/           what it was made from: proof report and logs,
                                test outputs, gcovr's JSON, cppcheck and
                                clang-tidy output

Sections:
  claims    every public function's contract: each clause's formal text (the
            header's ACSL) next to its plain words (scripts/evidence/claims.txt);
            fails on a clause without plain words or a stale entry
  proof     goals per function and family (proved / total, provers), the
            trusted base (proofs/README.md), the smoke tests; from the logs
            of the last proof run (build/proof: its logs and report.md;
            make proof-check), which must have proved these very sources
            (proofs/inputs.sh; make evidence runs the proofs first when it
            did not)
  tests     every exact suite run (the sizes of make test), its cases,
            failures, containment checks and failures, tightness figures
  coverage  statement and branch coverage of src/ by those suites (gcovr),
            every uncovered line or branch matched to a justification in
            scripts/evidence/coverage.txt (fails on one without)
  standard  cppcheck with its MISRA C:2012 addon and clang-tidy on src/, every
            finding matched to a deviation in scripts/evidence/deviations.txt
            (fails on one without)
  tools     versions; git revision; SHA-256 of every tracked file and of the
            built libraries

Reproducible: the content depends only on the revision and the tools; what
varies between runs (time stamps, durations, which racing prover answered
first) is kept under the JSON key "volatile" and in the last section of
index.md, which `evidence.py --compare A B` leaves out.
Usage: scripts/evidence.py [OUTDIR (build/evidence)]  |  scripts/evidence.py --compare DIR1 DIR2
"""
import datetime
import fcntl
import glob
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# the library's include folders (scripts/incs.sh: one list for every build)
INCS = subprocess.check_output(['sh', os.path.join(ROOT, 'scripts', 'incs.sh')], text=True).split()
# the oracles and helpers every test links (scripts/testutil.sh)
TESTUTIL = subprocess.check_output(['sh', os.path.join(ROOT, 'scripts', 'testutil.sh')], text=True).split()
sys.path.insert(0, os.path.join(ROOT, 'scripts', 'evidence'))
sys.path.insert(0, os.path.join(ROOT, 'proofs'))
import contracts  # noqa: E402

CC = os.environ.get('CC', 'cc')
FLAGS = ['-std=c99', '-Wall', '-Wextra', '-Wpedantic', '-Werror', '-ffp-contract=off', '-fno-fast-math']
# The suites and their sizes here: every table and hard-case list of make
# test, with fewer random cases (coverage saturates long before; make test
# runs the full sizes).  2026-12-01, to keep make check within CI's 30
# minutes, seven halved (batch, classes, project, trs, pnear, pball, pell:
# a pack 100 s instead of 115 s); pwide halved left a branch of
# src/f64/cbx_psph.c untaken, so it stays.  Each runs twice: the library
# as built (-O2) for the figures, and a -O0 --coverage build for coverage,
# whose output must be the same line for line.  test_ieee runs in every
# mode it has.
SUITES = [
    ('badinput', []), ('special', []), ('exact', ['100000', '1']), ('cbox', ['30000', '1']),
    ('sphere', ['20000', '1']), ('alias', ['10000', '1']), ('halfspace', ['20', '1']),
    ('chain', ['200', '5', '1']), ('batch', ['25', '1']), ('tight', ['10', '1']),
    ('classes', ['10000', '1']), ('float', ['50000', '1']), ('imat', ['40000', '10000', '1']), ('plane', ['20000', '1']), ('project', ['2000', '1']), ('trs', ['1500', '1']), ('psphere', ['4000', '1']), ('pnear', ['2000', '1']), ('pball', ['2000', '1']), ('pwide', ['3000', '1']), ('pell', ['2000', '1']), ('ieee', []),
    ('ieee', ['ftz', '4']), ('ieee', ['ftzonly', '4']), ('ieee', ['daz', '4']), ('ieee', ['up', '8']), ('ieee', ['down', '8']), ('ieee', ['zero', '8']),
    ('scene', sorted(glob.glob(os.path.join(ROOT, 'examples', '*.scene')))),
    # the scene tool's glTF reader (tools/certbox/gltf.c), against GMP, on
    # assimp-testmodels and tests/data/gltf; it runs the tool build/certbox
    ('gltf', ['/usr/share/assimp/models/glTF2', 'tests/data/gltf', 'build/certbox', '20000']),
]
# GMP and MPFR linked as the Makefile's tests are (scripts/exactlibs.sh)
EXACTLIBS = subprocess.check_output(['sh', os.path.join(ROOT, 'scripts', 'exactlibs.sh'), CC], text=True).split()
# test_gltf needs jansson (the tool's optional dependency; scripts/deps.sh
# test installs it): without it the suite is not run and the pack fails
HAVE_JANSSON = subprocess.run(['pkg-config', '--exists', 'jansson']).returncode == 0


def jansson_flags(kind):
    return subprocess.run(['pkg-config', kind, 'jansson'], capture_output=True, text=True).stdout.split()


def run_name(i):
    name, args = SUITES[i]
    same = [k for k, (n, _) in enumerate(SUITES) if n == name]
    return name if len(same) == 1 else '%s.%d' % (name, same.index(i) + 1)


def normal(text):
    """A suite's output without what may differ between two runs: durations."""
    text = re.sub(r'[0-9]+(\.[0-9]+)? ?(s|ms|seconds)\b', '<time>', text)
    # test_ieee's compiler probe reports what the optimizer does: it differs
    # between -O0 and -O2 by design and is not a result
    return '\n'.join(l for l in text.splitlines()
                     if 'CPU time' not in l and 'probe (not counted)' not in l) + '\n'
failures = []


def sh(cmd, cwd=ROOT, check=True, **kw):
    r = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, **kw)
    if check and r.returncode:
        sys.stderr.write(r.stdout[-3000:] + r.stderr[-3000:])
        raise SystemExit('evidence: failed: %s' % ' '.join(cmd))
    return r


def first_line(cmd):
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, shell=True).stdout.strip()
        return out.splitlines()[0] if out else 'not found'
    except OSError:
        return 'not found'


# ---- claims ------------------------------------------------------------------

def load_claims():
    table, cur = {}, None
    for line in open(os.path.join(ROOT, 'scripts', 'evidence', 'claims.txt'), encoding='utf-8'):
        line = line.rstrip('\n')
        if not line.strip() or line.startswith('#'):
            continue
        m = re.match(r'\[(.+)\]$', line.strip())
        if m:
            cur = m.group(1)
            table[cur] = {}
            continue
        key, _, text = line.partition(': ')
        table[cur][key.strip()] = text.strip()
    return table


def f32_name(name):
    return name + 'f'


def claims():
    table = load_claims()
    used = set()
    out = []
    for name, fam, doc, contract, proto in contracts.functions():
        own = table.get(name, {})
        rows = []
        for key, kind, text in contracts.clauses(contract):
            plain = own.get(key, table['*'].get(key))
            if plain is None:
                failures.append('claims: %s %s has no plain words in scripts/evidence/claims.txt' % (name, key))
                plain = '(missing)'
            if key in own:
                used.add((name, key))
            else:
                used.add(('*', key))
            rows.append({'key': key, 'formal': text, 'plain': plain})
        fams = {'64': ['binary64'], '32': ['binary32']}.get(fam, ['binary64', 'binary32'])
        out.append({'function': name, 'binary32': f32_name(name) if fam == 'both' else None,
                    'families': fams, 'prototype': proto.replace('cbx_fp', 'double'),
                    'summary': doc, 'clauses': rows})
    for fn, entries in table.items():
        for key in entries:
            if (fn, key) not in used:
                failures.append('claims: stale entry [%s] %s (no such clause)' % (fn, key))
    out.append({'function': 'cbx_status_name', 'binary32': None, 'families': ['binary64', 'binary32'],
                'prototype': 'const char *cbx_status_name(cbx_status s);',
                'summary': 'The name of a status. No contract beyond WP\'s run-time-error goals (proven: no undefined behaviour).',
                'clauses': []})
    out.append({'function': 'cbx_ieee_check', 'binary32': None, 'families': ['binary64', 'binary32'],
                'prototype': 'unsigned cbx_ieee_check(void);',
                'summary': 'The build check: not part of the proven set (it tests the build, '
                           'not the algorithm); tested by make ieee-check and make check-cross.',
                'clauses': []})
    return out


# ---- proof ---------------------------------------------------------------------

def proof(raw):
    import report  # proofs/report.py
    d = os.path.join(ROOT, 'build', 'proof')
    if not glob.glob(os.path.join(d, 'wp-*.log')):
        failures.append('proof: no proof logs in build/proof (run make proof first)')
        return {}, {}
    digest = sh(['sh', 'proofs/inputs.sh']).stdout.strip()
    stamp = os.path.join(d, 'inputs.sha256')
    ran_on = open(stamp).read().strip() if os.path.exists(stamp) else None
    if ran_on != digest:
        failures.append('proof: the logs in build/proof are not from a run on these sources '
                        '(proofs/inputs.sh: %s, the run: %s); run make proof' % (digest, ran_on))
    data = report.collect(d)
    os.makedirs(os.path.join(raw, 'proof'), exist_ok=True)
    for pat in ('wp-*.log', 'wp-*.json', 'wp-*.runs'):
        for f in glob.glob(os.path.join(d, pat)):
            shutil.copy(f, os.path.join(raw, 'proof'))
    # the report of that very run (proofs/run.sh writes it beside the logs;
    # the committed proofs/report.md may be older: make proof-report)
    rep = os.path.join(d, 'report.md')
    if os.path.exists(rep):
        shutil.copy(rep, os.path.join(raw, 'proof', 'report.md'))
        if 'from a kept WP cache' in open(rep).read():
            failures.append('proof: build/proof is a make proof run from a kept WP cache; '
                            'the evidence needs a from-scratch run (make proof-check)')
    else:
        failures.append('proof: no build/proof/report.md beside the logs (run make proof)')
    if not data['ok']:
        failures.append('proof: not every goal proved, or a smoke test failed, or a job did not finish')
    stable = {'families': {}, 'total': data['total'], 'proved': data['proved'],
              'smoke_tests': data['smoke'], 'smoke_failed': len(data['bad_smoke']),
              'unproved': data['failed'], 'errors': data['errors'], 'unfinished': data['unfinished'],
              'result': 'PROVED' if data['ok'] else 'NOT PROVED',
              'inputs_sha256': digest,
              'model': 'Frama-C/WP default float model (IEEE, round to nearest), Typed memory, -wp-rte, every goal proved by a prover in this run (no job keeps a WP cache)'}
    volatile = {'provers': {}, 'wall_seconds_per_job': data['job_time']}
    for fam, per in data['per'].items():
        stable['families'][fam] = {f: {'proved': v['ok'], 'total': v['n']} for f, v in sorted(per.items())}
        volatile['provers'][fam] = {f: v['provers'] for f, v in sorted(per.items())}
    trusted = []
    text = open(os.path.join(ROOT, 'proofs', 'README.md'), encoding='utf-8').read()
    sect = text.split('## Trusted base', 1)[1].split('\n## ', 1)[0]
    for line in sect.splitlines():
        m = re.match(r'\| (.+?) \| (.+) \|$', line)
        if m and not m.group(1).startswith('item') and not m.group(1).startswith('---'):
            trusted.append({'item': m.group(1), 'why': m.group(2)})
    stable['trusted_base'] = trusted
    return stable, volatile


# ---- tests ---------------------------------------------------------------------

CHECK = re.compile(r'^\s*check\s+(\S+)\s+(\d+)\s+(.+?)\s+checked,\s+(\d+) failed', re.M)
CONTAIN_FAIL = re.compile(r'containment failures:?\s*(\d+)')
LAST = re.compile(r'^(\d+) passed, (\d+) failed\s*$', re.M)


def tests(raw):
    out, volatile = [], {}
    os.makedirs(os.path.join(raw, 'tests'), exist_ok=True)
    for i, (name, args) in enumerate(SUITES):
        exe = os.path.join(ROOT, 'build', 'test_' + name)
        if name == 'gltf':
            if not HAVE_JANSSON:
                failures.append('tests: jansson (libjansson-dev) not found: test_gltf not run (scripts/deps.sh test)')
                continue
            sh(['make', '-s', 'build/certbox'])
        sh(['make', '-s', 'build/test_' + name])
        r = sh([exe] + args, check=False)
        text = r.stdout + r.stderr
        shown = [a if not a.startswith(ROOT) else os.path.relpath(a, ROOT) for a in args]
        stable_text = normal(text)
        open(os.path.join(raw, 'tests', run_name(i) + '.txt'), 'w').write(stable_text)
        m = LAST.findall(text)
        passed, failed = (int(m[-1][0]), int(m[-1][1])) if m else (0, -1)
        checks = [{'check': c[0], 'checked': int(c[1]), 'unit': c[2], 'failed': int(c[3])}
                  for c in CHECK.findall(text)]
        cont_checked = sum(c['checked'] for c in checks if 'contain' in c['check'] or 'corner' in c['check'])
        cont_failed = sum(c['failed'] for c in checks if 'contain' in c['check'] or 'corner' in c['check'])
        cont_failed += sum(int(x) for x in CONTAIN_FAIL.findall(text))
        tight = [' '.join(l.split()) for l in stable_text.splitlines()
                 if re.search(r'excess|ulps|units of', l) and re.search(r'max', l)][:8]
        row = {'suite': 'test_' + name, 'args': ' '.join(shown), 'exit': r.returncode,
               'passed': passed, 'failed': failed, 'checks': checks,
               'containment_checked': cont_checked, 'containment_failed': cont_failed, 'tightness': tight}
        if r.returncode or failed != 0 or cont_failed:
            failures.append('tests: test_%s failed (exit %d, %d failed, %d containment failures)'
                            % (name, r.returncode, failed, cont_failed))
        out.append(row)
    return out, volatile


# ---- coverage ------------------------------------------------------------------

def coverage(raw, b):
    """Statement and branch coverage of src/ by the suites (gcovr); the
    instrumented build goes to b (one per pack: two packs can be made at
    once)."""
    if not shutil.which('gcovr'):
        failures.append('coverage: gcovr not installed (scripts/deps.sh evidence)')
        return {}
    shutil.rmtree(b, ignore_errors=True)
    os.makedirs(os.path.join(b, 'obj'))
    objs = []
    for s in sorted(glob.glob(os.path.join(ROOT, 'src', '*', 'cbx_*.c'))):
        o = os.path.join(b, 'obj', os.path.basename(s)[:-2] + '.o')
        sh([CC] + FLAGS + ['-O0', '--coverage', *INCS, '-c', s, '-o', o])
        objs.append(o)
    scene = []
    for s in ['tools/certbox/scene.c']:
        o = os.path.join(b, 'obj', 'scene.o')
        sh([CC] + FLAGS + ['-O0', *INCS, '-Itools/certbox', '-c', s, '-o', o])
        scene.append(o)
    same = []
    gltf = []
    if HAVE_JANSSON:
        # the glTF reader, test_gltf's oracle and --animated checks (not measured: tools/certbox is
        # left out below, like scene.c)
        for s, o in [('tools/certbox/gltf.c', 'gltf.o'), ('tests/gltf_oracle.c', 'gltf_oracle.o'),
                     ('tests/gltf_anim.c', 'gltf_anim.o')]:
            o = os.path.join(b, 'obj', o)
            sh([CC] + FLAGS + ['-O0', '-DCBX_GLTF'] + jansson_flags('--cflags')
               + [*INCS, '-Itools/certbox', '-Itests', '-c', s, '-o', o])
            gltf.append(o)
    # the exact oracles and the tests' parts, compiled once into an archive
    # (not measured: only src/ and include/ are, from the library's
    # objects); a test links the members it uses, as with make's archive
    tu = []
    for s in TESTUTIL:
        o = os.path.join(b, 'tu_' + os.path.basename(s)[:-2] + '.o')
        sh([CC] + FLAGS + ['-O0', *INCS, '-Itests', '-c', s, '-o', o])
        tu.append(o)
    tua = os.path.join(b, 'libtestutil.a')
    sh(['ar', 'rcs', tua] + tu)
    tu = [tua]
    for i, (name, args) in enumerate(SUITES):
        exe = os.path.join(b, 'test_' + name)
        if name == 'gltf' and not HAVE_JANSSON:
            continue
        if not os.path.exists(exe):
            extra = scene + ['-Itools/certbox'] if name == 'scene' else []
            if name == 'gltf':
                extra = gltf + ['-DCBX_GLTF', '-Itools/certbox'] + jansson_flags('--cflags') + jansson_flags('--libs')
            # the archive after every object that may use it (test_gltf's
            # gltf_anim.o uses its slerp oracle): a linker takes from an
            # archive only what the files before it need
            sh([CC] + FLAGS + ['-O0', '--coverage', *INCS, '-Itests', 'tests/test_%s.c' % name]
               + objs + extra + tu + EXACTLIBS + ['-lm', '-o', exe])
        r = sh([exe] + args, check=False)
        # the -O0 build must compute exactly what the -O2 build did
        ref = open(os.path.join(raw, 'tests', run_name(i) + '.txt')).read()
        ok = normal(r.stdout + r.stderr) == ref
        same.append({'run': run_name(i), 'same_output_as_O2': ok})
        if not ok:
            failures.append('coverage: test_%s at -O0 --coverage printed something else than at -O2' % run_name(i))
    # gcovr runs gcov in the checkout's root when the object folder does not
    # resolve the sources' relative names, and gcov writes its .gcov files
    # there: two packs made at once (make evidence-check) must take turns, or
    # one reads the other's half-written files (the clean-clone run at
    # f72a675 failed on it).  The lock is the build folder's, held by one
    # gcovr at a time.
    os.makedirs(os.path.join(ROOT, 'build'), exist_ok=True)
    with open(os.path.join(ROOT, 'build', 'gcovr.lock'), 'w') as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        r = sh(['gcovr', '--root', ROOT, '--object-directory', os.path.join(b, 'obj'),
                '--filter', os.path.join(ROOT, 'src') + '/', '--filter', os.path.join(ROOT, 'include') + '/',
                '--json', os.path.abspath(os.path.join(raw, 'coverage.json')), os.path.join(b, 'obj')],
               cwd=b, check=True)
    data = json.load(open(os.path.join(raw, 'coverage.json')))
    waivers = load_waivers()
    used = set()
    lines_total = lines_hit = br_total = br_hit = 0
    uncovered = []
    per_file = {}
    for f in sorted(data['files'], key=lambda x: x['file']):
        fn = os.path.relpath(os.path.join(ROOT, f['file']), ROOT) if not os.path.isabs(f['file']) else os.path.relpath(f['file'], ROOT)
        src = open(os.path.join(ROOT, fn), encoding='utf-8').read().splitlines()
        pf = per_file.setdefault(fn, [0, 0, 0, 0])
        for ln in f['lines']:
            if ln.get('gcovr/noncode'):
                continue
            n = ln['line_number']
            text = src[n - 1].strip() if n - 1 < len(src) else ''
            lines_total += 1
            pf[0] += 1
            if ln['count'] > 0:
                lines_hit += 1
                pf[1] += 1
            else:
                w = match_waiver(waivers, fn, text, 'line', used)
                uncovered.append({'file': fn, 'line': n, 'kind': 'statement', 'code': text, 'why': w})
            for k, br in enumerate(ln.get('branches', [])):
                br_total += 1
                pf[2] += 1
                if br['count'] > 0:
                    br_hit += 1
                    pf[3] += 1
                else:
                    w = match_waiver(waivers, fn, text, 'branch', used)
                    uncovered.append({'file': fn, 'line': n, 'kind': 'branch %d' % k, 'code': text, 'why': w})
    for u in uncovered:
        if u['why'] is None:
            failures.append('coverage: %s:%d %s not covered and not justified: %s'
                            % (u['file'], u['line'], u['kind'], u['code']))
    for i, w in enumerate(waivers):
        if i not in used:
            failures.append('coverage: stale justification in scripts/evidence/coverage.txt: %s' % w['pattern'])
    return {'tool': first_line('gcovr --version'), 'build': 'gcc -O0 --coverage, the suites above',
            'same_as_O2': same,
            'statements': {'covered': lines_hit, 'total': lines_total},
            'branches': {'covered': br_hit, 'total': br_total},
            'per_file': {k: {'statements': [v[1], v[0]], 'branches': [v[3], v[2]]} for k, v in sorted(per_file.items())},
            'uncovered': uncovered}


def load_waivers():
    out = []
    path = os.path.join(ROOT, 'scripts', 'evidence', 'coverage.txt')
    for line in open(path, encoding='utf-8'):
        if not line.strip() or line.startswith('#'):
            continue
        p = line.rstrip('\n').split(' | ')
        if len(p) != 4:
            raise SystemExit('evidence: bad line in coverage.txt: ' + line)
        out.append({'file': p[0].strip(), 'kind': p[1].strip(), 'pattern': p[2].strip(), 'why': p[3].strip()})
    return out


def match_waiver(waivers, fn, text, kind, used):
    for i, w in enumerate(waivers):
        if (w['file'] == fn or w['file'] == '*') and w['kind'] in (kind, 'any') and w['pattern'] in text:
            used.add(i)
            return w['why']
    return None


# ---- coding standard -----------------------------------------------------------

def standard(raw, b):
    """cppcheck (MISRA addon) and clang-tidy; cppcheck's dump and
    whole-program files go to b/cppcheck (one per pack), not next to the
    sources, so that two packs made at once do not share them."""
    cb = os.path.join(b, 'cppcheck')
    shutil.rmtree(cb, ignore_errors=True)
    os.makedirs(cb)
    srcs = sorted(glob.glob(os.path.join(ROOT, 'src', '*', 'cbx_*.c')))
    rel = [os.path.relpath(s, ROOT) for s in srcs]
    cp = sh(['cppcheck', '--addon=misra', '--std=c99', '--enable=style,warning,portability',
             '--cppcheck-build-dir=' + cb,
             '--inline-suppr', *INCS, '--quiet', '-D__GNUC__', '-DFLT_EVAL_METHOD=0',
             '--template={file}:{line}:{severity}:{id}:{message}'] + rel, check=False)
    # clang-analyzer-valist.* off: the sources have no variadic function
    # (MISRA 17.1, cppcheck above), and clang 14's checker reported an
    # uninitialised va_list at two q_dot calls of src/f64/cbx_trs.c in one
    # of two identical packs made side by side (2026-11-29), not the other
    tidy_checks = ('-*,clang-analyzer-*,-clang-analyzer-valist.*,bugprone-*,cert-*,misc-*,'
                   'portability-*,performance-*,'
                   'readability-*,-readability-magic-numbers,-readability-identifier-length')
    ct = sh(['clang-tidy', '--quiet', '-checks=' + tidy_checks] + rel
            + ['--', '-std=c99', *INCS, '-ffp-contract=off'], check=False)
    open(os.path.join(raw, 'cppcheck.txt'), 'w').write(cp.stderr)
    open(os.path.join(raw, 'clang-tidy.txt'), 'w').write(ct.stdout)
    findings = []
    for line in cp.stderr.splitlines():
        m = re.match(r'(.+?):(\d+):(\w+):([\w.-]+):', line)
        if m:
            findings.append({'tool': 'cppcheck', 'file': m.group(1), 'line': int(m.group(2)),
                             'rule': m.group(4)})
    for line in ct.stdout.splitlines():
        m = re.match(r'(.+?):(\d+):\d+: (?:warning|error): .*\[([\w.,-]+)\]$', line)
        if m:
            findings.append({'tool': 'clang-tidy', 'file': os.path.relpath(m.group(1), ROOT)
                             if os.path.isabs(m.group(1)) else m.group(1),
                             'line': int(m.group(2)), 'rule': m.group(3)})
    devs = load_deviations()
    used = set()
    rules = {}
    for f in findings:
        key = (f['tool'], f['rule'])
        d = None
        for i, dv in enumerate(devs):
            if dv['tool'] == f['tool'] and dv['rule'] == f['rule'] and (dv['file'] == '*' or dv['file'] == f['file']):
                d = dv
                used.add(i)
                break
        r = rules.setdefault(key, {'tool': f['tool'], 'rule': f['rule'], 'count': 0, 'files': {},
                                   'justification': d['why'] if d else None})
        r['count'] += 1
        r['files'][f['file']] = r['files'].get(f['file'], 0) + 1
        if d is None:
            failures.append('standard: %s %s at %s:%d has no deviation record' % (f['tool'], f['rule'], f['file'], f['line']))
    for i, dv in enumerate(devs):
        if i not in used:
            failures.append('standard: stale deviation record %s %s %s' % (dv['tool'], dv['rule'], dv['file']))
    return {'cppcheck': first_line('cppcheck --version') + ', MISRA C:2012 addon (misra.py)',
            'clang_tidy': first_line('clang-tidy --version | grep -i version') + '; checks ' + tidy_checks,
            'sources': rel, 'findings': len(findings),
            'rules': [rules[k] for k in sorted(rules)]}


def load_deviations():
    out = []
    for line in open(os.path.join(ROOT, 'scripts', 'evidence', 'deviations.txt'), encoding='utf-8'):
        if not line.strip() or line.startswith('#'):
            continue
        p = line.rstrip('\n').split(' | ')
        if len(p) != 4:
            raise SystemExit('evidence: bad line in deviations.txt: ' + line)
        out.append({'tool': p[0].strip(), 'rule': p[1].strip(), 'file': p[2].strip(), 'why': p[3].strip()})
    return out


# ---- tools and hashes ----------------------------------------------------------

def tools(raw):
    gv = os.path.join(raw, 'gv')
    open(gv + '.c', 'w').write('#include <gmp.h>\n#include <mpfr.h>\n#include <stdio.h>\n'
                               'int main(void){printf("GMP %s, MPFR %s", gmp_version, mpfr_get_version());'
                               'return 0;}\n')
    sh([CC, gv + '.c', '-lmpfr', '-lgmp', '-o', gv])
    gmp = sh([gv], check=False).stdout.strip()
    os.remove(gv)
    os.remove(gv + '.c')
    return {'gcc': first_line(CC + ' --version'), 'frama-c': first_line('frama-c -version'),
            'why3': first_line('why3 --version'), 'cvc4': first_line('cvc4 --version'),
            'z3': first_line('z3 -version'), 'gmp_mpfr': gmp or 'not found',
            'cppcheck': first_line('cppcheck --version'), 'clang-tidy': first_line('clang-tidy --version | grep -i version'),
            'gcovr': first_line('gcovr --version'), 'python': first_line('python3 --version'),
            'os': first_line('. /etc/os-release && echo "$PRETTY_NAME"'), 'machine': first_line('uname -m')}


def sha(path):
    h = hashlib.sha256()
    with open(path, 'rb') as f:
        for chunk in iter(lambda: f.read(1 << 16), b''):
            h.update(chunk)
    return h.hexdigest()


def hashes():
    files = sh(['git', 'ls-files']).stdout.split()
    rev = sh(['git', 'rev-parse', 'HEAD'], check=False).stdout.strip() or 'unknown'
    dirty = sh(['git', 'status', '--porcelain', '--untracked-files=no'], check=False).stdout.strip()
    src = {f: sha(os.path.join(ROOT, f)) for f in sorted(files) if os.path.isfile(os.path.join(ROOT, f))}
    libs = {}
    for f in ('build/libcertbox.a', 'build/libcertbox.so.0.1.0'):
        if os.path.exists(os.path.join(ROOT, f)):
            libs[f] = sha(os.path.join(ROOT, f))
    return {'git_revision': rev, 'working_tree_clean': not dirty, 'files': src, 'libraries': libs}


# ---- output --------------------------------------------------------------------

def md(pack):
    L = ['# certbox evidence pack', '',
         'Revision `%s`%s. Made by `make evidence` (scripts/evidence.py); how to re-run each part: '
         'docs/evidence.md, "Audit evidence".' % (pack['tools_and_hashes']['git_revision'],
                                           '' if pack['tools_and_hashes']['working_tree_clean'] else ' (with uncommitted changes)'),
         '', 'Result: **%s**' % pack['result'], '']
    if pack['problems']:
        L += ['Problems:', ''] + ['- ' + p for p in pack['problems']] + ['']
    L += ['## 1. Claims: every public function\'s contract', '',
          'Formal text: the ACSL contract on the prototype (include/cbx_api.h, include/certbox.h), proven by '
          'Frama-C/WP (section 2). The binary32 function has the same contract with float types, the '
          'names of its logic ending in _f and binary32\'s constants (u = 2^-24, eta = 2^-149, domain '
          '2^122 where binary64 has 2^1018, tightness 2^-140 for 2^-1065).', '']
    for c in pack['claims']:
        L.append('### `%s`%s' % (c['function'], ' and `%s`' % c['binary32'] if c['binary32'] else ''))
        L += ['', '`%s`' % c['prototype'], '', c['summary'].replace('\n', ' '), '']
        if c['clauses']:
            L += ['| clause | formal text | in plain words |', '|---|---|---|']
            for r in c['clauses']:
                L.append('| %s | `%s` | %s |' % (r['key'], r['formal'].replace('|', '\\|'), r['plain'].replace('|', '\\|')))
            L.append('')
    p = pack['proof']
    L += ['## 2. Proof', '', 'Model: %s. Result: **%s**: %d / %d goals proved; %d smoke tests, %d failed '
          '(a failed smoke test would mean an inconsistent contract).' % (
              p.get('model', ''), p.get('result', 'none'), p.get('proved', 0), p.get('total', 0),
              p.get('smoke_tests', 0), p.get('smoke_failed', 0)), '',
          'The run proved these inputs (SHA-256 of the sources, specifications and proof scripts, '
          '`sh proofs/inputs.sh`): `%s`.' % p.get('inputs_sha256', 'none'), '']
    for fam, per in p.get('families', {}).items():
        L += ['%s: %d functions, %d / %d goals.' % (fam, len(per), sum(v['proved'] for v in per.values()),
                                                  sum(v['total'] for v in per.values())), '',
              '| function | proved / total |', '|---|---|']
        L += ['| %s | %d / %d |' % (f, v['proved'], v['total']) for f, v in per.items()]
        L.append('')
    L += ['Trusted base (proofs/README.md):', '', '| item | why it is believed |', '|---|---|']
    L += ['| %s | %s |' % (t['item'], t['why']) for t in p.get('trusted_base', [])]
    L += ['', '## 3. Tests', '', '| suite | arguments | passed | failed | containment checks | containment failures |',
          '|---|---|---|---|---|---|']
    for t in pack['tests']:
        L.append('| %s | %s | %d | %d | %d | %d |' % (t['suite'], t['args'], t['passed'], t['failed'],
                                                     t['containment_checked'], t['containment_failed']))
    L += ['', 'Tightness figures printed by the suites (units as each prints them):', '']
    for t in pack['tests']:
        for line in t['tightness']:
            L.append('- %s: %s' % (t['suite'], line))
    cv = pack['coverage']
    if cv:
        L += ['', '## 4. Coverage of src/ by the suites', '',
              'Statements: %d / %d (%.1f%%); branches: %d / %d (%.1f%%) (%s; %s).' % (
                  cv['statements']['covered'], cv['statements']['total'],
                  100.0 * cv['statements']['covered'] / max(1, cv['statements']['total']),
                  cv['branches']['covered'], cv['branches']['total'],
                  100.0 * cv['branches']['covered'] / max(1, cv['branches']['total']), cv['tool'], cv['build']),
              '', 'The instrumented -O0 build printed the same output as the -O2 build, line for line, '
              'in %d of %d runs.' % (sum(1 for s in cv['same_as_O2'] if s['same_output_as_O2']), len(cv['same_as_O2'])),
              '', '| file | statements | branches |', '|---|---|---|']
        L += ['| %s | %d / %d | %d / %d |' % (f, v['statements'][0], v['statements'][1], v['branches'][0],
                                               v['branches'][1]) for f, v in cv['per_file'].items()]
        L += ['', 'Not covered, each with its justification (scripts/evidence/coverage.txt):', '',
              '| where | what | code | why |', '|---|---|---|---|']
        L += ['| %s:%d | %s | `%s` | %s |' % (u['file'], u['line'], u['kind'], u['code'].replace('|', '\\|'),
                                              u['why'] or '**NOT JUSTIFIED**') for u in cv['uncovered']]
    st = pack['standard']
    L += ['', '## 5. Coding standard', '', '%s; %s. %d findings on %d sources, every one under a deviation '
          'record (scripts/evidence/deviations.txt):' % (st['cppcheck'], st['clang_tidy'], st['findings'],
                                                          len(st['sources'])), '',
          '| tool | rule | findings | where | deviation |', '|---|---|---|---|---|']
    for r in st['rules']:
        where = ', '.join('%s (%d)' % (f, n) for f, n in sorted(r['files'].items()))
        L.append('| %s | %s | %d | %s | %s |' % (r['tool'], r['rule'], r['count'], where,
                                                r['justification'] or '**NO DEVIATION RECORD**'))
    th = pack['tools_and_hashes']
    L += ['', '## 6. Tools and hashes', '', '| tool | version |', '|---|---|']
    L += ['| %s | %s |' % (k, v) for k, v in pack['tools'].items()]
    L += ['', 'Git revision `%s`; SHA-256 of the built libraries:' % th['git_revision'], '']
    L += ['- `%s` %s' % (v, k) for k, v in th['libraries'].items()]
    L += ['', 'SHA-256 of every tracked file (%d): evidence.json, key tools_and_hashes.files.' % len(th['files']), '']
    L += ['## 7. What varies between runs (left out of the reproducibility comparison)', '',
          '- made at %s' % pack['volatile']['made_at'],
          '- proof wall time per job (s): %s' % json.dumps(pack['volatile'].get('proof', {}).get('wall_seconds_per_job', {}),
                                                           sort_keys=True), '']
    return '\n'.join(L) + '\n'


def compare(a, b):
    ja = json.load(open(os.path.join(a, 'evidence.json')))
    jb = json.load(open(os.path.join(b, 'evidence.json')))
    ja.pop('volatile', None)
    jb.pop('volatile', None)
    ok = ja == jb
    if not ok:
        for k in sorted(set(ja) | set(jb)):
            if ja.get(k) != jb.get(k):
                print('evidence: differs in %s' % k)
    ma = open(os.path.join(a, 'index.md')).read().split('\n## 7.')[0]
    mb = open(os.path.join(b, 'index.md')).read().split('\n## 7.')[0]
    if ma != mb:
        ok = False
        print('evidence: index.md differs outside section 7')
    for name in sorted(os.listdir(os.path.join(a, 'raw', 'tests'))):
        if open(os.path.join(a, 'raw', 'tests', name)).read() != open(os.path.join(b, 'raw', 'tests', name)).read():
            ok = False
            print('evidence: test output %s differs' % name)
    print('evidence: the two packs are %s (apart from section 7 / "volatile")' % ('identical' if ok else 'DIFFERENT'))
    print('%d passed, %d failed' % (int(ok), int(not ok)))
    return 0 if ok else 1


def main():
    if len(sys.argv) == 4 and sys.argv[1] == '--compare':
        return compare(sys.argv[2], sys.argv[3])
    if len(sys.argv) > 2 or (len(sys.argv) == 2 and sys.argv[1].startswith('-')):
        sys.stderr.write('usage: evidence.py [OUTDIR] | evidence.py --compare DIR1 DIR2\n'
                         '  (OUTDIR, default build/evidence, is deleted and written anew)\n')
        return 2
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, 'build', 'evidence')
    raw = os.path.join(out, 'raw')
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(raw)
    print('evidence: claims')
    cl = claims()
    print('evidence: proof (from build/proof)')
    pf, pv = proof(raw)
    print('evidence: tests')
    ts, _ = tests(raw)
    print('evidence: coverage (and the same suites at -O0, compared with -O2)')
    pack_build = os.path.join(ROOT, 'build', 'cov-' + os.path.basename(os.path.normpath(out)))
    cv = coverage(raw, pack_build)
    print('evidence: coding standard')
    st = standard(raw, pack_build)
    print('evidence: tools and hashes')
    pack = {'claims': cl, 'proof': pf, 'tests': ts, 'coverage': cv, 'standard': st,
            'tools': tools(raw), 'tools_and_hashes': hashes(),
            'volatile': {'made_at': datetime.datetime.utcnow().strftime('%Y-%m-%d %H:%M:%S UTC'), 'proof': pv}}
    pack['problems'] = failures
    pack['result'] = 'COMPLETE: every check holds' if not failures else 'INCOMPLETE (%d problems)' % len(failures)
    json.dump(pack, open(os.path.join(out, 'evidence.json'), 'w'), indent=1, sort_keys=True)
    open(os.path.join(out, 'index.md'), 'w').write(md(pack))
    print('evidence: %s -> %s' % (pack['result'], os.path.relpath(out, ROOT)))
    for f in failures[:30]:
        print('  ' + f)
    return 0 if not failures else 1


if __name__ == '__main__':
    sys.exit(main())
