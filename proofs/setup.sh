#!/bin/sh
# Generate the project-local Why3 configuration (build/proof/why3.conf) with
# prover entries that keep floats out of the SMT floating-point theory, one
# pair per floating-point family:
#   cvc4r64, z3r64  CVC4 1.8 / Z3 4.8 for the binary64 jobs
#   cvc4r32, z3r32  the same for the binary32 jobs
#   cvc4rw, z3rw    the same for the unit that holds both families' logic
#                   (proofs/pwide.c)
# Each driver is Why3's own minus the floating-point theory mapping
# (proofs/cvc4_real.drv.in, proofs/z3_real.drv.in), with, first of its
# transformations, the family's certbox_prune64 / _prune32 / _prunew
# (proofs/prune.ml, loaded into Frama-C by proofs/plugin.sh): the axioms the
# provers never need to see (the other format's IEEE axioms, those of the
# IEEE operations the proven code never performs, integer powers of two and
# division) left out of every task.  Removing an axiom only removes a
# hypothesis: a goal proved without it is proved with it (proofs/README.md,
# trusted base).  The provers are about 40% faster on each goal without them.
# Second, certbox_strip (the same file): a memory-access goal (\valid,
# \separated, ...) without the declarations that name a float.  Last,
# certbox_relevant (certbox_relevant_wp in the drivers of the unit with both
# families' logic): the axioms the goal cannot use, left out (prune.ml says
# which).
# Driver paths in why3.conf are taken as written, so they are made absolute
# here, at build time.  See proofs/README.md for why this setup is trusted.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-$here/../build/proof}
mkdir -p "$out"
out=$(cd "$out" && pwd)
datadir=$(why3 --print-datadir)
for d in cvc4_real z3_real; do
  for fam in 64 32 w; do
    case $fam in w) rel=certbox_relevant_wp ;; *) rel=certbox_relevant ;; esac
    sed -e "s#@DATADIR@#$datadir#g" \
        -e "s#^transformation \"inline_trivial\"#transformation \"certbox_prune$fam\"\ntransformation \"certbox_strip\"\n&#" \
        -e "s#^transformation \"encoding_smt_if_poly\"#&\ntransformation \"$rel\"#" \
      "$here/$d.drv.in" > "$out/${d}$fam.drv"
    grep -q "^transformation \"certbox_prune$fam\"" "$out/${d}$fam.drv"
    grep -q "^transformation \"certbox_strip\"" "$out/${d}$fam.drv"
    grep -A1 "^transformation \"encoding_smt_if_poly\"" "$out/${d}$fam.drv" | grep -q "^transformation \"$rel\"$"
  done
done
cvc4=$(command -v cvc4)
z3=$(command -v z3)
cvc4v=$($cvc4 --version | sed -n 's/.*CVC4 version \([^ ]*\).*/\1/p' | head -1)
z3v=$($z3 -version | sed -n 's/Z3 version \([^ ]*\).*/\1/p')
entry() { # name version alternative shortcut command command_steps driver
  cat <<CONF

[prover]
name = "$1"
version = "$2"
alternative = "$3"
shortcut = "$4"
command = "$5"
command_steps = "$6"
driver = "$7"
in_place = false
interactive = false
CONF
}
# No --tlimit (Why3 itself stops a prover at the time limit), and glibc's
# malloc asked for transparent huge pages (nothing where the kernel gives
# none): why and what it saves, proofs/README.md (the provers' command
# lines).
HUGE="env GLIBC_TUNABLES=glibc.malloc.hugetlb=1"
CVC4CMD="$HUGE $cvc4 --stats --lang=smt2 %f"
CVC4STEPS="$HUGE $cvc4 --stats --rlimit=%S --lang=smt2 %f"
Z3CMD="$HUGE $z3 -smt2 -T:%t sat.random_seed=42 nlsat.randomize=false smt.random_seed=42 -st %f"
Z3STEPS="$HUGE $z3 -smt2 sat.random_seed=42 nlsat.randomize=false smt.random_seed=42 -st rlimit=%S %f"
{
  cat <<CONF
[main]
datadir = "$datadir"
libdir = "$(why3 --print-libdir)"
magic = 14
memlimit = 4000
running_provers_max = 2
timelimit = 10
CONF
  for fam in 64 32 w; do
    entry CVC4 "$cvc4v" real$fam cvc4r$fam "$CVC4CMD" "$CVC4STEPS" "$out/cvc4_real$fam.drv"
    entry Z3 "$z3v" real$fam z3r$fam "$Z3CMD" "$Z3STEPS" "$out/z3_real$fam.drv"
  done
} > "$out/why3.conf"
echo "$out/why3.conf"
