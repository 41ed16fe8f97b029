#!/bin/sh
# libFuzzer harnesses of certbox with an exact-rational (GMP) oracle.
#
#   sh scripts/fuzz.sh [SECONDS [HARNESS...]]
#
# SECONDS: time per harness (default 60), passed to -max_total_time.
# HARNESS: any of transform_box transform_cbox box_to_cbox cbox_to_box
#          sphere_box ellipsoid_box plane project psphere pell pnear pball pwide
#          gltf (default: all fourteen, one after the other).  plane
#          (tests/fuzz/fuzz_plane.c): the 2D family; project
#          (tests/fuzz/fuzz_project.c): the projective bound;
#          psphere (tests/fuzz/fuzz_psphere.c): a ball under a projective map;
#          pell (tests/fuzz/fuzz_pell.c): an ellipsoid under a projective map;
#          pnear (tests/fuzz/fuzz_pnear.c): a box clipped at a near plane;
#          pball (tests/fuzz/fuzz_pball.c): a ball clipped at a near plane;
#          pwide (tests/fuzz/fuzz_pwide.c): the binary32 twins of those three
#          (cbx_project_spheref, cbx_project_box_nearf,
#          cbx_project_sphere_nearf) against binary64 and the exact oracles.
#
# gltf (tests/fuzz/fuzz_gltf.c): the scene tool's glTF reader
# (tools/certbox/gltf.c) on arbitrary file contents, against the exact oracle
# of test_gltf (tests/gltf_oracle.c); it needs jansson (pkg-config
# jansson): without it that harness is skipped with a message (not a
# failure).  Its seeds are files of tests/data/gltf/ and small models of
# /usr/share/assimp/models/glTF2/ (assimp-testmodels; those absent are
# skipped), copied to its scratch corpus; inputs up to 4096 bytes.
#
# Each harness (tests/fuzz/fuzz_<name>.c) is built with clang
# -fsanitize=fuzzer,address,undefined, linking the library sources src/*/*.c
# directly and the oracles of scripts/testutil.sh (each compiled once into
# an archive), into build/fuzz/; its seed corpus
# (tests/fuzz/corpus/<name>/, written by tests/fuzz/make_corpus.c) is copied
# to the scratch directory build/fuzz/run/<name>/corpus, which the run then
# grows; crash reproducers go to build/fuzz/run/<name>/ (crash-*, ...), and
# the full log to build/fuzz/run/<name>/log.  A harness abort()s when the
# oracle fails; the log then shows the decoded input and output.
# Replay a reproducer: build/fuzz/fuzz_<name> build/fuzz/run/<name>/crash-...
#
# Per harness it prints the executions, the corpus size (files) and the
# crashes found (two harnesses run at a time, each for SECONDS).  Builds and
# runs are under nice -n 19.
# Needs clang with libFuzzer (Debian bookworm: clang and libclang-rt-14-dev);
# installed with apt-get when absent and running as root (FUZZ_NO_INSTALL=1:
# never install).  FUZZ_CC: the compiler (default clang).
# Exit status: 0 no crash, 1 some harness found a crash (or failed to run),
# 2 clang/libFuzzer (or GMP/MPFR) unavailable, or a usage error.
set -u

ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT" || exit 2
SECS=${1:-60}
[ $# -gt 0 ] && shift
ALL="transform_box transform_cbox box_to_cbox cbox_to_box sphere_box ellipsoid_box plane project psphere pell pnear pball pwide gltf"
GLTFDIR=/usr/share/assimp/models/glTF2
# the gltf harness's seeds (self-contained files: GLB, data: URIs; and a few
# refused ones)
GLTF_SEEDS="tests/data/gltf/cube.glb tests/data/gltf/trs.gltf tests/data/gltf/matrix.gltf
 tests/data/gltf/sparse.gltf tests/data/gltf/quantized.gltf tests/data/gltf/interleaved.gltf
 tests/data/gltf/two_scenes.gltf tests/data/gltf/overflow.gltf tests/data/gltf/nan_inf.gltf
 tests/data/gltf/anim_rot.gltf tests/data/gltf/anim_two.gltf
 tests/data/gltf/claims.gltf tests/data/gltf/cycle.gltf tests/data/gltf/glb_nobin.glb
 $GLTFDIR/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb
 $GLTFDIR/BoxBadNormals-glTF-Binary/BoxBadNormals.glb
 $GLTFDIR/RecursiveNodes/RecursiveNodes.gltf $GLTFDIR/cameras/Cameras.gltf
 $GLTFDIR/TestNoRootNode/SceneWithoutNodes.gltf"
HARNESSES=${*:-$ALL}
B=build/fuzz
NICE="nice -n 19"
CLANG=${FUZZ_CC:-clang}

case $SECS in ''|*[!0-9]*) echo "usage: $0 [SECONDS [HARNESS...]]" >&2; exit 2;; esac
for h in $HARNESSES; do
    [ -f "tests/fuzz/fuzz_$h.c" ] || { echo "fuzz: unknown harness '$h' (one of: $ALL)" >&2; exit 2; }
done

# ---- clang with libFuzzer ------------------------------------------------
mkdir -p "$B" || exit 2
cat > "$B/probe.c" <<'EOF'
#include <stddef.h>
#include <stdint.h>
int LLVMFuzzerTestOneInput(const uint8_t *d, size_t n);
int LLVMFuzzerTestOneInput(const uint8_t *d, size_t n) { (void)d; (void)n; return 0; }
EOF
probe() {
    command -v "$CLANG" >/dev/null 2>&1 \
    && "$CLANG" -fsanitize=fuzzer,address,undefined "$B/probe.c" -o "$B/probe" >/dev/null 2>&1 \
    && "$B/probe" -runs=1 >/dev/null 2>&1
}
apt_install() { # install the packages that apt-cache knows; 1 if none
    pk=""
    for p in "$@"; do
        apt-cache show "$p" >/dev/null 2>&1 && pk="$pk $p"
    done
    [ -n "$pk" ] || return 1
    echo "fuzz: installing$pk" >&2
    # shellcheck disable=SC2086
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends $pk >&2
}
if ! probe && [ -z "${FUZZ_NO_INSTALL:-}" ] && [ "$(id -u)" = 0 ] \
   && command -v apt-get >/dev/null 2>&1; then
    apt-get update -q >&2
    command -v "$CLANG" >/dev/null 2>&1 || apt_install clang
    if command -v "$CLANG" >/dev/null 2>&1 && ! probe; then
        # libFuzzer and the sanitizer runtimes (only "recommended" by clang)
        v=$("$CLANG" -dumpversion 2>/dev/null | cut -d. -f1)
        apt_install "libclang-rt-$v-dev" || apt_install libclang-rt-dev
    fi
fi
if ! probe; then
    if command -v "$CLANG" >/dev/null 2>&1; then
        echo "fuzz: $CLANG cannot link -fsanitize=fuzzer,address,undefined (libFuzzer missing);" \
             "install libclang-rt-<version>-dev; no fuzzing done" >&2
    else
        echo "fuzz: clang is unavailable (apt-get install clang libclang-rt-14-dev);" \
             "no fuzzing done" >&2
    fi
    exit 2
fi
sh scripts/deps.sh test >/dev/null || { echo "fuzz: GMP/MPFR headers unavailable" >&2; exit 2; }

# ---- build ---------------------------------------------------------------
CFLAGS="-std=c99 -O1 -g -Wall -Wextra -ffp-contract=off -fno-fast-math \
 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
HAVE_JANSSON=0
pkg-config --exists jansson 2>/dev/null && HAVE_JANSSON=1
SKIPPED=""
# The library's sources, compiled once with the harnesses' flags and linked
# into each (each harness used to recompile all of src/: 9 of them took
# most of the phase's minutes; an object archive of this one build does not),
# and the exact oracles of scripts/testutil.sh likewise (--oracles: not the
# tests' parts).
# archive ARCHIVE DIR EXTRA SOURCE...: every source compiled at once into
# DIR (with the extra flags EXTRA), then archived
archive() {
    a=$1; d=$2; x=$3; shift 3
    mkdir -p "$d"
    rm -f "$d/"*.o "$a"
    for f in "$@"; do
        # shellcheck disable=SC2046,SC2086
        $NICE "$CLANG" $CFLAGS $(sh scripts/incs.sh) $x -c "$f" -o "$d/$(echo "$f" | tr / _ | sed 's/\.c$/.o/')" &
    done
    wait
    for f in "$@"; do
        [ -f "$d/$(echo "$f" | tr / _ | sed 's/\.c$/.o/')" ] || { echo "fuzz: build of $f failed" >&2; return 1; }
    done
    ar rcs "$a" "$d/"*.o
}
archive "$B/libcertbox-fuzz.a" "$B/lib" "" src/*/*.c || exit 1
# shellcheck disable=SC2046
archive "$B/libtestutil-fuzz.a" "$B/tu" -Itests $(sh scripts/testutil.sh --oracles) || exit 1
for h in $HARNESSES; do
    if [ "$h" = gltf ]; then
        if [ $HAVE_JANSSON = 0 ]; then
            echo "fuzz: jansson (libjansson-dev) not found: the gltf harness is skipped" >&2
            SKIPPED="$SKIPPED gltf"
            continue
        fi
        echo "fuzz: building $B/fuzz_$h" >&2
        # shellcheck disable=SC2046,SC2086
        $NICE "$CLANG" $CFLAGS -DCBX_GLTF $(pkg-config --cflags jansson) $(sh scripts/incs.sh) -Itools/certbox -Itests \
            tests/fuzz/fuzz_gltf.c tests/gltf_oracle.c tools/certbox/gltf.c "$B/libcertbox-fuzz.a" \
            $(pkg-config --libs jansson) -lgmp -lm -o "$B/fuzz_$h" \
            || { echo "fuzz: build of fuzz_$h failed" >&2; exit 1; }
        continue
    fi
    echo "fuzz: building $B/fuzz_$h" >&2
    # shellcheck disable=SC2086
    $NICE "$CLANG" $CFLAGS $(sh scripts/incs.sh) -Itests "tests/fuzz/fuzz_$h.c" "$B/libtestutil-fuzz.a" \
        "$B/libcertbox-fuzz.a" -lmpfr -lgmp -lm -o "$B/fuzz_$h" || { echo "fuzz: build of fuzz_$h failed" >&2; exit 1; }
done

# ---- run -----------------------------------------------------------------
# One harness: its line of the table to $B/run/NAME.line, its failure
# details to $B/run/NAME.more.  Two harnesses run at a time (each one
# process for SECONDS), the table printed in the list's order.
run_one() {
    h=$1
    run=$B/run/$h
    rm -rf "$run"
    mkdir -p "$run/corpus"
    maxlen=256
    dict=""
    mkdir -p "$run/tmp"         # TMPDIR of the run (fuzz_gltf's private folders)
    if [ "$h" = gltf ]; then
        maxlen=4096
        dict=-dict=tests/fuzz/gltf.dict
        for f in $GLTF_SEEDS; do [ -f "$f" ] && cp "$f" "$run/corpus/"; done
    else
        cp tests/fuzz/corpus/"$h"/* "$run/corpus/"
    fi
    TMPDIR=$PWD/$run/tmp $NICE "./$B/fuzz_$h" -max_total_time="$SECS" -max_len=$maxlen -timeout=20 $dict \
        -print_final_stats=1 -artifact_prefix="$run/" "$run/corpus" > "$run/log" 2>&1
    rc=$?
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$run/log" | tail -n 1)
    [ -n "$execs" ] || execs=$(sed -n 's/^#\([0-9]*\).*/\1/p' "$run/log" | tail -n 1)
    size=$(find "$run/corpus" -type f | wc -l | tr -d ' ')
    crashes=$(find "$run" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'leak-*' \
              -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l | tr -d ' ')
    if [ "$rc" -ne 0 ] || [ "$crashes" -ne 0 ]; then
        result="FAIL (exit $rc), log $run/log"
    else
        result=ok
    fi
    printf '%-16s %12s %8s %8s  %s\n' "$h" "${execs:-?}" "$size" "$crashes" "$result" > "$B/run/$h.line"
    : > "$B/run/$h.more"
    if [ "$result" != ok ]; then
        # the oracle's message and the decoded reproducer (or the sanitizer's report)
        if grep -q 'oracle FAILURE' "$run/log"; then
            sed -n '/==== certbox fuzz oracle FAILURE/,/^====$/p' "$run/log" | sed 's/^/    /'
        else
            grep -E 'ERROR|runtime error|SUMMARY' "$run/log" | head -n 8 | sed 's/^/    /'
        fi
        find "$run" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'leak-*' \
             -o -name 'timeout-*' -o -name 'oom-*' \) | sed 's#^#    reproducer: #'
    fi >> "$B/run/$h.more"
}
bad=0
mkdir -p "$B/run"
n=0
for h in $HARNESSES; do
    rm -f "$B/run/$h.line" "$B/run/$h.more"
    case " $SKIPPED " in *" $h "*) printf '%-16s %12s %8s %8s  %s\n' "$h" - - - "skipped (no jansson)" > "$B/run/$h.line"; continue;; esac
    run_one "$h" &
    n=$((n + 1))
    [ $((n % 2)) = 0 ] && wait
done
wait
printf '%-16s %12s %8s %8s  %s\n' harness executions corpus crashes result
for h in $HARNESSES; do
    if [ -f "$B/run/$h.line" ]; then cat "$B/run/$h.line"; else echo "$h: FAIL (no result)"; bad=1; fi
    grep -q ' ok$\| skipped (no jansson)$' "$B/run/$h.line" 2>/dev/null || bad=1
    cat "$B/run/$h.more" 2>/dev/null
done
exit $bad
