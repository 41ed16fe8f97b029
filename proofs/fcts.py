#!/usr/bin/env python3
"""The functions of a proof job, read off the tree (proofs/job.sh).

    python3 proofs/fcts.py TU GROUP [--dead-code]
                                        a comma list of function names
    python3 proofs/fcts.py TU --callers NAME
                                        the functions of TU that call NAME
    python3 proofs/fcts.py TU --lemmas z3 [FILE...]
                                        a comma list of lemma names

TU is a proof translation unit (proofs/all.c, all_f.c, imat.c, proj.c,
proj_f.c, trs.c, psph.c, pnear.c, pball.c, pwide.c, pell.c).  It is
preprocessed as Frama-C preprocesses it (gcc -E -C -D__FRAMAC__, the
library's include folders of scripts/incs.sh and specs/); each function
definition is then attributed to the file the line markers name, under the
name it has in that family (cbx_transform_boxf in binary32).  The groups
follow the layers of src/:

    split    the functions proved with -wp-split: those whose contract is
             preceded by the comment /* proof: -wp-split */ (a goal of each
             timed out whole)
    kernels  the primitives and kernels: functions of src/core/*.h and
             src/algo/*.h, minus split
    f64      binary64-only code: functions of src/f64/*.c, minus split and
             minus the interval-matrix unit's (group imat)
    imat     the interval-matrix unit: src/f64/cbx_imat.c, src/f64/cbx_ikernel.h
    trs      the proven part of the rotation motion (proofs/trs.c): the
             interval arithmetic of src/f64/cbx_iv.h, the rotations,
             normalisation and arc boxes of quaternion boxes of
             src/f64/cbx_quat.h and the cells' interval
             matrices of src/f64/cbx_cell.h
    psph     a ball under a projective map (proofs/psph.c): the functions
             of src/f64/cbx_psph.c and of the enclosures they share,
             src/f64/cbx_paff.h and cbx_pgap.h (the interval arithmetic
             they call is proven in trs), minus psphrace
    psphrace the same files' functions marked /* proof: race */ (a goal
             that Z3 proves at once and CVC4 not in pass 1's time: their
             job races both provers from the first pass)
    pnear    a box under a projective map clipped at a near plane
             (proofs/pnear.c): the functions of src/f64/cbx_pnear.c (the
             enclosures of cbx_paff.h they call are proven in psph)
    pball    a ball under a projective map clipped at a near plane
             (proofs/pball.c): the functions of src/f64/cbx_pball.c (the
             enclosures of cbx_paff.h and cbx_pgap.h: psph)
    pell     an ellipsoid under a projective map (proofs/pell.c): the
             functions of src/f64/cbx_pell.c (the enclosures of cbx_paff.h
             and cbx_pgap.h they call: psph)
    pwide    the binary32 twins of the three above (proofs/pwide.c): the
             functions of src/f32/cbx_pwide.c (the binary64 functions they
             call are proven in psph, pnear, pball)
    proj     the projective unit (proofs/proj.c, proj_f.c): functions of
             src/algo/cbx_project.c and src/core/cbx_quot.h, minus split
    projsplit  the same unit's functions marked for -wp-split
    ball     the sphere and ellipsoid bounds (src/algo/cbx_sphere.c), minus
             split: proven with the lemmas of specs/cbx_ball.h
             (CBX_BALL_LEMMAS), which no other goal of the unit carries
    ballsplit  the same file's functions marked for -wp-split

    all      every function the unit defines

GROUP may be a comma list of groups (their union).  The smoke jobs keep
part of a group (proofs/job.sh, SMOKE, says why):

    --dead-code     the functions that call a function without a body in
                    the unit (a trusted contract: cbx_pinf, cbx_sqrt_rn,
                    cbx_two_sum, ...; proofs/README.md, "Trusted base"), and
                    the entry points: the functions defined without
                    `static`, and those no function of the unit calls

The rest of a unit (the algorithms of src/algo/*.c) is what a job's
-wp-skip-fct of these groups leaves.

--lemmas z3 lists the lemmas of the unit (of the FILEs only, if given)
marked for Z3: the line before the lemma reads // proof: z3 (inside the
annotation; a lemma that Z3 proves at once and CVC4 slowly or not at all).
The lemma jobs give these to Z3 and the rest to CVC4 (proofs/job.sh), each
lemma to one prover.  The names are WP's: in the binary32 family, after the
renaming of include/cbx_names_f.h (disk_plain_f for disk_plain).
"""
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The units where only one group is proven (the rest of their code is
# tested only), so a call from the rest establishes no precondition:
# proofs/trs.c, where src/f64/cbx_trs.c's path and loop are not proven.
PARTIAL = {'trs.c': 'trs', 'psph.c': 'psph,psphrace', 'pnear.c': 'pnear', 'pball.c': 'pball', 'pwide.c': 'pwide',
           'pell.c': 'pell'}
MARK = '/* proof: -wp-split */'
RACE = '/* proof: race */'
DEF = re.compile(r'^(?!typedef\b|extern\b)[A-Za-z_][\w \*]*?\b([A-Za-z_]\w*)\s*\(')


def preprocess(tu, defines=False):
    """the unit as Frama-C's preprocessing sees it, comments kept (and the
    #define lines, with defines)"""
    incs = subprocess.check_output(['sh', os.path.join(ROOT, 'scripts', 'incs.sh')], text=True).split()
    return subprocess.check_output(['gcc', '-E', '-C'] + (['-dD'] if defines else []) + ['-D__FRAMAC__']
                                   + incs + ['-Ispecs', tu], cwd=ROOT, text=True)


def definitions(text):
    """[(file, name, mark)] of every function defined in the unit; mark:
    'split' (MARK before its contract), 'race' (RACE) or None"""
    lines = text.split('\n')
    cur, split, seen, out = None, None, set(), []
    for k, ln in enumerate(lines):
        m = re.match(r'# \d+ "([^"]+)"', ln)
        if m:
            cur = os.path.normpath(m.group(1))
            continue
        if ln.strip() in (MARK, RACE):
            split = 'split' if ln.strip() == MARK else 'race'
            continue
        m = DEF.match(ln)
        if not m or ln.rstrip().endswith(';'):
            continue
        # a definition: its body opens before any ';'
        rest = '\n'.join(lines[k:k + 16])
        body, semi = rest.find('{'), rest.find(';')
        if body < 0 or (0 <= semi < body):
            continue
        name = m.group(1)
        if name not in seen:
            seen.add(name)
            out.append((cur, name, split))
        split = None
    return out


KEYWORDS = {'if', 'for', 'while', 'switch', 'return', 'sizeof', 'do'}


def callees(text, public=None):
    """{name: set of the names its body calls} for every function defined in
    the unit, read off the code without comments (ACSL included); the names
    of the functions defined without `static` are added to the set public
    when one is given"""
    code = re.sub(r'/\*.*?\*/', ' ', text, flags=re.S)
    code = re.sub(r'//[^\n]*|^#[^\n]*', ' ', code, flags=re.M)
    out = {}
    for m in re.finditer(r'\b([A-Za-z_]\w*)\s*\((?:[^;{()]|\([^()]*\))*\)\s*\{', code):
        name = m.group(1)
        if name in KEYWORDS or name in out:
            continue
        depth, k = 0, m.end() - 1
        for k in range(m.end() - 1, len(code)):
            depth += {'{': 1, '}': -1}.get(code[k], 0)
            if depth == 0:
                break
        out[name] = set(re.findall(r'\b([A-Za-z_]\w*)\s*\(', code[m.end():k])) - KEYWORDS
        head = code[max(code.rfind(';', 0, m.start()), code.rfind('}', 0, m.start())) + 1:m.start()]
        if public is not None and 'static' not in head.split():
            public.add(name)
    return out


def smoke_full(text, proven=None):
    """the functions whose smoke tests include dead code (proofs/job.sh,
    SMOKE): those whose body calls a function the unit does not define (a
    trusted contract), and the entry points, the public functions and those
    no proven function of the unit calls (proven: the names of the unit's
    proven functions when only some are, as in proofs/trs.c; by default
    all): a precondition that no proven call establishes is checked here"""
    public = set()
    calls = callees(text, public)
    called = set().union(*(c for n, c in calls.items() if proven is None or n in proven))
    return {n for n, c in calls.items() if c - set(calls) or n in public or n not in called}


def group(defs, g):
    def under(f, folder, ext):
        return f.startswith(folder) and f.endswith(ext)
    imat = ('src/f64/cbx_imat.c', 'src/f64/cbx_ikernel.h')
    proj = ('src/algo/cbx_project.c', 'src/core/cbx_quot.h')
    ball = ('src/algo/cbx_sphere.c',)
    trs = ('src/f64/cbx_iv.h', 'src/f64/cbx_quat.h', 'src/f64/cbx_cell.h')
    psph = ('src/f64/cbx_psph.c', 'src/f64/cbx_paff.h', 'src/f64/cbx_pgap.h')
    pnear = ('src/f64/cbx_pnear.c',)
    pball = ('src/f64/cbx_pball.c',)
    pwide = ('src/f32/cbx_pwide.c',)
    pell = ('src/f64/cbx_pell.c',)
    if g == 'split':
        return [n for f, n, s in defs if s == 'split' and f not in ball]
    if g == 'kernels':
        return [n for f, n, s in defs if s != 'split' and (under(f, 'src/core/', '.h') or under(f, 'src/algo/', '.h'))]
    if g == 'f64':
        return [n for f, n, s in defs if s != 'split' and under(f, 'src/f64/', '.c') and f not in imat + psph + pnear + pball + pell]
    if g == 'imat':
        return [n for f, n, s in defs if f in imat]
    if g == 'trs':
        return [n for f, n, s in defs if f in trs]
    if g == 'psph':
        return [n for f, n, s in defs if f in psph and s != 'race']
    if g == 'psphrace':
        return [n for f, n, s in defs if f in psph and s == 'race']
    if g == 'pnear':
        return [n for f, n, s in defs if f in pnear]
    if g == 'pball':
        return [n for f, n, s in defs if f in pball]
    if g == 'pwide':
        return [n for f, n, s in defs if f in pwide]
    if g == 'pell':
        return [n for f, n, s in defs if f in pell]
    if g == 'proj':
        return [n for f, n, s in defs if s != 'split' and f in proj]
    if g == 'projsplit':
        return [n for f, n, s in defs if s == 'split' and f in proj]
    if g == 'ball':
        return [n for f, n, s in defs if s != 'split' and f in ball]
    if g == 'ballsplit':
        return [n for f, n, s in defs if s == 'split' and f in ball]
    if g == 'all':
        return [n for f, n, s in defs]
    sys.exit('fcts.py: unknown group %s' % g)


Z3MARK = '// proof: z3'
LEMMA = re.compile(r'^\s*lemma\s+([A-Za-z_]\w*)\s*:')


def z3_lemmas(tu, files):
    """the WP names of the lemmas marked Z3MARK in the unit (in FILEs, if
    any), in the order of the unit"""
    text = preprocess(tu, defines=True)
    # the renamings the unit defines (#define NAME NAME_f): Frama-C expands
    # them in annotations, gcc -E does not
    ren = dict(re.findall(r'^#define ([A-Za-z_]\w*) ([A-Za-z_]\w*)\s*$', text, re.M))
    want = {os.path.normpath(f) for f in files}
    cur, marked, out = None, False, []
    for ln in text.split('\n'):
        m = re.match(r'# \d+ "([^"]+)"', ln)
        if m:
            cur = os.path.normpath(m.group(1))
            continue
        if ln.strip() == Z3MARK:
            marked = True
            continue
        m = LEMMA.match(ln)
        if m:
            name = m.group(1)
            for _ in range(4):
                name = ren.get(name, name)
            if marked and (not want or cur in want) and name not in out:
                out.append(name)
        if ln.strip():
            marked = False
    return out


def main():
    if len(sys.argv) >= 4 and sys.argv[2] == '--lemmas' and sys.argv[3] == 'z3':
        print(','.join(z3_lemmas(sys.argv[1], sys.argv[4:])))
        return
    if len(sys.argv) == 4 and sys.argv[2] == '--callers':
        calls = callees(preprocess(sys.argv[1]))
        print(','.join(n for n, c in calls.items() if sys.argv[3] in c))
        return
    if len(sys.argv) not in (3, 4) or sys.argv[3:] not in ([], ['--dead-code']):
        sys.exit(__doc__)
    text = preprocess(sys.argv[1])
    defs = definitions(text)
    names = [n for g in sys.argv[2].split(',') for n in group(defs, g)]
    if not names:
        sys.exit('fcts.py: group %s of %s is empty' % (sys.argv[2], sys.argv[1]))
    if sys.argv[3:]:
        part = PARTIAL.get(os.path.basename(sys.argv[1]))
        tc = smoke_full(text, [n for g in part.split(',') for n in group(defs, g)] if part else None)
        missing = set(names) - set(callees(text))
        if missing:
            sys.exit('fcts.py: no body found for %s' % ','.join(sorted(missing)))
        names = [n for n in names if n in tc]
        if not names:
            sys.exit('fcts.py: no function of group %s of %s needs smoke tests' % (sys.argv[2], sys.argv[1]))
    print(','.join(names))


if __name__ == '__main__':
    main()
