#!/bin/sh
# Install what certbox needs from Debian's packages, when it is absent.
# Usage: scripts/deps.sh [build|test|proof|fuzz|bench|all]   (default: all)
# bench: the test packages and gnuplot-nox (make bench draws its plot).
# Idempotent: a machine that has everything installs nothing.
set -eu
what=${1:-all}
need=""
have() { command -v "$1" >/dev/null 2>&1; }
hdr() { [ -f "/usr/include/$1" ] || [ -f "/usr/include/x86_64-linux-gnu/$1" ] \
        || [ -n "$(find /usr/include -name "$1" -print -quit 2>/dev/null)" ]; }
case $what in build|test|proof|fuzz|bench|all) ;; *) echo "usage: $0 [build|test|proof|fuzz|bench|all]" >&2; exit 2;; esac
have cc || need="$need gcc"
have make || need="$need make"
if [ "$what" != build ]; then
  hdr gmp.h || need="$need libgmp-dev"
  hdr mpfr.h || need="$need libmpfr-dev"
  have g++ || need="$need g++"
  have pkg-config || need="$need pkg-config"
fi
if [ "$what" = fuzz ] || [ "$what" = all ]; then
  # libFuzzer and the sanitizer runtimes of clang (only recommended by clang)
  have clang || need="$need clang"
  [ -n "$(find /usr/lib/llvm-* -name 'libclang_rt.fuzzer-x86_64.a' -print -quit 2>/dev/null)" ] \
    || need="$need libclang-rt-14-dev"
fi
if [ "$what" = bench ]; then
  have gnuplot || need="$need gnuplot-nox"
fi
if [ "$what" = proof ] || [ "$what" = all ]; then
  have frama-c || need="$need frama-c-base"
  have why3 || need="$need why3"
  have cvc4 || need="$need cvc4"
  have z3 || need="$need z3"
  have python3 || need="$need python3"
fi
[ -z "$need" ] && exit 0
echo "deps: installing$need" >&2
if [ "$(id -u)" != 0 ]; then
  echo "deps: missing packages:$need (run as root, or install them)" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -q >&2
# shellcheck disable=SC2086
apt-get install -y -q --no-install-recommends $need >&2
