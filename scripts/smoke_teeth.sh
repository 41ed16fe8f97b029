#!/bin/sh
# make smoke-teeth: do the smoke tests, at their step budget, catch an
# inconsistent contract?  Each case below copies the sources to a scratch
# directory, makes one contract inconsistent, and checks it the way
# proofs/job.sh's jobs would meet it: the smoke tests of the affected
# function exactly as the smoke jobs run them (same options, same
# CBX_SMOKE_STEPS), which must find one that does not pass; or, for an
# internal function's precondition (no requires test there: see
# proofs/job.sh, SMOKE), the regular proof of its callers, which must leave
# that precondition unproved at a call.
# Usage: sh scripts/smoke_teeth.sh  (from the checkout's root)
set -u
. scripts/teeth_copy.sh
teeth_setup smoke-teeth
STEPS=${CBX_SMOKE_STEPS:-40000}
# the smoke options of proofs/job.sh (dead-call tests off), in the functions
# its smoke jobs test (see there)
NOGOALS="-wp-prop=-@lemma,-@requires,-@assigns,-@ensures,-@exits,-@assert,-@invariant,-@variant,-@breaks,-@continues,-@returns,-@complete_behaviors,-@disjoint_behaviors,-@terminates,-@decreases,-@check"
pass=0; fail=0
# case NAME FILE FUNCTION TU OLD NEW [LABEL]: replace OLD by NEW in FILE,
# then as proofs/job.sh checks FUNCTION: where the smoke jobs test it (an
# entry point, or a caller of a trusted contract: proofs/fcts.py
# --dead-code), its smoke tests must find one that does not pass; for an
# internal function (no smoke test), the precondition LABEL must stay
# unproved at some call (every caller proved for LABEL alone, as the
# regular jobs prove it): an inconsistent precondition of a function that
# only proved code calls is caught there (proofs/job.sh, SMOKE).
case_() {
  name=$1; file=$2; fct=$3; tu=$4; old=$5; new=$6; label=${7:-}
  d=$B/$name
  teeth_copy "$d" "$file" "$old" "$new"
  fam=64; case $tu in *_f.c) fam=32;; esac
  smoked=0
  python3 proofs/fcts.py "$tu" all --dead-code | tr , '\n' | grep -qx "$fct" && smoked=1
  if [ $smoked = 0 ]; then
    callers=$(python3 proofs/fcts.py "$tu" --callers "$fct")
    (cd "$d" && frama-c $(teeth_incs "$d") ${DEFS:-} "$tu" \
       -wp -wp-rte -wp-prover "cvc4r$fam" -wp-timeout 10 -wp-par 2 -wp-cache none \
       -wp-fct "$callers" -wp-prop "$label" > "$d/smoke.log" 2>&1) || true
    bad=$(grep -E 'Goal typed_[A-Za-z0-9_]+ : (Timeout|Unknown|Failed|Stepout)|^\[wp\] \[(Failed|Timeout|Unknown)\] Goal' "$d/smoke.log" \
          | sed 's/.*Goal typed_//; s/ .*//' | grep "_call_${fct}_[0-9_]*requires_$label\$" | head -1)
    if [ -n "$bad" ]; then
      pass=$((pass + 1)); echo "smoke-teeth: ok   $name: caught at a call ($bad unproved; callers $callers)"
    else
      fail=$((fail + 1)); echo "smoke-teeth: FAIL $name: not caught (no call of $fct left $label unproved; callers $callers)"
    fi
    return
  fi
  # every hypothesis in each task, as in the smoke jobs (proofs/job.sh)
  (cd "$d" && CBX_WP_WHOLE_TASKS=1 frama-c $(teeth_incs "$d") "$tu" \
     -wp -wp-rte -wp-smoke-tests -wp-no-smoke-dead-call -wp-prover "cvc4r$fam" -wp-steps "$STEPS" -wp-smoke-timeout 30 \
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
    requires r0: 0 <= g0" rt
# 1b. a public function's precondition that contradicts itself through the
#     memory model (out both the same as in and separated from it)
case_ requires-entry include/certbox.h cbx_transform_box_chain proofs/all.c \
  "    requires sep: \\separated(out, p + (0 .. n - 1)) && (\\separated(out, in) || out == in);" \
  "    requires sep: \\separated(out, p + (0 .. n - 1)) && \\separated(out, in) && out == in;"
# 2. a precondition inconsistent only through a lemma (in_dom, dom_pair)
case_ requires-lemma src/algo/cbx_kernel.h cbx_axis proofs/all_f.c \
  "    requires rt: -CBX_RT <= t <= CBX_RT;
    assigns \\nothing;
    ensures fin: \\is_finite(\\result.lo) && \\is_finite(\\result.hi);" \
  "    requires rt: -CBX_RT <= t <= CBX_RT;
    requires bad: !in_dom(m0, l0);
    assigns \\nothing;
    ensures fin: \\is_finite(\\result.lo) && \\is_finite(\\result.hi);" bad
# 2b. inconsistent only through a lemma's instance: the class 2^509 x 2^509
#     implies in_dom (lemma cls_509), which the precondition denies
case_ requires-via-lemma src/algo/cbx_kernel.h cbx_column proofs/all.c \
  "    requires dom: in_dom(m, l) && in_dom(m, h);
    assigns \\nothing;
    ensures fin: \\is_finite(\\result.lo)" \
  "    requires dom: in_dom(m, h) && cls(m, l, CBX_SB, CBX_SB) && !in_dom(m, l);
    assigns \\nothing;
    ensures fin: \\is_finite(\\result.lo)" dom
# 2c. the same through the smoke tests: a function that calls a trusted
#     contract (cbx_ninf), whose precondition puts the class 2^509 x 2^509
#     beside !in_dom (lemma cls_509 makes it inconsistent)
case_ requires-via-lemma-smoke src/algo/cbx_interval.c ext_lo proofs/all.c \
  "    assigns \\nothing;
    ensures end: ext_lo_end(" \
  "    requires bad: cls(m0, l0, CBX_SB, CBX_SB) && !in_dom(m0, l0);
    assigns \\nothing;
    ensures end: ext_lo_end("
# 3. a trusted contract whose postcondition is false (every call is then dead)
case_ trusted-post src/core/cbx_round.h ball_radius proofs/all.c \
  "    ensures fin: \\is_finite(\\result) && \\result >= 0;
    ensures up:" \
  "    ensures fin: \\is_finite(\\result) && \\result >= 0 && \\result < 0;
    ensures up:"
# 4. an inconsistent loop invariant (in a public function; an internal
#    function has no smoke test, and an inconsistent invariant is one that
#    the regular proof cannot establish)
case_ loop-invariant src/f64/cbx_chain.c cbx_transform_box_chain proofs/all.c \
  "    /*@ loop invariant rng: 0 <= k <= n;" \
  "    /*@ loop invariant rng: 0 <= k <= n && k > n;"
# 5. code that no input reaches, in a function that calls a trusted
#    contract (cbx_ninf): the dead-code tests run there (proofs/job.sh)
case_ dead-branch src/algo/cbx_interval.c ext_lo proofs/all.c \
  "    if (!v0.ok || !v1.ok || !v2.ok) {
        r.v = cbx_ninf();
        r.ok = 1;" \
  "    if ((!v0.ok || !v1.ok || !v2.ok) && v0.ok && !v0.ok) {
        r.v = cbx_ninf();
        r.ok = 1;"
echo "smoke-teeth: $pass passed, $fail failed (step budget $STEPS)"
echo "$pass passed, $fail failed"
[ $fail = 0 ]
