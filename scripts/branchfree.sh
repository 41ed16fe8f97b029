#!/bin/sh
# Is the fast path branch-free?  Compiles tests/branchfree.c twice with the
# given compiler and flags (make branchfree: the library's flags at -O2,
# $(INC) -Ispecs): binary64 (wrapper bf64) and with -DCBX_FLOAT=1 (bf32),
# each a call of cbx_fast_box (src/algo/cbx_fast.h) with everything it calls
# inlined.  Disassembles each wrapper with objdump -d and fails on any
# conditional branch (x86: every j* but jmp, loop*, jrcxz; AArch64: b.cond,
# cbz, cbnz, tbz, tbnz; ARM: b<cond>) and on any call (a call could hide
# one).  Prints what it checked.
# Usage: sh scripts/branchfree.sh CC FLAGS...
set -eu
cc=${1:?usage: sh scripts/branchfree.sh CC FLAGS...}
shift
src=${BRANCHFREE_SRC:-tests/branchfree.c}   # another source: the teeth test
dir=build/branchfree
mkdir -p "$dir"
command -v objdump >/dev/null 2>&1 || { echo "branchfree: objdump not found (Debian: binutils)"; exit 1; }
arch=$(uname -m)
case $arch in
  x86_64|i?86) cond='^j([^m]|m[^p])|^loop|^jrcxz|^jecxz'; call='^call';;
  aarch64|arm64) cond='^b\.|^cbn?z|^tbn?z'; call='^bl';;
  arm*) cond='^b(eq|ne|cs|hs|cc|lo|mi|pl|vs|vc|hi|ls|ge|lt|gt|le)(\.|$)|^cbn?z'; call='^blx?';;
  *) echo "branchfree: no conditional-branch pattern for $arch; not checked"; exit 0;;
esac
fail=0
for v in 64 32; do
  def=; [ $v = 32 ] && def=-DCBX_FLOAT=1
  obj=$dir/bf$v.o
  # shellcheck disable=SC2086
  "$cc" "$@" $def -c "$src" -o "$obj"
  # the wrapper's instructions: mnemonics only
  objdump -d --no-show-raw-insn --disassemble="bf$v" "$obj" \
    | awk -v f="<bf$v>:" '$2 == f { on = 1; next } /^$/ { on = 0 } on && /^ *[0-9a-f]+:/ { sub(/^ *[0-9a-f]+:[ \t]*/, ""); print $1 }' \
    > "$dir/bf$v.ops"
  n=$(wc -l < "$dir/bf$v.ops" | tr -d ' ')
  nb=$(grep -Ec "$cond" "$dir/bf$v.ops" || true)
  nc=$(grep -Ec "$call" "$dir/bf$v.ops" || true)
  echo "branchfree: bf$v (cbx_fast_box, binary$v, $arch): $n instructions, $nb conditional branches, $nc calls"
  if [ "$n" -lt 10 ]; then
    echo "branchfree: bf$v: only $n instructions found in the disassembly of $obj: cannot check"; fail=1
  elif [ "$nb" != 0 ] || [ "$nc" != 0 ]; then
    echo "branchfree: FAILED: bf$v has branches or calls:"; grep -En "$cond|$call" "$dir/bf$v.ops" | sed 's/^/  /'; fail=1
  fi
done
[ $fail = 0 ] && echo "branchfree: the fast path is branch-free in both formats (flags: $*)"
exit $fail
