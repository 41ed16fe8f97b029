# Sourced by scripts/smoke_teeth.sh and scripts/proof_teeth.sh.
# teeth_setup NAME: B=build/NAME (emptied), WHY3CONFIG for the provers,
# TEETH_ROOT the checkout.
teeth_setup() {
  TEETH_ROOT=$(pwd)
  B=$TEETH_ROOT/build/$1
  rm -rf "$B"
  mkdir -p "$B"
  WHY3CONFIG=$(sh proofs/setup.sh "$B/why3")
  export WHY3CONFIG
}
# teeth_incs DIR: Frama-C's include options for the copy in DIR (the
# library's folders, scripts/incs.sh, and specs/), and the modules of
# proofs/plugin.sh (the drivers' transformations, the task loop).
teeth_incs() {
  for i in $(sh "$TEETH_ROOT/scripts/incs.sh") -Ispecs; do printf -- '-cpp-extra-args=-I%s/%s ' "$1" "${i#-I}"; done
  sh "$TEETH_ROOT/proofs/plugin.sh"
}
# teeth_copy DIR FILE OLD NEW: a scratch copy of include/, src/, specs/ and
# proofs/ in DIR, with OLD replaced by NEW in DIR/FILE (OLD must occur
# exactly once).
teeth_copy() {
  mkdir -p "$1"
  cp -r include src specs proofs "$1"/
  python3 - "$1/$2" "$3" "$4" <<'PY'
import sys
p, old, new = sys.argv[1:4]
t = open(p).read()
if t.count(old) != 1:
    sys.exit('teeth: the text to replace is not found exactly once in ' + p)
open(p, 'w').write(t.replace(old, new))
PY
}
