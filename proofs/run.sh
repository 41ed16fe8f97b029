#!/bin/sh
# Run the Frama-C/WP proofs of certbox (both families) and write
# build/proof/report.md (make proof-report copies it to the committed
# proofs/report.md: a proof run never changes a tracked file).
#   sh proofs/run.sh          prove, write the report
#   sh proofs/run.sh --check  same, and exit 1 unless every goal is proved
#                             and the smoke tests find no inconsistent contract
# Model: WP's default (Typed memory, IEEE float), -wp-rte; provers: see
# proofs/README.md.  Nothing is carried over: without CBX_WP_KEEP_CACHE the
# jobs keep no WP cache, so the provers prove every goal each run.
#
# The work is a list of independent jobs (proofs/job.sh: lemmas, kernels,
# the rest and the smoke tests, per family), run CBX_JOBS at a time (the
# number of cores by default): WP's own work (parsing, RTE, VC generation,
# simplification) is single-threaded, so two Frama-C processes keep two
# cores busy where one process with two prover jobs did not.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
check=0; [ "${1:-}" = --check ] && check=1
# --check always proves from scratch (see job.sh: CBX_WP_KEEP_CACHE)
[ $check = 1 ] && unset CBX_WP_KEEP_CACHE
out=build/proof
mkdir -p $out
rm -f $out/wp-*.log $out/wp-*.time $out/inputs.sha256 $out/report.md
# the inputs as they are when the run starts (make evidence checks them)
inputs=$(sh proofs/inputs.sh)
conf=$(sh proofs/setup.sh $out)
export WHY3CONFIG="$conf"
sh proofs/idle.sh > /dev/null   # checked once, before the jobs (proofs/idle.sh)
NPROC=$(nproc 2>/dev/null || echo 2)
# One job more than there are cores, each with one prover process per core:
# WP's task loop sleeps 50 ms between its rounds (Frama-C's Task.on_idle)
# and does its own work (VC generation, Qed) on one core, so two jobs on two
# cores left them idle a fifth of the time (measured 2026-11-28: PB64 and
# PN64 side by side, 250 s of CPU in 160 s of wall time on 2 cores).
JOBS=${CBX_JOBS:-$((NPROC + 1))}
export CBX_WP_PAR="${CBX_WP_PAR:-$NPROC}"
# longest first (the wall times, three jobs at a time, of the clean-clone
# run of a4e3f73, 2026-11-28: L64 took 151 s there, started 21st), so that
# the pool ends evenly
LIST="B64a T64 PB64 PA64 L64 PN64 K64 PA32 B64b B32 K32 A64 I64 PS64 PE64 S64 BS64 P64 P32 BS32 S32 A32 L32 LP64 BSA64 BSA32 SPS64 PSR64 ST64 SP32 SP64 SPN64 SPB64 SPE64 SI64 PW SPW"
echo "proof: $(echo $LIST | wc -w) jobs, $JOBS at a time, $CBX_WP_PAR prover processes each"
start=$(date +%s)
# a failed job shows in the report (RESULT: NOT PROVED), not here
echo $LIST | tr ' ' '\n' | xargs -P "$JOBS" -n 1 sh proofs/job.sh || true
end=$(date +%s)
CBX_CACHED=${CBX_WP_KEEP_CACHE:+1} python3 proofs/report.py $out $((end - start)) > $out/report.md.new
echo "$inputs" > $out/inputs.sha256
mv $out/report.md.new $out/report.md
tail -n 4 $out/report.md
if [ $check = 1 ]; then
  grep -q '^RESULT: PROVED' $out/report.md || { echo "proof: FAILED (see $out/report.md, $out/wp-*.log)"; exit 1; }
fi
