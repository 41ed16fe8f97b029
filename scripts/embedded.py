#!/usr/bin/env python3
"""make embedded: the library cross-compiled for Cortex-M, freestanding.

For each target (Cortex-M4F: single-precision FPU only; Cortex-M7: double
FPU) every library source is compiled with arm-none-eabi-gcc, -ffreestanding
and the library's flags, plus -fstack-usage and -fcallgraph-info=su.  Then:
  * the undefined symbols of every object: allowed are only libgcc's
    run-time helpers (__aeabi_*: soft double arithmetic on the M4F) and
    sqrt / sqrtf; the binary32 family must need no double helper at all on
    the M4F (it runs on the single-precision FPU alone);
  * code size of each public function: the function and everything it can
    call (its call closure within the library, what a link with
    -ffunction-sections --gc-sections keeps), at -O2 and -Os;
  * worst-case stack of each public function: the deepest path of the call
    graph GCC writes (-fcallgraph-info=su; every frame is static, there is
    no recursion), plus the helper calls' own frames, listed apart.
Writes build/embedded/report.md and prints it; exits 1 on a forbidden
symbol or a dynamic/unbounded stack.
Usage: scripts/embedded.py [CC]   (default arm-none-eabi-gcc)
"""
import glob
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# the library's include folders (scripts/incs.sh: one list for every build)
INCS = subprocess.check_output(['sh', os.path.join(ROOT, 'scripts', 'incs.sh')], text=True).split()
OUT = os.path.join(ROOT, 'build', 'embedded')
CC = sys.argv[1] if len(sys.argv) > 1 else 'arm-none-eabi-gcc'
TARGETS = [
    ('cortex-m4f', 'Cortex-M4F (FPv4-SP: single precision only)',
     ['-mcpu=cortex-m4', '-mfpu=fpv4-sp-d16', '-mfloat-abi=hard', '-mthumb']),
    ('cortex-m7', 'Cortex-M7 (FPv5-D16: single and double precision)',
     ['-mcpu=cortex-m7', '-mfpu=fpv5-d16', '-mfloat-abi=hard', '-mthumb']),
]
# The library's flags (Makefile: -std=c99, warnings as errors, no FMA
# contraction, no fast-math) for a freestanding target; -fno-math-errno lets
# sqrt be the FPU instruction (the library never takes the root of a
# negative number, so errno is never set anyway).
FLAGS = ['-std=c99', '-Wall', '-Wextra', '-Wpedantic', '-Werror', '-ffp-contract=off',
         '-fno-fast-math', '-fno-math-errno', '-ffreestanding', '-ffunction-sections',
        ] + ['-I' + os.path.join(ROOT, d[2:]) for d in INCS]
PUBLIC = ['cbx_transform_box', 'cbx_transform_boxes', 'cbx_transform_cbox', 'cbx_box_to_cbox',
          'cbx_cbox_to_box', 'cbx_sphere_box', 'cbx_ellipsoid_box']
PUBLIC64 = ['cbx_transform_box_tight', 'cbx_classify', 'cbx_transform_box_as', 'cbx_motion_box',
            'cbx_motion_trs_box', 'cbx_transform_box_pieces']
ALLOWED = re.compile(r'^(__aeabi_\w+|sqrt|sqrtf)$')
# The binary64 tight mode's two_prod (src/core/cbx_eft.h) is an fma where the
# target has the instruction (M7: vfma.f64) or glibc's, else Dekker's
# product (M4F, freestanding: no fma call).  libm's fma is allowed in
# cbx_tight.o only where the fma form is selected (by -DCBX_USE_FMA on a
# target without the instruction): that libm's fma must be correctly
# rounded (cbx_ieee_check's CBX_IEEE_FMA; newlib's generic one is not).
FMA_IN = {'cbx_tight.o': re.compile(r'^fma$')}


def two_prod_form(flags):
    """the two_prod form cbx_eft.h selects for these flags, from its macros"""
    out = run([CC] + FLAGS + flags + ['-dM', '-E', os.path.join(ROOT, 'src', 'core', 'cbx_eft.h')])
    name = re.search(r'#define CBX_TWO_PROD_NAME "([^"]+)"', out).group(1)
    dekker = re.search(r'#define CBX_EFT_DEKKER 1\b', out) is not None
    fast = re.search(r'#define __FP_FAST_FMA 1\b', out) is not None
    return name, dekker, fast


def run(cmd, cwd=None):
    r = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    if r.returncode:
        sys.stderr.write(r.stdout + r.stderr)
        raise SystemExit('embedded: failed: ' + ' '.join(cmd))
    return r.stdout


def build(target, flags, opt):
    d = os.path.join(OUT, target + opt)
    os.makedirs(d, exist_ok=True)
    for f in glob.glob(os.path.join(d, '*')):
        os.remove(f)
    srcs = sorted(glob.glob(os.path.join(ROOT, 'src', '*', 'cbx_*.c')))
    for s in srcs:
        o = os.path.join(d, os.path.basename(s)[:-2] + '.o')
        run([CC] + FLAGS + flags + [opt, '-fstack-usage', '-fcallgraph-info=su', '-c', s, '-o', o], cwd=d)
    return d


def symbols(d):
    """size of every defined function (name -> bytes), undefined symbols per object."""
    size, undef = {}, {}
    for o in sorted(glob.glob(os.path.join(d, '*.o'))):
        base = os.path.basename(o)
        for line in run([CC.replace('gcc', 'nm'), '-S', '--defined-only', o]).splitlines():
            p = line.split()
            if len(p) == 4 and p[2] in 'tT':
                # static helpers may have the same name in two objects
                key = p[3] if p[2] == 'T' else base + ':' + p[3]
                size[key] = int(p[1], 16)
        undef[base] = sorted(l.split()[-1] for l in run([CC.replace('gcc', 'nm'), '-u', o]).splitlines() if l.strip())
    return size, undef


def callgraph(d):
    """frame size of every function and the call edges, from the .ci files.
    GCC titles an exported function by its name and a static one by
    FILE:name; static ones are keyed OBJECT:name here, as in symbols()."""
    frame, edges, dynamic = {}, {}, []

    def key(title, base):
        return title if ':' not in title else base + ':' + title.split(':')[-1]
    for ci in sorted(glob.glob(os.path.join(d, '*.ci'))):
        base = os.path.basename(ci)[:-3] + '.o'
        text = open(ci, encoding='utf-8').read()
        for title, label in re.findall(r'node: \{ title: "([^"]+)" label: "([^"]+)"', text):
            m = re.search(r'\\n(\d+) bytes \((\w+)\)', label)
            k = key(title, base)
            edges.setdefault(k, [])
            if m:
                frame[k] = int(m.group(1))
                if m.group(2) != 'static':
                    dynamic.append(k)
        for src, dst in re.findall(r'edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"', text):
            edges.setdefault(key(src, base), []).append(key(dst, base))
    return frame, edges, dynamic


def closure(f, edges):
    seen, todo = set(), [f]
    while todo:
        g = todo.pop()
        if g in seen:
            continue
        seen.add(g)
        todo += edges.get(g, [])
    return seen


def deepest(f, frame, edges, memo, stack=()):
    """(bytes, path) of the deepest call path from f."""
    if f in stack:
        raise SystemExit('embedded: recursion through ' + f)
    if f in memo:
        return memo[f]
    best, path = 0, []
    for g in edges.get(f, []):
        v, p = deepest(g, frame, edges, memo, stack + (f,))
        if v > best:
            best, path = v, p
    memo[f] = (frame.get(f, 0) + best, [f] + path)
    return memo[f]


def main():
    os.makedirs(OUT, exist_ok=True)
    lines, bad = [], []
    lines.append('# certbox on Cortex-M (generated by `make embedded`)\n')
    lines.append('Compiler: %s. Flags: `%s` plus the target flags; sizes in bytes.\n'
                 % (run([CC, '--version']).splitlines()[0], ' '.join(FLAGS[:-1])))
    for target, title, flags in TARGETS:
        d2 = build(target, flags, '-O2')
        ds = build(target, flags, '-Os')
        size2, undef = symbols(d2)
        sizes, _ = symbols(ds)
        frame, edges, dyn = callgraph(d2)
        framess, edgess, _ = callgraph(ds)
        name, dekker, fast = two_prod_form(flags)
        allowed_in = {} if dekker else FMA_IN
        lines.append('## %s\n' % title)
        lines.append('`%s`\n' % ' '.join(flags))
        lines.append('two_prod (tight mode, src/core/cbx_eft.h): %s; %s.\n'
                     % (name, 'no double fma instruction (no __FP_FAST_FMA), freestanding: no trusted libm fma'
                        if dekker else 'double fma instruction (__FP_FAST_FMA)' if fast
                        else 'the C library\'s fma, as selected by the flags'))
        print('embedded: %s: two_prod = %s' % (target, name))
        if not dekker and not fast:
            bad.append('%s: two_prod calls a library fma (no instruction): vouch for it or use -DCBX_NO_FMA' % target)
        tight = 'cbx_tight.o'
        if dekker and any(u == 'fma' for u in undef.get(tight, [])):
            bad.append('%s: the Dekker form selected but %s calls fma' % (target, tight))
        # undefined symbols
        helpers = set()
        for o, us in undef.items():
            for u in us:
                if u.startswith('cbx_'):
                    continue   # another object of the library
                if not ALLOWED.match(u) and not (o in allowed_in and allowed_in[o].match(u)):
                    bad.append('%s %s needs %s' % (target, o, u))
                helpers.add(u)
                if target == 'cortex-m4f' and o.endswith('_f.o') and u.startswith('__aeabi_d'):
                    bad.append('%s: binary32 object %s needs double arithmetic %s' % (target, o, u))
        f32_undef = sorted(set(u for o, us in undef.items() if o.endswith('_f.o') for u in us if not u.startswith('cbx_')))
        lines.append('External symbols: %s. The binary32 family needs: %s.\n'
                     % (', '.join(sorted(helpers)) or 'none', ', '.join(f32_undef) or 'nothing (no libc, no libgcc helper)'))
        lines.append('| function | code -O2 | code -Os | stack (worst path, -O2) | deepest path |')
        lines.append('|---|---:|---:|---:|---|')
        for fam, names in (('64', PUBLIC + PUBLIC64), ('32', PUBLIC)):
            for n in names:
                f = n if fam == '64' else (n + 'f')
                if f not in size2:
                    continue
                c2 = sum(size2.get(g, 0) for g in closure(f, edges))
                cs = sum(sizes.get(g, 0) for g in closure(f, edgess))
                st, path = deepest(f, frame, edges, {})
                ext = sorted(set(g for g in closure(f, edges) if g not in frame))
                p = ' > '.join(x.split(':')[-1] for x in path)
                if ext:
                    p += ' (+ %s)' % ', '.join(ext[:4] + (['...'] if len(ext) > 4 else []))
                lines.append('| `%s` | %d | %d | %d | %s |' % (f, c2, cs, st, p))
        total2 = sum(size2.values())
        totals = sum(sizes.values())
        lines.append('\nWhole library (both families, every function): %d bytes at -O2, %d at -Os. '
                     'Stack: every frame static (%s).\n' % (total2, totals, 'none dynamic' if not dyn else 'DYNAMIC: ' + ', '.join(dyn)))
        bad += ['%s: dynamic stack in %s' % (target, x) for x in dyn]
    lines.append('Helper calls (`+ ...`): libgcc\'s soft-float routines (M4F, binary64 only) and '
                 '`sqrt`; their own stack is not in the figure. The tight mode\'s two_prod is the fma '
                 'instruction on the M7 and Dekker\'s product (no fma call) on the M4F.\n')
    if bad:
        lines.append('PROBLEMS:\n' + '\n'.join('- ' + b for b in bad))
    text = '\n'.join(lines) + '\n'
    open(os.path.join(OUT, 'report.md'), 'w').write(text)
    print(text)
    print('embedded: %s' % ('FAILED' if bad else 'ok: freestanding, no libc beyond sqrt; sizes and stack in build/embedded/report.md'))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
