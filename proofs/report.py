#!/usr/bin/env python3
"""Summarise the Frama-C/WP logs of proofs/run.sh as build/proof/report.md
(printed on stdout; make proof-report copies it to proofs/report.md).

Usage: report.py OUTDIR WALL_SECONDS
OUTDIR holds wp-JOB.log and wp-JOB.time for every job of proofs/job.sh.
Per family (binary64, binary32) and function: proved/total, provers, prover
time; per job: goals and wall time; the smoke tests; RESULT: PROVED only
when every job finished, every goal is proved and no smoke test failed.
"""
import glob
import os
import re
import subprocess
import sys

GOAL = re.compile(r'^\[wp\] \[([^\]]+)\] Goal (\S+) : (\w+)(.*)$')
FAIL = re.compile(r'^\[wp\] \[(Failed|Unsuccess|Timeout|Unknown|Stepout)\] Goal (\S+)')
TIME = re.compile(r'\((\d+(?:\.\d+)?)(ms|s)\)')
SMOKE = re.compile(r'^\[wp\] \[(\w+)\] Smoke-test (\S+)', re.M)
JOBS = {
    'L64': 'binary64 lemmas', 'L32': 'binary32 lemmas',
    'LP64': 'binary64 lemmas of the projective balls and clipped bounds (proofs/lemmas_p.c)',
    'A64': 'binary64 functions marked for -wp-split',
    'A32': 'binary32 functions marked for -wp-split',
    'K64': 'binary64 primitives and kernels (src/core, src/algo headers)',
    'K32': 'binary32 primitives and kernels (src/core, src/algo headers)',
    'B64a': 'binary64-only code (src/f64: tight mode, classes, motion)',
    'B64b': 'binary64 algorithms (src/algo/*.c)',
    'B32': 'binary32 algorithms (src/algo/*.c)',
    'S64': 'binary64 smoke tests', 'S32': 'binary32 smoke tests',
    'I64': 'binary64 interval matrices (proofs/imat.c)', 'SI64': 'binary64 interval-matrix smoke tests',
    'T64': 'binary64 rotation motion: interval arithmetic, quaternion boxes, cells (proofs/trs.c)',
    'ST64': 'binary64 rotation-motion smoke tests',
    'PS64': 'binary64 ball under a projective map (proofs/psph.c)',
    'SPS64': 'binary64 projected-ball smoke tests',
    'PSR64': 'binary64 ball under a projective map: functions marked for both provers (proofs/psph.c)',
    'PN64': 'binary64 box clipped at a near plane (proofs/pnear.c)',
    'PB64': 'binary64 ball clipped at a near plane (proofs/pball.c)',
    'SPN64': 'binary64 clipped-box smoke tests',
    'SPB64': 'binary64 clipped-ball smoke tests',
    'PE64': 'binary64 ellipsoid under a projective map (proofs/pell.c)',
    'SPE64': 'binary64 projected-ellipsoid smoke tests',
    'PW': 'binary32 twins of the projected ball and the clipped box and ball (proofs/pwide.c)',
    'SPW': 'binary32 projective twins smoke tests',
    'P64': 'binary64 projective bound (proofs/proj.c)', 'P32': 'binary32 projective bound (proofs/proj_f.c)',
    'PA64': 'binary64 projective bound, -wp-split', 'PA32': 'binary32 projective bound, -wp-split',
    'SP64': 'binary64 projective-bound smoke tests', 'SP32': 'binary32 projective-bound smoke tests',
    'BS64': 'binary64 spheres and ellipsoids (src/algo/cbx_sphere.c, with its lemmas)',
    'BS32': 'binary32 spheres and ellipsoids (src/algo/cbx_sphere.c, with its lemmas)',
    'BSA64': 'binary64 spheres and ellipsoids, -wp-split', 'BSA32': 'binary32 spheres and ellipsoids, -wp-split',
}
FAMILY = {'64': 'binary64 (double): `cbx_transform_box`, ...',
          '32': 'binary32 (float): `cbx_transform_boxf`, ... (same sources)'}


def functions(log):
    return sorted(set(re.findall(r'annotating function (\w+)', log)), key=len, reverse=True)


def owner(goal, names):
    g = goal[len('typed_'):] if goal.startswith('typed_') else goal
    if g.startswith('lemma_'):
        return '(lemmas)'
    for n in names:
        if g.startswith(n + '_'):
            return n
    return '(other)'


def tool(cmd):
    try:
        return subprocess.run(cmd, shell=True, capture_output=True, text=True).stdout.strip().splitlines()[0]
    except Exception:  # noqa: BLE001 - a missing tool is reported, not fatal
        return 'unknown'


def collect(outdir):
    """Everything the report says, as data (also read by scripts/evidence.py)."""
    per = {'64': {}, '32': {}}
    jobs, job_time = [], {}
    errors, failed, bad_smoke = [], [], []
    smoke_n = {'64': 0, '32': 0}
    unfinished = []
    for name in JOBS:
        path = os.path.join(outdir, 'wp-%s.log' % name)
        if not os.path.exists(path):
            unfinished.append(name)
            continue
        text = open(path, encoding='utf-8', errors='replace').read()
        fam = '64' if '64' in name else '32'
        tpath = os.path.join(outdir, 'wp-%s.time' % name)
        secs = open(tpath).read().strip() if os.path.exists(tpath) else '?'
        job_time[name] = secs
        names = functions(text)
        n_goals = 0
        if name.startswith('S'):
            st = SMOKE.findall(text)
            smoke_n[fam] += len(st)
            bad_smoke += ['%s: %s (%s)' % (name, n, v) for v, n in st if v != 'Passed']
            n_goals = len(st)
            if not st:
                unfinished.append(name)
        else:
            # every Frama-C run of the job finished (a lemma job runs two
            # in pass 1, one per prover: proofs/job.sh)
            if len(re.findall(r'Proved goals:\s+\d+ / \d+', text)) < max(1, text.count('[wp] Running WP plugin')):
                unfinished.append(name)
            # a goal's last result counts (a job may run two passes)
            last = {}
            for line in text.splitlines():
                m = GOAL.match(line)
                if m and m.group(1) not in ('Failed', 'Unsuccess', 'Timeout', 'Unknown', 'Stepout'):
                    prover, goal, status, rest = m.groups()
                    t = TIME.findall(rest)
                    s = (float(t[-1][0]) / (1000.0 if t[-1][1] == 'ms' else 1.0)) if t else 0.0
                    last[goal] = (status == 'Valid', prover, s, status)
                    continue
                m = FAIL.match(line)
                if m:
                    last[m.group(2)] = (False, None, 0.0, m.group(1))
            for goal, (ok, prover, s, status) in last.items():
                f = owner(goal, names)
                d = per[fam].setdefault(f, {'ok': 0, 'n': 0, 'provers': {}, 'time': 0.0})
                d['n'] += 1
                d['time'] += s
                n_goals += 1
                if ok:
                    d['ok'] += 1
                    d['provers'][prover] = d['provers'].get(prover, 0) + 1
                else:
                    failed.append('%s: %s (%s)' % (name, goal, status))
        errors += ['%s: %s' % (name, l.strip()) for l in text.splitlines()
                   if 'Why3 Error' in l or 'User Error' in l or 'aborted' in l]
        jobs.append((name, JOBS[name], n_goals, secs))
    proved = sum(d['ok'] for fam in per.values() for d in fam.values())
    total = sum(d['n'] for fam in per.values() for d in fam.values())
    smoke = smoke_n['64'] + smoke_n['32']
    ok = (proved == total and total > 0 and not failed and not errors and not bad_smoke
          and not unfinished and smoke_n['64'] > 0 and smoke_n['32'] > 0)
    return {'per': per, 'jobs': jobs, 'job_time': job_time, 'errors': errors, 'failed': failed,
            'bad_smoke': bad_smoke, 'smoke_n': smoke_n, 'smoke': smoke, 'unfinished': unfinished,
            'proved': proved, 'total': total, 'ok': ok}


def unproved_functions(log):
    """The functions with a goal whose last result is not Valid (for the
    second pass of proofs/job.sh), comma-separated."""
    text = open(log, encoding='utf-8', errors='replace').read()
    names = functions(text)
    last = {}
    for line in text.splitlines():
        m = GOAL.match(line)
        if m:
            last[m.group(2)] = m.group(3) == 'Valid' and m.group(1) not in (
                'Failed', 'Unsuccess', 'Timeout', 'Unknown', 'Stepout')
            continue
        m = FAIL.match(line)
        if m:
            last[m.group(2)] = False
    fs = sorted(set(owner(g, names) for g, ok in last.items() if not ok))
    if any(f.startswith('(') for f in fs):
        return 'ALL'   # a lemma (no function to name): the whole job again
    return ','.join(fs)


def main():
    if sys.argv[1] == '--unproved-functions':
        print(unproved_functions(sys.argv[2]))
        return
    outdir, wall = sys.argv[1], sys.argv[2]
    data = collect(outdir)
    per, jobs, errors, failed = data['per'], data['jobs'], data['errors'], data['failed']
    bad_smoke, smoke_n, unfinished = data['bad_smoke'], data['smoke_n'], data['unfinished']
    cached = os.environ.get('CBX_CACHED') == '1'
    out = ['# Proof report (generated by `make proof`; do not edit)\n',
           'Frama-C/WP, default float model (IEEE binary64 and binary32, round to nearest), '
           'Typed memory model, `-wp-rte` (kernels with `-wp-split`). Every goal below '
           + ('was proved, but **from a kept WP cache** (`make proof` during development: '
              'unchanged goals are read back from earlier runs); `make proof-check` proves every goal from scratch. '
              if cached else
              'was proved by the provers in this run: no job keeps a WP cache (`-wp-cache none`). ')
           + 'Smoke tests in jobs of their own '
           '(`-wp-smoke-tests`, CVC4 with a step budget).\n']
    for fam in ('64', '32'):
        out.append('## %s\n' % FAMILY[fam])
        out.append('| function | proved / total | provers (goals) | prover time (s) |')
        out.append('|---|---|---|---|')
        fp = ft = 0
        for f in sorted(per[fam]):
            d = per[fam][f]
            pv = ', '.join('%s %d' % (p, c) for p, c in sorted(d['provers'].items()))
            out.append('| %s | %d / %d | %s | %.1f |' % (f, d['ok'], d['n'], pv, d['time']))
            fp += d['ok']
            ft += d['n']
        out.append('')
        out.append('%s: %d / %d goals proved; %d smoke tests.\n' % (FAMILY[fam].split(' ')[0], fp, ft, smoke_n[fam]))
    out.append('## Jobs\n')
    out.append('| job | what | goals | wall time (s) |')
    out.append('|---|---|---|---|')
    for name, what, n, secs in jobs:
        out.append('| %s | %s | %d | %s |' % (name, what, n, secs))
    out.append('')
    out.append('Tools: %s; %s; %s; %s.' % (tool('frama-c -version'), tool('why3 --version'),
               tool('cvc4 --version | head -1'), tool('z3 -version')))
    out.append('Wall time: %s s in all (%s jobs at a time, %s prover processes each).\n'
               % (wall, os.environ.get('CBX_JOBS', '?'), os.environ.get('CBX_WP_PAR', '?')))
    if unfinished:
        out.append('Jobs that did not finish: %s\n' % ', '.join(unfinished))
    if failed:
        out.append('Unproved goals:\n')
        out += ['- `%s`' % g for g in sorted(failed)]
        out.append('')
    if errors:
        out.append('Errors:\n')
        out += ['- `%s`' % e for e in errors[:20]]
        out.append('')
    ns = smoke_n['64'] + smoke_n['32']
    out.append('Smoke tests (`-wp-smoke-tests`): %d goals, %d not passed (a proved smoke goal '
               'would mean an inconsistent contract or dead code).' % (ns, len(bad_smoke)))
    for l in bad_smoke[:20]:
        out.append('- `%s`' % l)
    out.append('')
    ok = data['ok']
    out.append('Total: %d / %d goals proved.' % (data['proved'], data['total']))
    out.append('RESULT: %s' % ('PROVED' if ok else 'NOT PROVED'))
    print('\n'.join(out))


if __name__ == '__main__':
    main()
