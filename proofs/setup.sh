#!/bin/sh
# Generate the project-local Why3 configuration (build/proof/why3.conf) with
# prover entries that keep floats out of the SMT floating-point theory, one
# pair per floating-point family:
#   cvc4r64, z3r64  CVC4 1.8 / Z3 4.8 for the binary64 jobs
#   cvc4r32, z3r32  the same for the binary32 jobs
# (and cvc4r, z3r: the drivers without the per-family pruning below).
# Each driver is Why3's own minus the floating-point theory mapping
# (proofs/cvc4_real.drv.in, proofs/z3_real.drv.in), plus, per family, a list
# of axioms the provers never need to see: the other format's IEEE axioms
# (the binary64 sources use no float, and the binary32 sources no double)
# and the axioms of the IEEE operations the proven code never performs
# (fma, division, square root: the code's sqrt and fma are trusted
# contracts, not IEEE operations of the model; rounding to integral values;
# the RNA rounding mode: WP's model rounds to nearest even).  Removing an
# axiom only removes a hypothesis: a goal proved without it is proved with it
# (proofs/README.md, trusted base).  The provers are about 40% faster on
# each goal without them.
# Driver paths in why3.conf are taken as written, so they are made absolute
# here, at build time.  See proofs/README.md for why this setup is trusted.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-$here/../build/proof}
mkdir -p "$out"
out=$(cd "$out" && pwd)
datadir=$(why3 --print-datadir)
# The IEEE axioms of the operations the proven code never performs.
UNUSED="div_finite div_finite_rev div_finite_rev_n div_special fma_finite fma_finite_rev
 fma_finite_rev_n fma_special fma_int sqrt_finite sqrt_finite_rev sqrt_special
 roundToIntegral_is_int roundToIntegral_is_finite truncate_int truncate_neg truncate_pos
 ceil_le ceil_lest ceil_to_real ceil_to_int floor_le floor_lest floor_to_real floor_to_int
 RNA_down RNA_up RNA_down_tie RNA_up_tie"
# Whole theories of lemmas that no goal needs: the facts about integer
# powers of two (bv.Pow2int: pow2_0 ... pow2_64; ieee_float imports it for
# its own definitions, and no specification or code here uses pow2), and
# about integer division and remainder (int.ComputerDivision and the
# division lemmas of WP's Qed theory: no proven function divides integers,
# no specification uses / or % on integers).  They were 103 of the 350
# hypotheses of every goal; without them CVC4 spends 24% fewer resource units
# on the same goals (48 goals of proofs/proj.c, 2026-11-27).
UNUSED_THEORIES="bv.Pow2int int.ComputerDivision int.Power"
UNUSED_QED="c_euclidian cmod_remainder cdiv_neutral cdiv_inv cdiv_closed_remainder"
prune() { # FAMILY: the removal block for that family (64 or 32)
  if [ "$1" = 64 ]; then keep=Float64; drop=Float32; else keep=Float32; drop=Float64; fi
  echo "(* certbox: axioms this family's goals never need (proofs/setup.sh) *)"
  for t in $UNUSED_THEORIES; do printf 'theory %s\n  remove allprops\nend\n' "$t"; done
  echo "theory frama_c_wp.qed.Qed"
  for p in $UNUSED_QED; do echo "  remove prop $p"; done
  echo "end"
  echo "theory ieee_float.$keep"
  for p in $UNUSED; do echo "  remove prop $p"; done
  echo "end"
  echo "theory ieee_float.$drop"
  echo "  remove allprops"
  echo "end"
}
for d in cvc4_real z3_real; do
  sed "s#@DATADIR@#$datadir#g" "$here/$d.drv.in" > "$out/$d.drv"
  for fam in 64 32; do
    { cat "$out/$d.drv"; prune $fam; } > "$out/${d}$fam.drv"
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
  entry CVC4 "$cvc4v" real cvc4r "$CVC4CMD" "$CVC4STEPS" "$out/cvc4_real.drv"
  entry Z3 "$z3v" real z3r "$Z3CMD" "$Z3STEPS" "$out/z3_real.drv"
  for fam in 64 32; do
    entry CVC4 "$cvc4v" real$fam cvc4r$fam "$CVC4CMD" "$CVC4STEPS" "$out/cvc4_real$fam.drv"
    entry Z3 "$z3v" real$fam z3r$fam "$Z3CMD" "$Z3STEPS" "$out/z3_real$fam.drv"
  done
} > "$out/why3.conf"
echo "$out/why3.conf"
