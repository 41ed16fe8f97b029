#!/usr/bin/env python3
"""Summarise the proof jobs of proofs/run.sh as build/proof/report.md
(printed on stdout; make proof-report copies it to proofs/report.md).

Usage: report.py OUTDIR WALL_SECONDS
       report.py --unproved-functions OUTDIR JOB   (proofs/job.sh's pass 2)
       report.py --goals OUTDIR JOB                (the job's goal count)
OUTDIR holds, for every job of proofs/job.sh, WP's own reports of its runs
(wp-JOB.K.json, written by -wp-report-json and listed in run order in
wp-JOB.runs), wp-JOB.time (the job's wall time) and wp-JOB.log (WP's
console output, read only for error messages).  The counts come from the
JSON reports alone: per family (binary64, binary32) and function, the
goals proved and in all and the prover of each; per job, goals and wall
time; the smoke tests; RESULT: PROVED only when every run of every job
finished (wrote its report), every goal is proved and every smoke test
passed.
"""
import json
import os
import subprocess
import sys

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


def runs(outdir, name):
    """The JSON reports of job name's runs, in run order; None when the
    job did not start or a run did not finish (no report, or a broken one)."""
    lst = os.path.join(outdir, 'wp-%s.runs' % name)
    if not os.path.exists(lst):
        return None
    out = []
    for line in open(lst, encoding='utf-8'):
        path = os.path.join(outdir, line.strip())
        if not line.strip():
            continue
        try:
            with open(path, encoding='utf-8') as f:
                out.append(json.load(f))
        except (OSError, ValueError):
            return None
    return out or None


def properties(reports):
    """scope -> property -> WP's stats for it, merged over a job's runs (a
    later run's entry replaces an earlier one's: pass 2 proves again every
    goal of the functions it names).  scope is the function, or '(lemmas)'
    for the lemmas of the axiomatics."""
    props = {}
    for rep in reports:
        for f, sect in rep.get('wp:functions', {}).items():
            for prop, st in sect.items():
                if prop != 'wp:section':
                    props.setdefault(f, {})[prop] = st
        for sect in rep.get('wp:axiomatics', {}).values():
            for prop, st in sect.items():
                if prop != 'wp:section':
                    props.setdefault('(lemmas)', {})[prop] = st
    return props


def prover_name(key):
    """WP's JSON key of a prover ('CVC4:1.8:real64', 'qed') as WP prints it."""
    if key == 'qed':
        return 'Qed'
    parts = key.split(':')
    return '%s %s (%s)' % tuple(parts) if len(parts) == 3 else ' '.join(parts)


def tally(st):
    """(goals, valid goals, {prover: valid goals}, status) of one property."""
    main = st.get('wp:main', {})
    n, ok = main.get('total', 0), main.get('valid', 0)
    provers = {prover_name(k): v.get('valid', 0) for k, v in st.items()
               if k != 'wp:main' and v.get('valid', 0)}
    bad = [k for k in main if k not in ('total', 'valid', 'rank') and main[k]]
    return n, ok, provers, (bad[0] if bad else 'valid')


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
        reports = runs(outdir, name)
        if reports is None:
            unfinished.append(name)
            continue
        fam = '64' if '64' in name else '32'
        tpath = os.path.join(outdir, 'wp-%s.time' % name)
        secs = open(tpath).read().strip() if os.path.exists(tpath) else '?'
        job_time[name] = secs
        n_goals = 0
        for f, props in sorted(properties(reports).items()):
            for prop, st in sorted(props.items()):
                n, ok, provers, status = tally(st)
                n_goals += n
                if name.startswith('S'):
                    # a smoke goal is valid when it passed (the prover did
                    # not derive false from its context)
                    smoke_n[fam] += n
                    if ok < n:
                        bad_smoke.append('%s: %s (%s)' % (name, prop, status))
                    continue
                d = per[fam].setdefault(f, {'ok': 0, 'n': 0, 'provers': {}})
                d['n'] += n
                d['ok'] += ok
                for p, c in provers.items():
                    d['provers'][p] = d['provers'].get(p, 0) + c
                if ok < n:
                    failed.append('%s: %s (%s)' % (name, prop, status))
        if name.startswith('S') and n_goals == 0:
            unfinished.append(name)
        log = os.path.join(outdir, 'wp-%s.log' % name)
        text = open(log, encoding='utf-8', errors='replace').read() if os.path.exists(log) else ''
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


def unproved_functions(outdir, name):
    """The functions with a goal not proved in the job's runs so far (for
    the second pass of proofs/job.sh), comma-separated; ALL for a lemma
    (no function to name: the whole job again); empty when every goal is
    proved or the run left no report (the job is then unfinished)."""
    reports = runs(outdir, name)
    if reports is None:
        return ''
    fs = sorted(f for f, props in properties(reports).items()
                if any(tally(st)[1] < tally(st)[0] for st in props.values()))
    if '(lemmas)' in fs:
        return 'ALL'
    return ','.join(fs)


def goals(outdir, name):
    reports = runs(outdir, name)
    return sum(tally(st)[0] for props in properties(reports or []).values() for st in props.values())


def main():
    if sys.argv[1] == '--unproved-functions':
        print(unproved_functions(sys.argv[2], sys.argv[3]))
        return
    if sys.argv[1] == '--goals':
        print(goals(sys.argv[2], sys.argv[3]))
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
           + 'The counts are WP\'s own (`-wp-report-json`, one report per Frama-C run). '
           'Smoke tests in jobs of their own '
           '(`-wp-smoke-tests`, CVC4 with a step budget).\n']
    for fam in ('64', '32'):
        out.append('## %s\n' % FAMILY[fam])
        out.append('| function | proved / total | provers (goals) |')
        out.append('|---|---|---|')
        fp = ft = 0
        for f in sorted(per[fam]):
            d = per[fam][f]
            pv = ', '.join('%s %d' % (p, c) for p, c in sorted(d['provers'].items()))
            out.append('| %s | %d / %d | %s |' % (f, d['ok'], d['n'], pv))
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
