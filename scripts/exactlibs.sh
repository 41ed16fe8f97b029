#!/bin/sh
# The link flags of GMP and MPFR for the tests, the demo, the bench and the
# evidence pack's coverage build: one answer for the Makefile (EXACTLIBS)
# and scripts/evidence.py.  Static where both archives are there (Debian's
# libgmp-dev, libmpfr-dev): MPFR's thread-local state is then read without
# a call to __tls_get_addr (measured 2026-11-30: test_trs 19% less CPU,
# test_project 8%, test_classes 3%; the same output); dynamic otherwise.
# Usage: sh scripts/exactlibs.sh [CC...]   (the compiler and its flags, default cc)
cc=${*:-cc}
for a in libmpfr.a libgmp.a; do
  f=$($cc -print-file-name=$a 2>/dev/null)
  case $f in /*) [ -f "$f" ] || { echo "-lmpfr -lgmp"; exit 0; } ;; *) echo "-lmpfr -lgmp"; exit 0 ;; esac
done
echo "-Wl,-Bstatic -lmpfr -lgmp -Wl,-Bdynamic"
