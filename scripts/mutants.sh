#!/usr/bin/env bash
# Mutation check: do the fast exact tests catch deliberate faults in src/, include/ (and tools/)?
#
#   bash scripts/mutants.sh [ID...]      (no ID: every mutant of the list)
#
# The checkout's include/, src/, specs/, tests/, examples/, tools/, Makefile,
# scripts/testutil.sh and scripts/exactlibs.sh (never .git or build/) are
# copied into a scratch directory (mktemp -d).  specs/ is copied
# because the Makefile lists specs/cbx_spec.h among the library's
# prerequisites; nothing under specs/ is ever mutated.  The pristine copy is
# built and tested once (it must pass); then, for each mutant of
# scripts/mutants.txt, a copy of that baseline (build/ included, timestamps
# kept, so only what the fault touches is rebuilt) gets ONE fault applied to
# a file under src/, include/ or tools/ (exact search string, which must match exactly once, or
# the run stops), is built, and runs the fast exact tests with reduced case
# counts.  A non-zero exit of a test (or a crash or timeout) means CAUGHT; a
# mutant that does not build is a BAD MUTANT (reported, exit 2).
#
# Environment:
#   MUT_EXACT_N   random cases of test_exact   (default 100000)
#   MUT_CBOX_N    random cases of test_cbox    (default 50000)
#   MUT_SPHERE_N  random cases of test_sphere  (default 30000)
#   MUT_HALF_N    random maps of test_halfspace (default 40)
#   MUT_TIGHT_N   thousands of cases of test_tight (default 40)
#   MUT_FLOAT_N   random cases of test_float   (default 50000)
#   MUT_CLASSES_N random cases of test_classes (default 20000; its misuse part
#                 checks every class value against the exact image)
#   MUT_GLTF_N    random interval matrices of test_gltf (default 20000; it
#                 also reads every glTF file of assimp-testmodels and
#                 tests/data/gltf and runs build/certbox on four).  test_gltf
#                 runs only when pkg-config finds jansson; without it the
#                 mutants of tools/certbox/gltf.c are SKIPPED (reported, not a
#                 failure)
#   MUT_PLANE_N   random cases of test_plane per format (default 20000)
#   MUT_PROJECT_N random cameras and maps of test_project per format (default 5000)
#   MUT_TRS_N     keyframe pairs of test_trs   (default 3000)
#   MUT_PSPHERE_N random cameras and maps of test_psphere (default 5000)
#   MUT_PNEAR_N random cameras and maps of test_pnear (default 5000)
#   MUT_PBALL_N random cameras and maps of test_pball (default 3000)
#   MUT_PWIDE_N random cases of test_pwide (default 2000)
#   MUT_PELL_N  random cameras and maps of test_pell (default 3000)
#   MUT_SEED      seed of the random cases     (default 1)
#   MUT_TIMEOUT   seconds per test run         (default 30)
#   MUT_LIST      mutant list                  (default scripts/mutants.txt)
#   MUT_KEEP=1    keep the scratch directory (its path is printed)
#   CC            compiler (passed to make)
# Exit status: 0 all caught, 1 some mutant survived, 2 bad mutant or setup
# error (list malformed, search string not unique, baseline failing).
set -u

ROOT=$(cd "$(dirname "$0")/.." && pwd)
LIST=${MUT_LIST:-$ROOT/scripts/mutants.txt}
EXACT_N=${MUT_EXACT_N:-100000}
CBOX_N=${MUT_CBOX_N:-50000}
SPHERE_N=${MUT_SPHERE_N:-30000}
HALF_N=${MUT_HALF_N:-40}
SEED=${MUT_SEED:-1}
TMO=${MUT_TIMEOUT:-30}
NICE="nice -n 19"

die() { echo "mutants: error: $*" >&2; exit 2; }
command -v python3 >/dev/null 2>&1 || die "python3 not found"
command -v timeout >/dev/null 2>&1 || die "timeout (coreutils) not found"
[ -f "$LIST" ] || die "mutant list $LIST not found"

# ---- the mutant list: parse, check, apply (python3) ----------------------
# mutool list FILE            -> id<TAB>file<TAB>desc per mutant
# mutool check FILE DIR       -> every mutant matches exactly once in DIR
# mutool apply FILE ID DIR    -> apply mutant ID to DIR (in place)
mutool() {
    python3 - "$@" <<'PY'
import sys, os
def dec(s):
    out, i = [], 0
    while i < len(s):
        if s[i] == '\\' and i + 1 < len(s) and s[i+1] in 'nt\\':
            out.append({'n': '\n', 't': '\t', '\\': '\\'}[s[i+1]]); i += 2
        else:
            out.append(s[i]); i += 1
    return ''.join(out)
def parse(path):
    muts, cur = [], {}
    def flush(ln):
        if not cur: return
        miss = [k for k in ('id', 'file', 'desc', 'find', 'repl') if k not in cur]
        if miss: sys.exit("mutants.txt: mutant ending at line %d lacks %s" % (ln, ', '.join(miss)))
        muts.append(dict(cur)); cur.clear()
    with open(path) as f:
        lines = f.read().split('\n')
    for n, line in enumerate(lines, 1):
        if line.startswith('#'): continue
        if not line.strip(): flush(n); continue
        if ':' not in line: sys.exit("mutants.txt:%d: expected 'key: value'" % n)
        k, v = line.split(':', 1)
        k = k.strip()
        if k not in ('id', 'file', 'desc', 'find', 'repl'):
            sys.exit("mutants.txt:%d: unknown key %r" % (n, k))
        if k in cur: sys.exit("mutants.txt:%d: duplicate key %r (missing blank line?)" % (n, k))
        v = v.lstrip(' ')  # leading blanks only align the columns
        cur[k] = dec(v) if k in ('find', 'repl') else v.strip()
    flush(len(lines))
    ids = [m['id'] for m in muts]
    dup = sorted(set(i for i in ids if ids.count(i) > 1))
    if dup: sys.exit("mutants.txt: duplicate ids: %s" % ', '.join(dup))
    for m in muts:
        if not m['file'].startswith(('src/', 'include/', 'tools/')) or '..' in m['file']:
            sys.exit("mutant %s: file %s is not under src/, include/ or tools/" % (m['id'], m['file']))
        if m['find'] == m['repl'] or not m['find']:
            sys.exit("mutant %s: empty search string or replacement equal to it (no-op)" % m['id'])
    return muts
def check(m, root):
    p = os.path.join(root, m['file'])
    if not os.path.isfile(p):
        sys.exit("mutant %s: file %s does not exist" % (m['id'], m['file']))
    with open(p) as f: text = f.read()
    n = text.count(m['find'])
    if n != 1:
        sys.exit("mutant %s: search string %r matches %d times in %s (must be exactly 1)"
                 % (m['id'], m['find'], n, m['file']))
    return p, text
cmd, path = sys.argv[1], sys.argv[2]
muts = parse(path)
if cmd == 'list':
    for m in muts: print('%s\t%s\t%s' % (m['id'], m['file'], m['desc']))
elif cmd == 'check':
    for m in muts: check(m, sys.argv[3])
elif cmd == 'apply':
    sel = [m for m in muts if m['id'] == sys.argv[3]]
    if not sel: sys.exit("no mutant %s in %s" % (sys.argv[3], path))
    m = sel[0]
    p, text = check(m, sys.argv[4])
    new = text.replace(m['find'], m['repl'], 1)
    if new == text: sys.exit("mutant %s: replacement changed nothing" % m['id'])
    with open(p, 'w') as f: f.write(new)
else:
    sys.exit("mutool: unknown command " + cmd)
PY
}

MUTS=$(mutool list "$LIST") || die "bad mutant list $LIST"
[ -n "$MUTS" ] || die "no mutants in $LIST"
if [ $# -gt 0 ]; then
    sel=""
    for id in "$@"; do
        line=$(printf '%s\n' "$MUTS" | awk -F'\t' -v id="$id" '$1 == id')
        [ -n "$line" ] || die "no mutant $id in $LIST"
        sel="$sel$line"$'\n'
    done
    MUTS=${sel%$'\n'}
fi

# ---- scratch copy and baseline -------------------------------------------
SCR=$(mktemp -d "${TMPDIR:-/tmp}/certbox-mutants.XXXXXX") || die "mktemp failed"
if [ "${MUT_KEEP:-0}" = 1 ]; then
    echo "mutants: scratch directory $SCR (kept)"
else
    trap 'rm -rf "$SCR"' EXIT
fi
trap 'exit 130' INT TERM
BASE=$SCR/base
mkdir -p "$BASE"
for d in include src specs tests examples tools bench; do
    [ -d "$ROOT/$d" ] || die "$ROOT/$d missing"
    cp -pR "$ROOT/$d" "$BASE/$d"
done
cp -p "$ROOT/Makefile" "$BASE/Makefile"
# the Makefile reads its list of test oracles from scripts/testutil.sh and
# the link flags of GMP and MPFR from scripts/exactlibs.sh
mkdir -p "$BASE/scripts"
cp -p "$ROOT/scripts/testutil.sh" "$ROOT/scripts/exactlibs.sh" "$BASE/scripts/"
# tests/data/gltf/escape.bin is a symbolic link to ../../../README.md (a
# uri that leaves its folder through a link): it must resolve in the copy
cp -p "$ROOT/README.md" "$BASE/README.md"
rm -rf "$BASE/build"

TESTS="test_badinput test_exact test_cbox test_sphere test_special test_alias test_halfspace test_batch test_tight test_eft test_float test_classes test_plane test_project test_chain test_trs test_psphere test_pnear test_pball test_pwide test_pell"
BINS="build/test_badinput build/test_exact build/test_cbox build/test_sphere build/test_special build/test_alias build/test_halfspace build/test_batch build/test_tight build/test_eft build/test_float build/test_classes build/test_plane build/test_project build/test_chain build/test_trs build/test_psphere build/test_pnear build/test_pball build/test_pwide build/test_pell"
# the scene tool's glTF reader (tools/certbox/gltf.c): test_gltf, which also runs
# the tool; only with jansson (the Makefile's optional dependency)
GLTF=0
if pkg-config --exists jansson 2>/dev/null; then
    GLTF=1
    TESTS="$TESTS test_gltf"
    BINS="$BINS build/test_gltf build/certbox"
else
    echo "mutants: jansson (libjansson-dev) not found: test_gltf is not run; the mutants of tools/certbox/gltf.c are skipped"
fi
args_of() {
    case $1 in
    test_badinput) echo "" ;;
    test_exact) echo "$EXACT_N $SEED" ;;
    test_cbox) echo "$CBOX_N $SEED" ;;
    test_sphere) echo "$SPHERE_N $SEED" ;;
    test_special) echo "" ;;
    test_alias) echo "20000 $SEED" ;;
    test_halfspace) echo "$HALF_N $SEED" ;;
    test_batch) echo "50 $SEED" ;;
    test_tight) echo "${MUT_TIGHT_N:-40} $SEED" ;;
    test_eft) echo "100 $SEED" ;;
    test_float) echo "${MUT_FLOAT_N:-50000} $SEED" ;;
    test_classes) echo "${MUT_CLASSES_N:-20000} $SEED" ;;
    test_plane) echo "${MUT_PLANE_N:-20000} $SEED" ;;
    test_project) echo "${MUT_PROJECT_N:-5000} $SEED" ;;
    test_chain) echo "${MUT_CHAIN_STEPS:-200} 5 $SEED" ;;
    test_trs) echo "${MUT_TRS_N:-3000} $SEED" ;;
    test_psphere) echo "${MUT_PSPHERE_N:-5000} $SEED" ;;
    test_pnear) echo "${MUT_PNEAR_N:-5000} $SEED" ;;
    test_pball) echo "${MUT_PBALL_N:-3000} $SEED" ;;
    test_pwide) echo "${MUT_PWIDE_N:-2000} $SEED" ;;
    test_pell) echo "${MUT_PELL_N:-3000} $SEED" ;;
    test_gltf) echo "/usr/share/assimp/models/glTF2 tests/data/gltf build/certbox ${MUT_GLTF_N:-20000}" ;;
    esac
}
# $NICE, $BINS and the test arguments are meant to be split into words.
# shellcheck disable=SC2086
build() { # dir logfile
    (cd "$1" && $NICE make -s ${CC:+CC="$CC"} $BINS) </dev/null >"$2" 2>&1
}
# run_tests dir logdir -> sets CAUGHT_BY (space separated, empty if none)
run_tests() {
    CAUGHT_BY=""
    local t rc
    for t in $TESTS; do
        # shellcheck disable=SC2046,SC2086
        (cd "$1" && timeout "$TMO" $NICE ./build/$t $(args_of $t)) </dev/null >"$2/$t.log" 2>&1
        rc=$?
        case $rc in
        0) ;;
        124) CAUGHT_BY="$CAUGHT_BY $t(timeout)" ;;
        1) CAUGHT_BY="$CAUGHT_BY $t" ;;
        *) if [ $rc -gt 128 ]; then CAUGHT_BY="$CAUGHT_BY $t(signal $((rc - 128)))"
           else CAUGHT_BY="$CAUGHT_BY $t(exit $rc)"; fi ;;
        esac
    done
    CAUGHT_BY=${CAUGHT_BY# }
}

T0=$(date +%s)
mutool check "$LIST" "$BASE" || die "mutant list does not match the sources"
mkdir -p "$SCR/logs/base"
echo "mutants: baseline build and tests (exact $EXACT_N, cbox $CBOX_N, sphere $SPHERE_N, halfspace $HALF_N, seed $SEED)"
build "$BASE" "$SCR/logs/base/build.log" || { cat "$SCR/logs/base/build.log" >&2; die "baseline does not build"; }
run_tests "$BASE" "$SCR/logs/base"
if [ -n "$CAUGHT_BY" ]; then
    for t in $CAUGHT_BY; do t=${t%%(*}; tail -n 20 "$SCR/logs/base/$t.log" >&2; done
    die "baseline (unmutated) tests fail: $CAUGHT_BY"
fi
echo "mutants: baseline passes ($(( $(date +%s) - T0 )) s)"

# ---- the mutants -----------------------------------------------------------
total=0; caught=0; survivors=""; bad=""; skipped=""
while IFS=$'\t' read -r id file desc; do
    [ -n "$id" ] || continue
    if [ "$file" = tools/certbox/gltf.c ] && [ $GLTF = 0 ]; then
        skipped="$skipped $id"
        printf '%-16s %-20s %-68s %s\n' "$id" "$file" "$desc" "SKIPPED (no jansson: test_gltf not built)"
        continue
    fi
    total=$((total + 1))
    W=$SCR/m; L=$SCR/logs/$id
    rm -rf "$W"; mkdir -p "$L"
    cp -pR "$BASE" "$W"
    t1=$(date +%s)
    mutool apply "$LIST" "$id" "$W" || die "cannot apply mutant $id"
    touch "$W/$file"
    if cmp -s "$BASE/$file" "$W/$file"; then die "mutant $id left $file unchanged"; fi
    if ! build "$W" "$L/build.log"; then
        res="BAD-MUTANT (does not build)"
        bad="$bad $id"
        sed 's/^/    /' "$L/build.log" | head -n 15 >&2
    else
        run_tests "$W" "$L"
        if [ -n "$CAUGHT_BY" ]; then
            caught=$((caught + 1)); res="CAUGHT by $CAUGHT_BY"
        else
            survivors="$survivors $id"; res="SURVIVED"
        fi
    fi
    printf '%-16s %-20s %-68s %s [%ss]\n' "$id" "$file" "$desc" "$res" "$(( $(date +%s) - t1 ))"
done <<EOF
$MUTS
EOF

echo "mutants: $caught caught / $total total ($(( $(date +%s) - T0 )) s)"
if [ -n "$survivors" ]; then echo "survivors:$survivors"; else echo "survivors: none"; fi
if [ -n "$skipped" ]; then echo "skipped (no jansson):$skipped"; fi
if [ -n "$bad" ]; then echo "bad mutants (do not build):$bad"; exit 2; fi
[ -z "$survivors" ] || exit 1
exit 0
