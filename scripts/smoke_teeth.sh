#!/bin/sh
# make smoke-teeth: do the smoke tests, at their step budget, catch an
# inconsistent contract?  Each case below copies the sources to a scratch
# directory, makes one contract inconsistent, runs the smoke tests of the
# affected function exactly as proofs/job.sh does (same options, same
# CBX_SMOKE_STEPS), and requires a smoke test that does not pass.
# Usage: sh scripts/smoke_teeth.sh  (from the checkout's root)
set -u
. scripts/teeth_copy.sh
teeth_setup smoke-teeth
STEPS=${CBX_SMOKE_STEPS:-60000}
# the smoke options of proofs/job.sh (dead-call tests off: see there)
export CBX_SMOKE_OPTS="${CBX_SMOKE_OPTS:--wp-no-smoke-dead-call}"
NOGOALS="-wp-prop=-@lemma,-@requires,-@assigns,-@ensures,-@exits,-@assert,-@invariant,-@variant,-@breaks,-@continues,-@returns,-@complete_behaviors,-@disjoint_behaviors,-@terminates,-@decreases,-@check"
pass=0; fail=0
# case NAME FILE FUNCTION TU OLD NEW : replace OLD by NEW in FILE, smoke FUNCTION
case_() {
  name=$1; file=$2; fct=$3; tu=$4; old=$5; new=$6
  d=$B/$name
  teeth_copy "$d" "$file" "$old" "$new"
  (cd "$d" && frama-c $(teeth_incs "$d") "$tu" \
     -wp -wp-rte -wp-smoke-tests ${CBX_SMOKE_OPTS:-} -wp-prover "cvc4r$(case $tu in *_f.c) echo 32;; *) echo 64;; esac)" -wp-steps "$STEPS" -wp-smoke-timeout 30 \
     -wp-par 2 -wp-cache none $NOGOALS -wp-fct "$fct" > "$d/smoke.log" 2>&1) || true
  # WP prints [Passed] for a smoke test the prover could not refute (the
  # context is consistent) and [Failed] for one it could
  n=$(grep -c 'Smoke-test' "$d/smoke.log" || true)
  if grep -v '^\[wp\] \[Passed\] Smoke-test' "$d/smoke.log" | grep -q 'Smoke-test'; then
    pass=$((pass + 1)); echo "smoke-teeth: ok   $name: caught ($(grep -v '\[Passed\]' "$d/smoke.log" | grep 'Smoke-test' | head -1 | cut -c1-110))"
  else
    fail=$((fail + 1)); echo "smoke-teeth: FAIL $name: not caught ($n smoke tests, all passed)"
  fi
}
# 1. a precondition that contradicts itself
case_ requires-range src/core/cbx_round.h cbx_widening proofs/all.c \
  "    requires rt: -CBX_RT <= t <= CBX_RT;
    requires r0: 0 <= g0" \
  "    requires rt: -CBX_RT <= t <= CBX_RT && t >= 2 * CBX_RT;
    requires r0: 0 <= g0"
# 2. a precondition inconsistent only through a lemma (in_dom, dom_pair)
case_ requires-lemma src/algo/cbx_kernel.h cbx_axis proofs/all_f.c \
  "    requires rt: -CBX_RT <= t <= CBX_RT;
    assigns \\nothing;
    ensures fin: \\is_finite(\\result.lo) && \\is_finite(\\result.hi);" \
  "    requires rt: -CBX_RT <= t <= CBX_RT;
    requires bad: !in_dom(m0, l0);
    assigns \\nothing;
    ensures fin: \\is_finite(\\result.lo) && \\is_finite(\\result.hi);"
# 2b. inconsistent only through a lemma's instance: the class 2^509 x 2^509
#     implies in_dom (lemma cls_509), which the precondition denies
case_ requires-via-lemma src/algo/cbx_kernel.h cbx_column proofs/all.c \
  "    requires dom: in_dom(m, l) && in_dom(m, h);
    assigns \\nothing;
    ensures fin: \\is_finite(\\result.lo)" \
  "    requires dom: in_dom(m, h) && cls(m, l, CBX_SB, CBX_SB) && !in_dom(m, l);
    assigns \\nothing;
    ensures fin: \\is_finite(\\result.lo)"
# 3. a trusted contract whose postcondition is false (every call is then dead)
case_ trusted-post src/core/cbx_round.h ball_radius proofs/all.c \
  "    ensures fin: \\is_finite(\\result) && \\result >= 0;
    ensures up:" \
  "    ensures fin: \\is_finite(\\result) && \\result >= 0 && \\result < 0;
    ensures up:"
# 4. an inconsistent loop invariant
case_ loop-invariant src/algo/cbx_batch.c batch proofs/all.c \
  "    /*@ loop invariant rng: 0 <= k <= n;" \
  "    /*@ loop invariant rng: 0 <= k <= n && k > n;"
# 5. a behavior that no input can take, and code only it reaches
case_ dead-branch src/algo/cbx_vertex.h vertex_lo proofs/all.c \
  "    if (m > CBX_C(0.0)) {
        /*@ assert sg: m > 0; */
        r.v = l;" \
  "    if (m > CBX_C(0.0) && m < CBX_C(0.0)) {
        /*@ assert sg: m > 0; */
        r.v = l;"
echo "smoke-teeth: $pass passed, $fail failed (step budget $STEPS)"
echo "$pass passed, $fail failed"
[ $fail = 0 ]
