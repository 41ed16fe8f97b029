#!/bin/sh
# make check-cross: the exact test suites on a second architecture.
# Every suite (the tight mode with both two_prod forms among them) is
# cross-compiled for 32-bit ARM (arm-linux-gnueabihf, VFP,
# statically linked with the armhf GMP and MPFR), run under qemu-arm, and
# its output compared line by line with the same run on this machine: IEEE
# arithmetic is deterministic, so every count, status, excess statistic and
# histogram must be the same (only durations are left out).  Then the
# build check on ARM: cbx_ieee_check() == 0, and a build of its sources in
# GCC's default GNU mode for a VFPv4 CPU (which has fused multiply-add and
# contracts a*b+c there) must be caught.
# test_gltf (the scene tool's glTF reader) too when jansson is there for
# both (host and armhf: sh scripts/deps.sh cross), skipped with a message
# otherwise.
# Usage: sh scripts/cross.sh  (run from the checkout's root, after make all)
set -eu
XCC=${XCC:-arm-linux-gnueabihf-gcc}
QEMU=${QEMU:-qemu-arm}
B=build/cross
mkdir -p $B
F="-std=c99 -Wall -Wextra -Wpedantic -Werror -ffp-contract=off -fno-fast-math -O2 $(sh scripts/incs.sh) -Itests"
LIB="src/*/cbx_*.c"
# suite and arguments (host and ARM alike), the longest under qemu first
# (test_gltf, when there, before them); sizes keep the whole under ~1.5
# minutes: the ARM runs compare outputs line by line, so every hard-case
# table runs whole and the random cases are a sample of the kind of input,
# not a search (make test runs those at full size).  2026-11-29: the five
# longest halved; 2026-12-01: every random count halved again, to keep make
# check within CI's 30 minutes (alone 80 s instead of about 130 s; each
# suite's time then: pwide 18 s, gltf 17 s, pnear and tight 10 s, pell and
# tight_nofma 9 s, the rest 8 s or less)
# (NAME_nofma: tests/test_NAME.c and the library built with -DCBX_NO_FMA,
# compared with build/test_NAME_nofma; eft: both two_prod forms, GMP)
GLTFDIR=/usr/share/assimp/models/glTF2
GLTF_N=${CROSS_GLTF_N:-5000}
SUITES=${CROSS_SUITES:-"pwide:1000,1 pnear:2000,1 tight:5,1 pell:1500,1 tight_nofma:5,1 batch:10,1 classes:5000,1 float:12500,1 trs:1000,1 sphere:5000,1 psphere:2000,1 pball:1000,1 alias:5000,1 exact:50000,1 cbox:15000,1 eft:50,1 imat:10000,2500,1 halfspace:10,1 special: chain:100,5,1 badinput:"}
# one suite: build it for ARM (against the ARM library built once below),
# run it here and under qemu, compare; the verdict line goes to
# $B/NAME.verdict, with the suite's time
suite() {
  s=$1
  t0=$(date +%s)
  name=${s%%:*}; args=$(echo "${s#*:}" | tr ',' ' ')
  src=$name; lib=$B/libcertbox.a; extra=""
  case $name in *_nofma) src=${name%_nofma}; lib=$B/libcertbox_nofma.a; extra=-DCBX_NO_FMA ;; esac
  if [ "$name" = gltf ]; then
    G="-DCBX_GLTF -Itools/certbox"
    # shellcheck disable=SC2086
    $XCC $F $G tests/test_gltf.c tests/gltf_oracle.c tests/gltf_anim.c tools/certbox/gltf.c $B/libtestutil.a $lib -static -ljansson -lmpfr -lgmp -lm -o $B/test_gltf
    # shellcheck disable=SC2086
    $XCC $F $G tools/certbox/main.c tools/certbox/scene.c tools/certbox/gltf.c $lib -static -ljansson -lm -o $B/certbox
    ./build/test_gltf $GLTFDIR tests/data/gltf build/certbox "$GLTF_N" > $B/$name.host.txt 2>&1 || true
    $QEMU $B/test_gltf $GLTFDIR tests/data/gltf "$QEMU $B/certbox" "$GLTF_N" > $B/$name.arm.txt 2>&1 || true
    args="$GLTFDIR tests/data/gltf build/certbox $GLTF_N (ARM: $QEMU $B/certbox)"
  else
  # shellcheck disable=SC2086
  $XCC $F $extra tests/test_$src.c $B/libtestutil.a $lib -static -lmpfr -lgmp -lm -o $B/test_$name
  # shellcheck disable=SC2086
  ./build/test_$name $args > $B/$name.host.txt 2>&1 || true
  # shellcheck disable=SC2086
  $QEMU $B/test_$name $args > $B/$name.arm.txt 2>&1 || true
  fi
  # durations are the only thing allowed to differ
  T='s/[0-9]+(\.[0-9]+)? ?(s|ms|seconds)\b/<time>/g'
  grep -v -i 'cpu time' $B/$name.host.txt | sed -E "$T" > $B/$name.host.cmp || true
  grep -v -i 'cpu time' $B/$name.arm.txt | sed -E "$T" > $B/$name.arm.cmp || true
  last=$(tail -1 $B/$name.arm.txt)
  t=$(( $(date +%s) - t0 ))
  if cmp -s $B/$name.host.cmp $B/$name.arm.cmp && echo "$last" | grep -q ' 0 failed$'; then
    echo "cross: ok   test_$name $args: ARM output identical to the host's ($(wc -l < $B/$name.arm.cmp) lines; $last; $t s)" > $B/$name.verdict
  else
    { echo "cross: FAIL test_$name $args: last line '$last'"; diff $B/$name.host.cmp $B/$name.arm.cmp | head -5 || true; } > $B/$name.verdict
  fi
}
# sh scripts/cross.sh --suite S: one suite (the pool below runs these)
if [ "${1:-}" = --suite ]; then suite "$2"; exit 0; fi
pass=0; fail=0
echo "cross: $($XCC --version | head -1); $($QEMU --version | head -1)"
start=$(date +%s)
# test_gltf (the scene tool's glTF reader, tests/test_gltf.c): built with
# the armhf jansson (static), on the same files; the tool it runs is the
# ARM build of build/certbox, itself under qemu.  Skipped with a message
# (not a failure) without jansson on the host or for armhf.
if [ -z "${CROSS_SUITES:-}" ]; then
  if ! pkg-config --exists jansson 2>/dev/null || [ ! -f /usr/lib/arm-linux-gnueabihf/libjansson.a ]; then
    echo "cross: skip test_gltf: jansson missing (libjansson-dev on the host, libjansson-dev:armhf: sh scripts/deps.sh cross)"
  elif [ ! -d $GLTFDIR ]; then
    echo "cross: skip test_gltf: $GLTFDIR missing (assimp-testmodels: sh scripts/deps.sh test)"
  else
    SUITES="gltf: $SUITES"
  fi
fi
# The library for ARM, built once (and once with -DCBX_NO_FMA, for the
# tight mode's fma-free product), two objects at a time.
for v in "" _nofma; do
  mkdir -p $B/obj$v
  extra=""; [ -n "$v" ] && extra=-DCBX_NO_FMA
  # shellcheck disable=SC2086
  for c in $LIB; do echo "$c"; done | xargs -P 2 -I{} sh -c \
    'o='$B/obj$v'/$(basename {} .c).o; '"$XCC $F $extra"' -c {} -o $o' || { echo "cross: FAIL the ARM library$v did not build"; exit 1; }
  rm -f $B/libcertbox$v.a
  ${XCC%-gcc}-ar rcs $B/libcertbox$v.a $B/obj$v/*.o
done
# the exact oracles (scripts/testutil.sh) for ARM, once for every suite
mkdir -p $B/tu
# shellcheck disable=SC2046
for c in $(sh scripts/testutil.sh); do echo "$c"; done | xargs -P 2 -I{} sh -c \
  'o='$B'/tu/$(basename {} .c).o; '"$XCC $F"' -c {} -o $o' || { echo "cross: FAIL the ARM oracles did not build"; exit 1; }
rm -f $B/libtestutil.a
${XCC%-gcc}-ar rcs $B/libtestutil.a $B/tu/*.o
# two suites at a time (qemu is single-threaded), as each one ends the next
# starts; verdicts in list order
for s in $SUITES; do rm -f "$B/${s%%:*}.verdict"; done
echo $SUITES | tr ' ' '\n' | xargs -P 2 -I{} sh "$0" --suite {}
for s in $SUITES; do
  v=$B/${s%%:*}.verdict
  if [ -f "$v" ] && head -1 "$v" | grep -q '^cross: ok'; then pass=$((pass + 1)); else fail=$((fail + 1)); fi
  cat "$v" 2>/dev/null || echo "cross: FAIL test_${s%%:*}: no verdict"
done
# the build check on ARM
$XCC $F tests/test_ieee.c $B/libcertbox.a -static -lm -o $B/test_ieee
if $QEMU $B/test_ieee plain 0 > $B/ieee.txt; then pass=$((pass + 1)); echo "cross: ok   $(head -1 $B/ieee.txt)"
else fail=$((fail + 1)); echo "cross: FAIL $(head -1 $B/ieee.txt)"; fi
G="-std=gnu99 -O2 $(sh scripts/incs.sh) -mfpu=neon-vfpv4 -mfloat-abi=hard"
$XCC $G -c src/core/cbx_ieee.c -o $B/v1.o && $XCC $G -c src/f32/cbx_ieee_f.c -o $B/v2.o
$XCC $F tests/test_ieee.c $B/v1.o $B/v2.o src/core/cbx_status.c -static -lm -o $B/test_ieee_gnu
if $QEMU $B/test_ieee_gnu plain 1 > $B/ieee_gnu.txt; then
  pass=$((pass + 1)); echo "cross: ok   GNU mode on VFPv4 (contracts a*b+c): $(head -1 $B/ieee_gnu.txt | sed 's/.*: //')"
else fail=$((fail + 1)); echo "cross: FAIL GNU mode on VFPv4 not caught: $(head -1 $B/ieee_gnu.txt)"; fi
end=$(date +%s)
echo "cross: $pass passed, $fail failed in $((end - start)) s (armhf under qemu-user)"
echo "$pass passed, $fail failed"
[ $fail = 0 ]
