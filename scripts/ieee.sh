#!/bin/sh
# The IEEE build checks and their teeth (make ieee-check, part of make check).
#   1. The library as built (build/libcertbox.a): cbx_ieee_check() == 0, also
#      after the tests' own runs; then with the FP environment broken at run
#      time: x86 flush-to-zero/denormals-are-zero, and the three directed
#      rounding modes: each must be caught (its bit set, no other).
#   2. The check's own sources built with flags that break the proofs'
#      model: FMA contraction (if this CPU has FMA), reassociation, no signed
#      zeros, an fma rounded twice, sqrt not correctly rounded (test hooks):
#      each must be caught at run time; the fma-free build must pass.
#   3. -ffast-math, -ffinite-math-only and x87 arithmetic (-mfpmath=387):
#      every library source must refuse to compile.
# Usage: sh scripts/ieee.sh CC  (run from the checkout's root, after make all)
set -eu
CC=${1:-cc}
B=build/ieee
mkdir -p $B
pass=0; fail=0
ok() { pass=$((pass + 1)); echo "ieee: ok   $*"; }
ko() { fail=$((fail + 1)); echo "ieee: FAIL $*"; }
FLAGS="-std=c99 -Wall -Wextra -Wpedantic -Werror -O2 $(sh scripts/incs.sh)"
$CC $FLAGS -ffp-contract=off tests/test_ieee.c build/libcertbox.a -lm -o $B/test_ieee
run() { # name expect mode
  if ./$B/test_ieee "$3" "$2" > $B/out.txt; then ok "$1: $(head -1 $B/out.txt | sed 's/^test_ieee: //')"
  else ko "$1: $(head -1 $B/out.txt)"; fi
}
run "library as built" 0 plain
grep probe $B/out.txt | sed 's/^test_ieee: /ieee: /' || true
case $(uname -m) in
  x86_64|i?86) run "flush-to-zero and denormals-are-zero set at run time" 0x04 ftz
               run "flush-to-zero alone" 0x04 ftzonly
               run "denormals-are-zero alone" 0x04 daz ;;
esac
run "rounding upward" 0x08 up
run "rounding downward" 0x08 down
run "rounding toward zero" 0x08 zero
# 2. the check's sources built with bad flags
variant() { # name expect flags...
  name=$1; expect=$2; shift 2
  if $CC $FLAGS "$@" -c src/core/cbx_ieee.c -o $B/v1.o && $CC $FLAGS "$@" -c src/f32/cbx_ieee_f.c -o $B/v2.o \
     && $CC $FLAGS -ffp-contract=off tests/test_ieee.c $B/v1.o $B/v2.o build/libcertbox.a -lm -o $B/test_v; then
    if ./$B/test_v plain "$expect" > $B/out.txt; then ok "$name: $(head -1 $B/out.txt | sed 's/.*: //')"
    else ko "$name: $(head -1 $B/out.txt)"; fi
  else ko "$name: did not build"; fi
}
if [ "$(uname -m)" = x86_64 ] && grep -qw fma /proc/cpuinfo 2>/dev/null; then
  variant "built with -ffp-contract=fast -mfma (FMA contraction)" 0x01 -ffp-contract=fast -mfma
else
  echo "ieee: skip FMA contraction on x86 (no FMA here; check-cross builds the GNU default on ARM)"
fi
variant "built with -fassociative-math -fno-signed-zeros -fno-trapping-math" 0x3a \
  -fassociative-math -fno-signed-zeros -fno-trapping-math
variant "built with -fno-signed-zeros" 0x10 -fno-signed-zeros
# what the proofs trust, broken through the test hooks: an fma rounded
# twice (x*y+z, as newlib's generic fma) and square roots that are not
# correctly rounded (binary64 through the x87 format, binary32 by Newton's
# iteration); the fma-free build (Dekker's product) must pass
variant "fma replaced by x*y+z (CBX_TEST_NAIVE_FMA)" 0x140 -DCBX_TEST_NAIVE_FMA
variant "sqrt and sqrtf not correctly rounded (CBX_TEST_NAIVE_SQRT)" 0x80 -DCBX_TEST_NAIVE_SQRT
variant "division through the reciprocal (CBX_TEST_NAIVE_DIV)" 0x200 -DCBX_TEST_NAIVE_DIV
variant "fma-free build (CBX_NO_FMA: Dekker's product) passes" 0 -DCBX_NO_FMA
# 3. refused at compile time, by every library source
refused() { # name flags...
  name=$1; shift
  n=0; r=0
  for f in src/*/cbx_*.c; do
    n=$((n + 1))
    if $CC $FLAGS "$@" -c "$f" -o $B/r.o 2> $B/err.txt; then :; else
      grep -q 'certbox:' $B/err.txt && r=$((r + 1)); fi
  done
  if [ $r = $n ]; then ok "$name refused by all $n sources"; else ko "$name refused by $r of $n sources"; fi
}
refused "-ffast-math" -ffast-math
refused "-ffinite-math-only" -ffinite-math-only
case $(uname -m) in
  x86_64|i?86) refused "x87 arithmetic (-mfpmath=387, FLT_EVAL_METHOD 2)" -mfpmath=387 ;;
esac
echo "ieee: $pass passed, $fail failed"
echo "$pass passed, $fail failed"
[ $fail = 0 ]
