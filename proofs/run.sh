#!/bin/sh
# Run the Frama-C/WP proofs of certbox and write proofs/report.md.
#   sh proofs/run.sh          prove, write the report
#   sh proofs/run.sh --check  same, and exit 1 unless every goal is proved
#                             and the smoke tests find no inconsistent contract
# Model: WP's default (Typed memory, IEEE float), -wp-rte; provers: see
# proofs/README.md.  Nothing is cached: the provers prove every goal each run.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
check=0; [ "${1:-}" = --check ] && check=1
out=build/proof
mkdir -p $out
conf=$(sh proofs/setup.sh $out)
export WHY3CONFIG="$conf"
SRC="proofs/all.c"
# one prover job per core (at least 2)
PAR=$(nproc 2>/dev/null || echo 2); [ "$PAR" -ge 2 ] 2>/dev/null || PAR=2
export CBX_PAR="${CBX_WP_PAR:-$PAR}"
FC="frama-c -cpp-extra-args=-I$root/src -cpp-extra-args=-I$root/specs"
WP="-wp -wp-rte -wp-prover cvc4r,z3r -wp-timeout ${CBX_WP_TIMEOUT:-120} -wp-par ${CBX_WP_PAR:-$PAR} -wp-cache none"
# Pass S: the smoke tests alone (every regular category deselected), one
# prover: a smoke goal "passes" when the prover can NOT prove false from the
# context, so each one costs the full smoke timeout per prover tried.
SMOKE="-wp -wp-rte -wp-smoke-tests -wp-smoke-timeout ${CBX_SMOKE_TIMEOUT:-1} -wp-prover cvc4r -wp-par ${CBX_WP_PAR:-$PAR} -wp-cache none"
NOGOALS="-wp-prop=-@lemma,-@requires,-@assigns,-@ensures,-@exits,-@assert,-@invariant,-@variant,-@breaks,-@continues,-@returns,-@complete_behaviors,-@disjoint_behaviors,-@terminates,-@decreases,-@check"
# Pass A: rounding primitives and kernels, with -wp-split (their assertions
# are two-sided bounds; one goal per side proves fastest).
# Pass B: everything else (lemmas, domain checks, public functions) without
# -wp-split (splitting the behaviors' postconditions multiplies goals).
KERNELS=cbx_cls,cbx_mul_rn,cbx_add_rn,cbx_sub_rn,cbx_abs,cbx_min2,cbx_max2,cbx_dom_pair,cbx_widening,term_lo,term_hi,term_mag,axis_lo,axis_hi,cbox_axis,b2c,cbx_c2b,ball_radius,abs_prod_up,row_radius,ball_axis_bounds,ell_axis_bounds,vertex_lo,vertex_hi,pos_below,neg_below,pos_above,neg_above,point_lo,point_hi,ext_lo,ext_hi,cbx_no_point,eft_sum,pass8,decide,certify,approx,neighbour,eft_ok,tighten_core,exact_terms,tighten_lo,tighten_hi,tight_lo_sound,tight_hi_sound,tight_axis,cbx_add_dn,cbx_add_up,in_rng,end_pair,sign_step,span_mul,span_add,span_id,col0_sound,col1_sound,col2_sound,sparse_axis,lerp_pt,mot_corners,mot_points_lo,mot_points_hi
# Pass L: the lemmas of specs/cbx_spec.h (proofs/lemmas.c has no function).
echo "proof: pass L, lemmas"
start=$(date +%s)
# shellcheck disable=SC2086
$FC $WP proofs/lemmas.c > $out/wp-l.log 2>&1 || true
echo "proof: pass A, primitives and kernels"
# shellcheck disable=SC2086
$FC $WP -wp-split -wp-fct $KERNELS $SRC > $out/wp-a.log 2>&1 || true
echo "proof: pass B, lemmas and public functions"
# shellcheck disable=SC2086
$FC $WP -wp-skip-fct $KERNELS $SRC > $out/wp-b.log 2>&1 || true
mid=$(date +%s)
echo "proof: pass S, smoke tests"
# shellcheck disable=SC2086
$FC $SMOKE $NOGOALS $SRC > $out/wp-s.log 2>&1 || true
end=$(date +%s)
cat $out/wp-l.log $out/wp-a.log $out/wp-b.log $out/wp-s.log > $out/wp.log
python3 proofs/report.py $out/wp.log $out/wp.log $((mid - start)) $((end - mid)) > proofs/report.md.new
mv proofs/report.md.new proofs/report.md
tail -n 6 proofs/report.md
if [ $check = 1 ]; then
  grep -q '^RESULT: PROVED' proofs/report.md || { echo "proof: FAILED (see proofs/report.md, $out/wp.log)"; exit 1; }
fi
