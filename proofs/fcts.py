#!/usr/bin/env python3
"""The functions of a proof job, read off the tree (proofs/job.sh).

    python3 proofs/fcts.py TU GROUP     a comma list of function names

TU is a proof translation unit (proofs/all.c, all_f.c, imat.c, proj.c,
proj_f.c).  It is
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
    proj     the projective unit (proofs/proj.c, proj_f.c): functions of
             src/algo/cbx_project.c and src/core/cbx_quot.h, minus split
    projsplit  the same unit's functions marked for -wp-split
    ball     the sphere and ellipsoid bounds (src/algo/cbx_sphere.c), minus
             split: proven with the lemmas of specs/cbx_ball.h
             (CBX_BALL_LEMMAS), which no other goal of the unit carries
    ballsplit  the same file's functions marked for -wp-split

The rest of a unit (the algorithms of src/algo/*.c) is what a job's
-wp-skip-fct of these groups leaves.
"""
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MARK = '/* proof: -wp-split */'
DEF = re.compile(r'^(?!typedef\b|extern\b)[A-Za-z_][\w \*]*?\b([A-Za-z_]\w*)\s*\(')


def definitions(tu):
    """[(file, name, split)] of every function defined in the unit"""
    incs = subprocess.check_output(['sh', os.path.join(ROOT, 'scripts', 'incs.sh')], text=True).split()
    text = subprocess.check_output(['gcc', '-E', '-C', '-D__FRAMAC__'] + incs + ['-Ispecs', tu],
                                   cwd=ROOT, text=True)
    lines = text.split('\n')
    cur, split, seen, out = None, False, set(), []
    for k, ln in enumerate(lines):
        m = re.match(r'# \d+ "([^"]+)"', ln)
        if m:
            cur = os.path.normpath(m.group(1))
            continue
        if ln.strip() == MARK:
            split = True
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
        split = False
    return out


def group(defs, g):
    def under(f, folder, ext):
        return f.startswith(folder) and f.endswith(ext)
    imat = ('src/f64/cbx_imat.c', 'src/f64/cbx_ikernel.h')
    proj = ('src/algo/cbx_project.c', 'src/core/cbx_quot.h')
    ball = ('src/algo/cbx_sphere.c',)
    if g == 'split':
        return [n for f, n, s in defs if s and f not in ball]
    if g == 'kernels':
        return [n for f, n, s in defs if not s and (under(f, 'src/core/', '.h') or under(f, 'src/algo/', '.h'))]
    if g == 'f64':
        return [n for f, n, s in defs if not s and under(f, 'src/f64/', '.c') and f not in imat]
    if g == 'imat':
        return [n for f, n, s in defs if f in imat]
    if g == 'proj':
        return [n for f, n, s in defs if not s and f in proj]
    if g == 'projsplit':
        return [n for f, n, s in defs if s and f in proj]
    if g == 'ball':
        return [n for f, n, s in defs if not s and f in ball]
    if g == 'ballsplit':
        return [n for f, n, s in defs if s and f in ball]
    sys.exit('fcts.py: unknown group %s' % g)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    names = group(definitions(sys.argv[1]), sys.argv[2])
    if not names:
        sys.exit('fcts.py: group %s of %s is empty' % (sys.argv[2], sys.argv[1]))
    print(','.join(names))


if __name__ == '__main__':
    main()
