#!/bin/sh
# Frama-C's option that loads the project's two OCaml modules into every
# Frama-C run of the proofs (proofs/job.sh, scripts/proof_teeth.sh,
# scripts/smoke_teeth.sh):
#   proofs/idle.ml   Frama-C's task loop without its 50 ms naps
#   proofs/prune.ml  the Why3 transformations that the drivers of
#                    proofs/setup.sh name: certbox_prune64, _prune32,
#                    _prunew (the axioms no goal needs), certbox_strip (the
#                    float facts of a memory-access goal), certbox_relevant
#                    and _relevant_wp (the axioms a goal cannot use), each
#                    leaving hypotheses out of a prover task
# They are compiled once per build tree (ocamlfind, against Frama-C's and
# Why3's libraries: scripts/deps.sh proof installs ocaml-findlib), into
# build/proof/certbox_wp.cmxs, and checked to load; the option is kept in
# build/proof/plugin.opt.  The drivers need the transformations, so where
# the modules do not compile or load this fails, and so does every proof.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
out=$root/build/proof
opt=$out/plugin.opt
if [ ! -f "$opt" ] || [ "$root/proofs/idle.ml" -nt "$opt" ] || [ "$root/proofs/prune.ml" -nt "$opt" ]; then
  mkdir -p "$out"
  # compiled beside copies (Frama-C's -load-script compiles beside the .ml,
  # so runs that start together would clash)
  tmp=$(mktemp -d "$out/plugin.XXXXXX")
  cp "$root/proofs/idle.ml" "$root/proofs/prune.ml" "$tmp/"
  echo 'int main(void) { return 0; }' > "$tmp/t.c"
  lib=$(frama-c -print-libpath 2>/dev/null)
  if (cd "$tmp" && ocamlfind ocamlopt -shared -o certbox_wp.cmxs -g -package why3 \
        -I "$lib" -I "$lib/plugins" idle.ml prune.ml \
      && frama-c -load-module "$tmp/certbox_wp.cmxs" t.c) > "$tmp/log" 2>&1; then
    mv "$tmp/certbox_wp.cmxs" "$out/certbox_wp.cmxs"
    echo "-load-module $out/certbox_wp.cmxs" > "$tmp/opt"
    mv "$tmp/opt" "$opt"   # atomic: runs that start together agree
    rm -rf "$tmp"
  else
    cat "$tmp/log" >&2
    rm -rf "$tmp"
    echo "proofs/plugin.sh: proofs/idle.ml and proofs/prune.ml do not compile or load (scripts/deps.sh proof installs ocaml-findlib)" >&2
    exit 1
  fi
fi
cat "$opt"
