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
rm -f $out/wp-*.log $out/wp-*.time $out/wp-*.json $out/wp-*.runs $out/inputs.sha256 $out/report.md
# the inputs as they are when the run starts (make evidence checks them)
inputs=$(sh proofs/inputs.sh)
conf=$(sh proofs/setup.sh $out)
export WHY3CONFIG="$conf"
# the modules every Frama-C run loads (proofs/plugin.sh), built once, before the jobs
sh proofs/plugin.sh > /dev/null
NPROC=$(nproc 2>/dev/null || echo 2)
# As many jobs as there are cores, each with one prover process per core.
# A job is WP's own work (VC generation, Qed, Why3's encoding of each task)
# on one core plus its prover processes; with proofs/idle.ml it keeps
# about 1.6 cores busy alone, so two jobs fill two cores, and a third only
# adds contention: jobs K64 K32 B64b B32 A64 A32, 2026-11-30 on 2 cores,
# took 297 s two at a time and 326 s three at a time (304 s two at a time
# with one prover process each).  Before proofs/idle.ml (Frama-C's task loop
# slept 50 ms between rounds: two jobs left a fifth of two cores idle, PB64
# beside PN64, 2026-11-28) the pool ran one job more than there are cores.
JOBS=${CBX_JOBS:-$NPROC}
export CBX_JOBS=$JOBS   # for the report
export CBX_WP_PAR="${CBX_WP_PAR:-$NPROC}"
# longest first (the wall times, two jobs at a time, of the clean-clone
# run of 4e0c9fc, 2026-12-01, the lemma jobs placed by their times since
# each lemma goes to one prover), so that the pool ends evenly with the
# short smoke jobs
LIST="B64a T64 PW PB64 PE64 PA64 PN64 PA32 S64 B64b B32 K64 K32 A64 I64 PS64 BS32 BS64 P32 S32 A32 L64 P64 SPW LP64 ST64 SPS64 L32 BSA64 BSA32 PSR64 SP32 SP64 SPE64 SPN64 SPB64 SI64"
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
