#!/bin/sh
# One proof job of proofs/run.sh: a Frama-C/WP run on one translation unit
# and one selection of goals.  Usage: sh proofs/job.sh NAME (run from the
# checkout's root, with WHY3CONFIG set; proofs/run.sh does both).
#   L64, L32  the lemmas of each family (proofs/lemmas.c, proofs/lemmas_f.c)
#   LP64      the lemmas of specs/cbx_psph.h, cbx_pnear.h, cbx_pball.h,
#             cbx_pwide.h, cbx_pell.h
#             (proofs/lemmas_p.c; the goals: those files' lemmas, by name)
#   A64, A32  the functions marked /* proof: -wp-split */ in their source
#             (their two-sided postconditions over several behaviors time
#             out whole, and one goal per side proves fastest)
#   K64, K32  the rounding primitives and kernels (src/core/*.h,
#             src/algo/*.h), without -wp-split (measured: half the goals
#             and half the prover calls of the split run)
#   B64a      binary64-only code (src/f64/*.c: tight mode, classes, motion,
#             chains), with the motion lemmas of specs/cbx_class.h
#             (CBX_MOTION_LEMMAS) and the chain lemmas of specs/cbx_chain.h
#             (CBX_CHAIN_LEMMAS)
#   B64b, B32 the rest: the algorithms of src/algo/*.c (public functions,
#             domain checks), without -wp-split (splitting the behaviors'
#             postconditions multiplies goals)
#   I64, SI64 the interval-matrix functions (proofs/imat.c, with the
#             lemmas of specs/cbx_imat_logic.h) and their smoke tests
#   T64, ST64 the proven part of the rotation motion (proofs/trs.c): the
#             interval arithmetic of src/f64/cbx_iv.h, the rotations of
#             src/f64/cbx_quat.h and the cells of src/f64/cbx_cell.h, with
#             the lemmas of specs/cbx_iv_logic.h and cbx_imat_logic.h; its
#             smoke tests
#   PSR64     the functions of PS64's files marked /* proof: race */
#             (proofs/fcts.py: psphrace), both provers raced in pass 1
#   PS64, SPS64 a ball under a projective map (proofs/psph.c:
#             src/f64/cbx_psph.c, on the interval arithmetic of T64, with
#             the lemmas of specs/cbx_psph.h, cbx_ball.h, cbx_iv_logic.h);
#             its smoke tests; with the enclosures of src/f64/cbx_paff.h
#   PN64, SPN64 a box under a projective map clipped at a near plane
#             (proofs/pnear.c: src/f64/cbx_pnear.c, on T64 and the
#             enclosures of PS64, with the lemmas of specs/cbx_pnear.h);
#             its smoke tests
#   PB64, SPB64 a ball under a projective map clipped at a near plane
#             (proofs/pball.c: src/f64/cbx_pball.c, on T64 and the
#             enclosures of PS64, with the lemmas of specs/cbx_pball.h);
#             its smoke tests
#   PE64, SPE64 an ellipsoid under a projective map (proofs/pell.c:
#             src/f64/cbx_pell.c, on the enclosures of PS64, with the
#             lemmas of specs/cbx_pell.h, proven in LP64)
#   PW, SPW   the binary32 twins of those three (proofs/pwide.c:
#             src/f32/cbx_pwide.c, on the contracts of PS64, PN64, PB64,
#             with the lemmas of specs/cbx_pwide.h, proven in LP64): both
#             families' logic in one unit, so their provers are the
#             entries cvc4rw, z3rw (proofs/setup.sh: both formats' IEEE
#             axioms); its smoke tests
#   P64, P32  the projective bound (proofs/proj.c, proj_f.c, with the
#             lemmas of specs/cbx_proj_logic.h and cbx_proj.h), without
#             -wp-split; PA64, PA32 its functions marked for -wp-split;
#             SP64, SP32 its smoke tests
#   BS64, BS32  the sphere and ellipsoid bounds (src/algo/cbx_sphere.c) with
#             the lemmas of specs/cbx_ball.h (CBX_BALL_LEMMAS), which no other
#             job of proofs/all.c carries; BSA64, BSA32 that file's functions
#             marked for -wp-split
#   S64, S32  the smoke tests alone (-wp-smoke-tests, every regular goal
#             deselected): a smoke goal "passes" when CVC4 can NOT derive
#             false from its context within CBX_SMOKE_STEPS resource units
#             (a deterministic budget, independent of the machine's load);
#             see SMOKE below for the categories
# Writes build/proof/wp-NAME.log (WP's console output, both passes),
# wp-NAME.K.json (WP's report of run K: -wp-report-json), wp-NAME.runs
# (those reports in run order) and wp-NAME.time (seconds; both passes).
set -eu
name=$1
root=$(pwd)
out=build/proof
FC="frama-c $(sh proofs/plugin.sh) $(for d in $(sh scripts/incs.sh) -Ispecs; do printf -- '-cpp-extra-args=-I%s/%s ' "$root" "${d#-I}"; done)"
PAR=${CBX_WP_PAR:-2}
# OCaml's major collector with space_overhead 400 instead of 80: Frama-C
# then spends less time collecting and holds more memory (measured
# 2026-11-30, job K64's Frama-C side alone, provers answered at once: 34 s
# of CPU instead of 41 s; 1.8 GB at most instead of 1.2 GB)
OCAMLRUNPARAM=${OCAMLRUNPARAM:-o=400}
export OCAMLRUNPARAM
# each family's jobs use its own prover entries (proofs/setup.sh: the same
# provers, with the axioms that family never needs left out)
case $name in PW|SPW) fam=w ;; *64*) fam=64 ;; *) fam=32 ;; esac
WP="-wp -wp-rte -wp-par $PAR"   # + the provers, limits and cache of each pass (below)
# Smoke tests.  A smoke goal that the prover proves (false derived) means
# goals proved vacuously.  A vacuous goal matters only at a point that some
# run reaches, and only an assumed fact that no run has to satisfy can make
# the context there inconsistent: a precondition nobody proves (an entry
# point's), a trusted callee's postcondition (no proved body: cbx_pinf,
# cbx_sqrt_rn, cbx_two_sum, ...), an inconsistent axiomatic definition.
# Everything else WP assumes is proved to hold in every run that gets
# there: an internal function's precondition (proved at each call: if no
# state satisfied it, no call could prove it), a proved callee's
# postcondition (it terminates: no recursion, every loop has a proved
# variant), an assert, a loop invariant (established and preserved).  So
# the smoke jobs run every category but dead calls (requires, dead code,
# assumes, loops) in the entry points (functions without `static`, or that
# the unit never calls) and in the functions that call a trusted contract
# (proofs/fcts.py --dead-code: 43 of the 166 functions of proofs/all.c),
# and none in the other, internal functions (WP makes no smoke test at all
# without its dead-code category, which carries the requires test).  An
# internal function's precondition is checked at its calls instead (the
# regular jobs prove it there); code that WP finds dead in it is code that
# no run reaches (which the evidence pack's coverage would show: every
# branch of src/ taken by the suites, or justified); a behavior of it that
# no input takes leaves a promise that no caller can use, not a vacuous
# proof (its callers' goals use the behaviors that hold, and complete
# behaviors are proved).  make smoke-teeth
# checks both routes: inconsistent preconditions of internal functions are
# left unproved at their calls, and inconsistent entry preconditions,
# trusted postconditions, loop invariants and dead branches are caught by
# the smoke tests.  Measured 2026-11-27: 76% of the smoke goals had been
# dead-code tests in internal functions, and the smoke jobs a quarter of
# the proof time (S64 alone: 844 goals before, 346 after, in 118 s).
# The dead-call tests are off: a dead-call test asks whether the code after
# a call is reachable; after a proved callee it is whenever the caller's
# context is consistent, and after a trusted callee the dead-code tests ask
# it (make smoke-teeth injects an inconsistent trusted postcondition and
# sees it caught).  Budget: CBX_SMOKE_STEPS CVC4 resource units (40,000:
# 4/3 of the smallest that catches every smoke case of scripts/smoke_teeth.sh,
# which make check runs at this same budget, so a case that comes to need
# more fails there.  2026-12-01: the hardest case, a precondition
# inconsistent only through lemma cls_509, caught at 30k and missed at 25k
# and 20k; the other smoke cases are caught at 5k.  The budget was 60k
# until then (2026-11-27, twice the smallest; 80k before the drivers left
# out the integer theories): the smoke jobs are an eighth of the proof
# time, most of it CVC4 spending its whole budget on goals that pass).
SMOKE="-wp -wp-rte -wp-smoke-tests -wp-no-smoke-dead-call -wp-prover cvc4r$fam -wp-steps ${CBX_SMOKE_STEPS:-40000} -wp-smoke-timeout ${CBX_SMOKE_TIMEOUT:-30} -wp-par $PAR -wp-cache none"
# the sphere's lemmas (specs/cbx_ball.h): only in the jobs of cbx_sphere.c.
# The smoke jobs (S64, S32) do without them: a lemma is a theorem (jobs L),
# so it cannot make a consistent context inconsistent.
BALL="-cpp-extra-args=-DCBX_BALL_LEMMAS"
NOGOALS="-wp-prop=-@lemma,-@requires,-@assigns,-@ensures,-@exits,-@assert,-@invariant,-@variant,-@breaks,-@continues,-@returns,-@complete_behaviors,-@disjoint_behaviors,-@terminates,-@decreases,-@check"
# The functions of each job come from the tree (proofs/fcts.py): the
# primitives and kernels (src/core/*.h, src/algo/*.h: jobs K), the
# functions marked /* proof: -wp-split */ in their source (jobs A: without
# -wp-split a goal of each timed out), binary64-only code (src/f64/*.c:
# B64a), the interval-matrix unit (I64), and the rest, the algorithms of
# src/algo/*.c (B64b, B32).  A new function joins its layer's job by
# where it is written; nothing here lists names.
fcts() { python3 proofs/fcts.py "$@"; }
# TU: the translation unit; OPTS: its options; SEL: the goals it proves
case $name in
  I64) TU=proofs/imat.c; OPTS=$WP; SEL="-wp-fct $(fcts $TU imat)" ;;
  SI64) TU=proofs/imat.c; OPTS="$SMOKE $NOGOALS"; SG=imat ;;
  T64) TU=proofs/trs.c; OPTS=$WP; SEL="-wp-fct $(fcts $TU trs)" ;;
  PS64) TU=proofs/psph.c; OPTS=$WP; SEL="-wp-fct $(fcts $TU psph)" ;;
  PSR64) TU=proofs/psph.c; OPTS=$WP; SEL="-wp-fct $(fcts $TU psphrace)" ;;
  SPS64) TU=proofs/psph.c; OPTS="$SMOKE $NOGOALS"; SG=psph,psphrace ;;
  PN64) TU=proofs/pnear.c; OPTS=$WP; SEL="-wp-fct $(fcts $TU pnear)" ;;
  SPN64) TU=proofs/pnear.c; OPTS="$SMOKE $NOGOALS"; SG=pnear ;;
  PB64) TU=proofs/pball.c; OPTS=$WP; SEL="-wp-fct $(fcts $TU pball)" ;;
  SPB64) TU=proofs/pball.c; OPTS="$SMOKE $NOGOALS"; SG=pball ;;
  PE64) TU=proofs/pell.c; OPTS=$WP; SEL="-wp-fct $(fcts $TU pell)" ;;
  SPE64) TU=proofs/pell.c; OPTS="$SMOKE $NOGOALS"; SG=pell ;;
  PW) TU=proofs/pwide.c; OPTS=$WP; SEL="-wp-fct $(fcts $TU pwide)" ;;
  SPW) TU=proofs/pwide.c; OPTS="$SMOKE $NOGOALS"; SG=pwide ;;
  ST64) TU=proofs/trs.c; OPTS="$SMOKE $NOGOALS"; SG=trs ;;
  P64|P32) TU=proofs/proj$(test $fam = 64 || echo _f).c; OPTS=$WP; SEL="-wp-fct $(fcts $TU proj)" ;;
  PA64|PA32) TU=proofs/proj$(test $fam = 64 || echo _f).c; OPTS="$WP -wp-split"; SEL="-wp-fct $(fcts $TU projsplit)" ;;
  SP64|SP32) TU=proofs/proj$(test $fam = 64 || echo _f).c; OPTS="$SMOKE $NOGOALS"; SG=proj,projsplit ;;
  L64) TU=proofs/lemmas.c; OPTS=$WP; SEL="" ;;
  LP64) TU=proofs/lemmas_p.c; OPTS=$WP
    LFILES="specs/cbx_psph.h specs/cbx_pnear.h specs/cbx_pball.h specs/cbx_pwide.h specs/cbx_pell.h"
    # shellcheck disable=SC2086
    LIST=$(grep -ho 'lemma [a-z0-9_]*:' $LFILES | sed 's/lemma //; s/://' | paste -sd, -)
    SEL="-wp-prop $LIST" ;;
  L32) TU=proofs/lemmas_f.c; OPTS=$WP; SEL="" ;;
  BS64|BS32) TU=proofs/all$(test $fam = 64 || echo _f).c; OPTS="$WP $BALL"; SEL="-wp-fct $(fcts $TU ball)" ;;
  BSA64|BSA32) TU=proofs/all$(test $fam = 64 || echo _f).c; OPTS="$WP -wp-split $BALL"; SEL="-wp-fct $(fcts $TU ballsplit)" ;;
  A64) TU=proofs/all.c; OPTS="$WP -wp-split"; SEL="-wp-fct $(fcts $TU split)" ;;
  A32) TU=proofs/all_f.c; OPTS="$WP -wp-split"; SEL="-wp-fct $(fcts $TU split)" ;;
  K64) TU=proofs/all.c; OPTS=$WP; SEL="-wp-fct $(fcts $TU kernels)" ;;
  K32) TU=proofs/all_f.c; OPTS=$WP; SEL="-wp-fct $(fcts $TU kernels)" ;;
  B64a) TU=proofs/all.c; OPTS="$WP -cpp-extra-args=-DCBX_MOTION_LEMMAS -cpp-extra-args=-DCBX_CHAIN_LEMMAS"; SEL="-wp-fct $(fcts $TU f64)" ;;
  B64b) TU=proofs/all.c; OPTS=$WP; SEL="-wp-skip-fct $(fcts $TU kernels),$(fcts $TU split),$(fcts $TU f64),$(fcts $TU ball),$(fcts $TU ballsplit)" ;;
  B32) TU=proofs/all_f.c; OPTS=$WP; SEL="-wp-skip-fct $(fcts $TU kernels),$(fcts $TU split),$(fcts $TU ball),$(fcts $TU ballsplit)" ;;
  S64) TU=proofs/all.c; OPTS="$SMOKE $NOGOALS"; SG=all ;;
  S32) TU=proofs/all_f.c; OPTS="$SMOKE $NOGOALS"; SG=all ;;
  *) echo "job.sh: unknown job $name" >&2; exit 2 ;;
esac
start=$(date +%s)
# Each Frama-C run of the job writes WP's own report of its goals
# (-wp-report-json: per function and property, the goals, the valid ones
# and the prover of each); wp-NAME.runs lists them in run order and
# proofs/report.py reads nothing else for the counts (a later run's entry
# for a property replaces an earlier one's).  A run that did not finish
# leaves no report: the job is then unfinished.
rm -f $out/wp-$name.*.json $out/wp-$name.runs
json() { echo "wp-$name.$1.json" >> $out/wp-$name.runs; echo "-wp-report-json $out/wp-$name.$1.json"; }
case $name in
  S*)
    # the functions of group SG where an unproved fact enters (SMOKE above),
    # every hypothesis in each task (proofs/prune.ml: certbox_relevant
    # leaves a task whole when CBX_WP_WHOLE_TASKS is set)
    # shellcheck disable=SC2086
    CBX_WP_WHOLE_TASKS=1 $FC $TU $OPTS -wp-fct $(fcts $TU $SG --dead-code) $(json 1) > $out/wp-$name.log 2>&1 || true ;;
  *)
    # Two passes (proofs/README.md says why these limits): 1, CVC4 alone,
    # CBX_WP_TIMEOUT1 (120 s), enforced by Why3; 2, both provers raced with
    # CBX_WP_TIMEOUT, on the functions where pass 1 left a goal unproved
    # (every goal of those functions regenerated and proved again).  The
    # job's log is pass 1's followed by pass 2's; proofs/report.py takes
    # each goal's last result.
    # CBX_WP_KEEP_CACHE (make proof, during development): a cache kept
    # between runs, so only changed goals go to the provers; unset (make
    # proof-check, CI): no cache at all (proofs/README.md: its cost).
    if [ -n "${CBX_WP_KEEP_CACHE:-}" ]; then
      mkdir -p "$CBX_WP_KEEP_CACHE/$name"
      CACHE="-wp-cache update -wp-cache-dir $CBX_WP_KEEP_CACHE/$name"
    else
      CACHE="-wp-cache none"
    fi
    # PSR64 races both provers from pass 1 (its functions are marked
    # /* proof: race */).  The lemma jobs give each lemma to one prover in
    # pass 1: Z3 the lemmas marked // proof: z3 in specs/ (proofs/fcts.py
    # --lemmas z3: lagrange, irow_in_terms, ... which Z3 proves in under
    # 0.1 s where CVC4 times out), CVC4 the others, in two Frama-C runs
    # whose logs follow each other.  Until 2026-12-01 both provers raced on
    # every lemma, so each lemma cost both provers' time until the first
    # answer: L64 alone took 117 s of CPU raced, 57 s split (68.6 s and
    # 32.5 s of wall time; 141 of 141 lemmas both ways).  A lemma left
    # unproved goes to pass 2 (every lemma of the job, raced), as before.
    P1=cvc4r$fam
    case $name in PSR64) P1=cvc4r$fam,z3r$fam ;; esac
    case $name in
      L*)
        # shellcheck disable=SC2086
        z=$(fcts $TU --lemmas z3 ${LFILES:-})
        if [ -z "${LIST:-}" ]; then
          c=${z:+-wp-prop=-$(echo "$z" | sed 's/,/,-/g')}
        else
          c=$(echo "$LIST" | tr , '\n' | awk -v z=",$z," 'index(z, "," $0 ",") == 0' | paste -sd, -)
          c=${c:+-wp-prop=$c}
          z=$(echo "$z" | tr , '\n' | awk -v l=",$LIST," 'index(l, "," $0 ",") > 0' | paste -sd, -)
        fi
        # shellcheck disable=SC2086
        $FC $TU $OPTS $c -wp-prover cvc4r$fam -wp-timeout ${CBX_WP_TIMEOUT1:-120} $CACHE \
          $(json 1) > $out/wp-$name.log 2>&1 || true
        if [ -n "$z" ]; then
          # shellcheck disable=SC2086
          $FC $TU $OPTS -wp-prop=$z -wp-prover z3r$fam -wp-timeout ${CBX_WP_TIMEOUT1:-120} $CACHE \
            $(json 2) >> $out/wp-$name.log 2>&1 || true
        fi ;;
      *)
        # shellcheck disable=SC2086
        $FC $TU $OPTS $SEL -wp-prover $P1 -wp-timeout ${CBX_WP_TIMEOUT1:-120} $CACHE \
          $(json 1) > $out/wp-$name.log 2>&1 || true ;;
    esac
    again=$(python3 proofs/report.py --unproved-functions $out $name)
    if [ -n "$again" ]; then
      echo "proof: job $name: pass 2 on $again"
      [ "$again" = ALL ] || SEL="-wp-fct $again"
      # shellcheck disable=SC2086
      $FC $TU $OPTS $SEL -wp-prover cvc4r$fam,z3r$fam -wp-timeout ${CBX_WP_TIMEOUT:-120} \
        $CACHE $(json 3) >> $out/wp-$name.log 2>&1 || true
    fi ;;
esac
end=$(date +%s)
echo $((end - start)) > $out/wp-$name.time
echo "proof: job $name done in $((end - start)) s ($(python3 proofs/report.py --goals $out $name) goals)"
