#!/bin/sh
# Frama-C's option that loads proofs/idle.ml, the task loop without its
# 50 ms naps, for every Frama-C run of the proofs (proofs/job.sh,
# scripts/proof_teeth.sh, scripts/smoke_teeth.sh).  It is compiled once per
# build tree, with the command Frama-C's own -load-script uses (which
# compiles beside the .ml, so runs that start together would clash), into
# build/proof/idle.cmxs; the option is kept in build/proof/idle.opt.  Where
# it does not compile or load (no ocaml-findlib: scripts/deps.sh proof
# installs it), this prints nothing and a warning: the proofs are the same,
# only slower.
root=$(cd "$(dirname "$0")/.." && pwd)
out=$root/build/proof
opt=$out/idle.opt
if [ ! -f "$opt" ] || [ "$root/proofs/idle.ml" -nt "$opt" ]; then
  mkdir -p "$out"
  tmp=$(mktemp -d "$out/idle.XXXXXX")
  cp "$root/proofs/idle.ml" "$tmp/idle.ml"
  echo 'int main(void) { return 0; }' > "$tmp/t.c"
  lib=$(frama-c -print-libpath 2>/dev/null)
  if (cd "$tmp" && ocamlfind ocamlopt -shared -o idle.cmxs -g -w -a -warn-error a \
        -I "$lib" -I "$lib/plugins" idle.ml && frama-c -load-module "$tmp/idle.cmxs" t.c) \
       > "$tmp/log" 2>&1; then
    mv "$tmp/idle.cmxs" "$out/idle.cmxs"
    echo "-load-module $out/idle.cmxs" > "$tmp/opt"
  else
    echo "proofs/idle.sh: proofs/idle.ml does not compile or load (is ocaml-findlib installed?); Frama-C keeps its 50 ms naps" >&2
    : > "$tmp/opt"
  fi
  mv "$tmp/opt" "$opt"   # atomic: runs that start together agree
  rm -rf "$tmp"
fi
cat "$opt"
