#!/bin/sh
# Install what certbox needs from Debian's packages, when it is absent.
# Usage: scripts/deps.sh [build|test|proof|fuzz|bench|embedded|cross|evidence|all]
#   build     gcc, make
#   test      + GMP, MPFR, g++, pkg-config, python3, cmake (install-check's
#               CMake consumer), jansson (the tool's glTF input) and
#               assimp-testmodels (glTF files for test_gltf)
#   proof     + frama-c-base, why3, cvc4, z3, ocaml-findlib
#   fuzz      + clang and its libFuzzer/sanitizer runtimes
#   bench     + gnuplot-nox (make bench draws its plot)
#   embedded  + arm-none-eabi-gcc (make embedded: Cortex-M4F/M7, freestanding)
#   cross     + the armhf cross compiler, armhf GMP/MPFR/jansson and qemu-user
#               (make check-cross; adds the armhf architecture to dpkg)
#   evidence  + gcovr, cppcheck, clang-tidy (make evidence)
#   all       everything make check uses (all of the above but bench)
# Idempotent: a machine that has everything installs nothing.
set -eu
what=${1:-all}
need=""
have() { command -v "$1" >/dev/null 2>&1; }
hdr() { [ -f "/usr/include/$1" ] || [ -f "/usr/include/x86_64-linux-gnu/$1" ] \
        || [ -n "$(find /usr/include -name "$1" -print -quit 2>/dev/null)" ]; }
is() { [ "$what" = "$1" ] || [ "$what" = all ]; }
case $what in build|test|proof|fuzz|bench|embedded|cross|evidence|all) ;;
  *) echo "usage: $0 [build|test|proof|fuzz|bench|embedded|cross|evidence|all]" >&2; exit 2;; esac
have cc || need="$need gcc"
have make || need="$need make"
if [ "$what" != build ]; then
  hdr gmp.h || need="$need libgmp-dev"
  hdr mpfr.h || need="$need libmpfr-dev"
  have g++ || need="$need g++"
  have pkg-config || need="$need pkg-config"
  have python3 || need="$need python3"
  have cmake || need="$need cmake"
  hdr jansson.h || need="$need libjansson-dev"
  [ -d /usr/share/assimp/models/glTF2 ] || need="$need assimp-testmodels"
fi
if is fuzz; then
  # libFuzzer and the sanitizer runtimes of clang (only recommended by clang)
  have clang || need="$need clang"
  [ -n "$(find /usr/lib/llvm-* -name 'libclang_rt.fuzzer-x86_64.a' -print -quit 2>/dev/null)" ] \
    || need="$need libclang-rt-14-dev"
fi
if [ "$what" = bench ]; then
  have gnuplot || need="$need gnuplot-nox"
fi
if is proof; then
  have frama-c || need="$need frama-c-base"
  have why3 || need="$need why3"
  have cvc4 || need="$need cvc4"
  have z3 || need="$need z3"
  # ocamlfind compiles proofs/idle.ml and proofs/prune.ml (proofs/plugin.sh:
  # the task loop without its naps, the drivers' transformations) with the
  # OCaml compiler, against Why3's library (frama-c-base depends on it)
  have ocamlfind || need="$need ocaml-findlib libfindlib-ocaml-dev"
  ocamlfind query why3 > /dev/null 2>&1 || need="$need libwhy3-ocaml-dev"
  have ocamlopt || need="$need ocaml"
fi
if is embedded; then
  have arm-none-eabi-gcc || need="$need gcc-arm-none-eabi"
fi
armhf=0
if is cross; then
  have arm-linux-gnueabihf-gcc || need="$need gcc-arm-linux-gnueabihf libc6-dev-armhf-cross"
  [ -f /usr/lib/arm-linux-gnueabihf/libgmp.a ] || { need="$need libgmp-dev:armhf"; armhf=1; }
  [ -f /usr/lib/arm-linux-gnueabihf/libmpfr.a ] || { need="$need libmpfr-dev:armhf"; armhf=1; }
  # test_gltf under qemu: the tool's JSON parser, static
  [ -f /usr/lib/arm-linux-gnueabihf/libjansson.a ] || { need="$need libjansson-dev:armhf"; armhf=1; }
  have qemu-arm || need="$need qemu-user"
fi
if is evidence; then
  have gcovr || need="$need gcovr"
  have cppcheck || need="$need cppcheck"
  have clang-tidy || need="$need clang-tidy"
fi
[ -z "$need" ] && exit 0
echo "deps: installing$need" >&2
if [ "$(id -u)" != 0 ]; then
  echo "deps: missing packages:$need (run as root, or install them)" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
if [ $armhf = 1 ] && ! dpkg --print-foreign-architectures | grep -qx armhf; then
  dpkg --add-architecture armhf
fi
# A mirror in the middle of a sync makes apt-get update fail on one index
# while the ones we need are fine: the install below says if anything is
# really missing.
apt-get update -q >&2 || echo "deps: apt-get update reported errors; installing anyway" >&2
# shellcheck disable=SC2086
apt-get install -y -q --no-install-recommends $need >&2
