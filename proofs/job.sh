#!/bin/sh
# One proof job of proofs/run.sh: a Frama-C/WP run on one translation unit
# and one selection of goals.  Usage: sh proofs/job.sh NAME (run from the
# checkout's root, with WHY3CONFIG set; proofs/run.sh does both).
#   L64, L32  the lemmas of each family (proofs/lemmas.c, proofs/lemmas_f.c)
#   A64, A32  the kernels that need -wp-split (SPLIT64, SPLIT32: their
#             two-sided postconditions over several behaviors time out
#             whole, and one goal per side proves fastest)
#   K64, K32  the other rounding primitives and kernels, without -wp-split
#             (measured: half the goals and half the prover calls of the
#             split run, every goal within pass 1)
#   B64, B32  everything else (domain checks, public functions), without
#             -wp-split (splitting the behaviors' postconditions multiplies
#             goals); B64 is cut in two (B64a, B64b) to balance the jobs
#   I64, SI64 the interval-matrix functions (proofs/imat.c, with the
#             lemmas of specs/cbx_imat_logic.h) and their smoke tests
#   S64, S32  the smoke tests alone (-wp-smoke-tests, every regular goal
#             deselected): a smoke goal "passes" when CVC4 can NOT derive
#             false from its context within CBX_SMOKE_STEPS resource units
#             (a deterministic budget, independent of the machine's load);
#             see SMOKE below for the categories
# Writes build/proof/wp-NAME.log (the final pass) and build/proof/wp-NAME.time
# (seconds; both passes).
set -eu
name=$1
root=$(pwd)
out=build/proof
FC="frama-c $(for d in $(sh scripts/incs.sh) -Ispecs; do printf -- '-cpp-extra-args=-I%s/%s ' "$root" "${d#-I}"; done)"
PAR=${CBX_WP_PAR:-2}
# each family's jobs use its own prover entries (proofs/setup.sh: the same
# provers, with the axioms that family never needs left out)
case $name in *64*) fam=64 ;; *) fam=32 ;; esac
WP="-wp -wp-rte -wp-par $PAR"   # + the provers, limits and cache of each pass (below)
# Smoke tests: every category but dead calls.  A dead-call test asks whether
# the code after a call is reachable; for a callee whose contract is proven
# and that terminates (every function here: no recursion, every loop has a
# proven variant) it always is once the caller's context is consistent,
# which the caller's own requires and dead-code tests check.  The callees
# without a proven body (the trusted contracts: cbx_pinf, cbx_sqrt_rn,
# two_sum, ...) are covered by the dead-code test after their calls
# (make smoke-teeth injects an inconsistent trusted postcondition and sees
# it caught).  Budget: CBX_SMOKE_STEPS CVC4 resource units (80,000: the
# smallest budget of 40k, 60k, 80k that catches every case of
# scripts/smoke_teeth.sh with margin).
SMOKE="-wp -wp-rte -wp-smoke-tests ${CBX_SMOKE_OPTS:--wp-no-smoke-dead-call} -wp-prover cvc4r$fam -wp-steps ${CBX_SMOKE_STEPS:-80000} -wp-smoke-timeout ${CBX_SMOKE_TIMEOUT:-30} -wp-par $PAR -wp-cache none"
NOGOALS="-wp-prop=-@lemma,-@requires,-@assigns,-@ensures,-@exits,-@assert,-@invariant,-@variant,-@breaks,-@continues,-@returns,-@complete_behaviors,-@disjoint_behaviors,-@terminates,-@decreases,-@check"
# Functions proved with -wp-split, per family (-wp-fct rejects a name
# that the translation unit does not define).
KERNELS32=cbx_cls,cbx_mul_rn,cbx_add_rn,cbx_sub_rn,cbx_abs,cbx_min2,cbx_max2,cbx_dom_pair,cbx_widening,cbx_neg,cbx_column,cbx_sum3,cbx_end_lo,cbx_end_hi,cbx_axis,cbx_in2,cbx_ord3,cbx_fast_row,cbx_full_axis,cbx_fast_axis,cbx_fast_box,cbox_axis,b2c,cbx_c2b,ball_radius,abs_prod_up,nrm3_up,row_radius,ball_axis_bounds,ell_axis_bounds,vertex_lo,vertex_hi,pos_below,neg_below,pos_above,neg_above,point_lo,point_hi,ext_lo,ext_hi,cbx_no_point,cbx_transform_box_prepf,cbx_transform_boxf,cbx_preparef
KERNELS64=cbx_cls,cbx_mul_rn,cbx_add_rn,cbx_sub_rn,cbx_abs,cbx_min2,cbx_max2,cbx_dom_pair,cbx_widening,cbx_neg,cbx_column,cbx_sum3,cbx_end_lo,cbx_end_hi,cbx_axis,cbx_in2,cbx_ord3,cbx_fast_row,cbx_full_axis,cbx_fast_axis,cbx_fast_box,cbox_axis,b2c,cbx_c2b,ball_radius,abs_prod_up,nrm3_up,row_radius,ball_axis_bounds,ell_axis_bounds,vertex_lo,vertex_hi,pos_below,neg_below,pos_above,neg_above,point_lo,point_hi,ext_lo,ext_hi,cbx_no_point,cbx_transform_box_prep,cbx_transform_box,cbx_prepare,eft_sum,pass8,decide,certify,approx,neighbour,eft_ok,tighten_core,exact_terms,tighten_lo,tighten_hi,tight_lo_sound,tight_hi_sound,tight_axis,cbx_add_dn,cbx_add_up,in_rng,end_pair,span_add,span_id,col0_sound,col1_sound,col2_sound,lerp_pt,mot_corners,mot_points_lo,mot_points_hi
# The kernels that need -wp-split (without it, a goal of each timed out at
# 10 s on 2026-11-24); the other kernels are proved whole (jobs K64, K32).
SPLIT64=cbx_transform_box,cbx_transform_box_prep,vertex_lo,vertex_hi,cbx_fast_row,cbox_axis,ball_radius,row_radius,eft_ok
SPLIT32=cbx_transform_boxf,cbx_transform_box_prepf,vertex_lo,vertex_hi,cbx_fast_row,cbox_axis,ball_radius,row_radius
# a comma list minus another
minus() { echo "$1" | tr , '\n' | grep -v -x -F "$(echo "$2" | tr , '\n')" | paste -s -d, -; }
# The binary64 public functions and their helpers that are not kernels,
# in two halves of similar proof time (B64a: tight mode, classes, motion).
B64A=cbx_transform_box_tight,cbx_classify,cbx_transform_box_as,kern_identity,kern_translate,fast_identity,fast_translate,ends_ok,tr_ok,is_val,translate_holds,axis_full,full_row,cbx_motion_box,mot_union,mot_axis_union,one_box,one_box_as,step,put_box,severity,batch,cbx_transform_boxes,cbx_transform_boxes_prep,class_checked
# The interval-matrix functions (proofs/imat.c): the unit also holds the
# kernels it includes, proved in their own jobs.
IMAT64=cbx_icolumn,cbx_isum3,cbx_irow,iv_in,icoord_of,imat_row_bad,imat_any_bad,cbx_transform_box_imat,col_apply,whole_imat,cbx_imat_compose
# TU: the translation unit; OPTS: its options; SEL: the goals it proves
case $name in
  I64) TU=proofs/imat.c; OPTS=$WP; SEL="-wp-fct $IMAT64" ;;
  SI64) TU=proofs/imat.c; OPTS="$SMOKE $NOGOALS"; SEL="-wp-fct $IMAT64" ;;
  L64) TU=proofs/lemmas.c; OPTS=$WP; SEL="" ;;
  L32) TU=proofs/lemmas_f.c; OPTS=$WP; SEL="" ;;
  A64) TU=proofs/all.c; OPTS="$WP -wp-split"; SEL="-wp-fct $SPLIT64" ;;
  A32) TU=proofs/all_f.c; OPTS="$WP -wp-split"; SEL="-wp-fct $SPLIT32" ;;
  K64) TU=proofs/all.c; OPTS=$WP; SEL="-wp-fct $(minus $KERNELS64 $SPLIT64)" ;;
  K32) TU=proofs/all_f.c; OPTS=$WP; SEL="-wp-fct $(minus $KERNELS32 $SPLIT32)" ;;
  B64a) TU=proofs/all.c; OPTS=$WP; SEL="-wp-fct $B64A" ;;
  B64b) TU=proofs/all.c; OPTS=$WP; SEL="-wp-skip-fct $KERNELS64,$B64A" ;;
  B32) TU=proofs/all_f.c; OPTS=$WP; SEL="-wp-skip-fct $KERNELS32" ;;
  S64) TU=proofs/all.c; OPTS="$SMOKE $NOGOALS"; SEL="" ;;
  S32) TU=proofs/all_f.c; OPTS="$SMOKE $NOGOALS"; SEL="" ;;
  *) echo "job.sh: unknown job $name" >&2; exit 2 ;;
esac
start=$(date +%s)
case $name in
  S*)
    # shellcheck disable=SC2086
    $FC $TU $OPTS $SEL > $out/wp-$name.log 2>&1 || true ;;
  *)
    # Two passes.  1: CVC4 alone, CBX_WP_TIMEOUT1 (20 s): it proves most
    # goals in well under a second and nearly all the rest within 10 s (the
    # big behaviors' postconditions take 2-9 s; at 2 s they all fell to pass
    # 2, which regenerated every goal of their functions; at 10 s a few
    # goals of cbx_sphere_box fell to pass 2 on a loaded machine).  2: both provers
    # raced with the full timeout, on
    # the functions where pass 1 left a goal unproved (every goal of those
    # functions is regenerated; the ones pass 1 proved are read back from
    # this job's cache, which starts empty and serves nothing else, so every
    # result still comes from a prover of this run).  The job's log is pass
    # 1's followed by pass 2's; proofs/report.py takes each goal's last
    # result.  Racing both provers on every goal cost twice the CPU, and a
    # second pass over every goal regenerated every task.
    # CBX_WP_KEEP_CACHE (make proof, during development): a cache kept
    # between runs, so only changed goals go to the provers; unset (make
    # proof-check, CI): a cache of this job alone, empty at the start
    if [ -n "${CBX_WP_KEEP_CACHE:-}" ]; then
      cache=$CBX_WP_KEEP_CACHE/$name; mkdir -p "$cache"
    else
      cache=$out/cache-$name; rm -rf "$cache"; mkdir -p "$cache"
    fi
    # The lemma jobs race both provers from pass 1: Z3 proves lagrange and
    # irow_in_terms in under 0.1 s where CVC4 times out, and a lemma job's
    # pass 2 regenerates every lemma (measured at 492e631: L64 54 s, L32
    # 40 s, each with that 20 s timeout and a second pass).
    P1=cvc4r$fam
    case $name in L*) P1=cvc4r$fam,z3r$fam ;; esac
    # shellcheck disable=SC2086
    $FC $TU $OPTS $SEL -wp-prover $P1 -wp-timeout ${CBX_WP_TIMEOUT1:-20} -wp-cache update \
      -wp-cache-dir "$cache" > $out/wp-$name.log 2>&1 || true
    again=$(python3 proofs/report.py --unproved-functions $out/wp-$name.log)
    if [ -n "$again" ]; then
      echo "proof: job $name: pass 2 on $again"
      [ "$again" = ALL ] || SEL="-wp-fct $again"
      # shellcheck disable=SC2086
      $FC $TU $OPTS $SEL -wp-prover cvc4r$fam,z3r$fam -wp-timeout ${CBX_WP_TIMEOUT:-120} \
        -wp-cache update -wp-cache-dir "$cache" >> $out/wp-$name.log 2>&1 || true
    fi
    [ -n "${CBX_WP_KEEP_CACHE:-}" ] || rm -rf "$cache" ;;
esac
end=$(date +%s)
echo $((end - start)) > $out/wp-$name.time
echo "proof: job $name done in $((end - start)) s ($(grep -c '\] Goal\|Smoke-test' $out/wp-$name.log) goals)"
