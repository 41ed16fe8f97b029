#!/bin/sh
# The digest of everything a proof run reads: the library's sources and
# headers, the specifications, the proof translation units, the prover
# drivers and the pipeline's scripts.  proofs/run.sh stores it with its logs
# (build/proof/inputs.sha256); make evidence reuses the logs only when it
# matches the checkout, and runs the proofs otherwise.
#   sh proofs/inputs.sh           print the digest
#   sh proofs/inputs.sh --check   exit 0 iff build/proof holds a complete
#                                 run of these very inputs
set -eu
cd "$(dirname "$0")/.."
digest=$(LC_ALL=C sha256sum include/*.h src/*/*.c src/*/*.h specs/*.h proofs/*.c proofs/*.drv.in \
         scripts/incs.sh proofs/fcts.py proofs/run.sh proofs/job.sh proofs/setup.sh proofs/report.py proofs/idle.ml proofs/prune.ml proofs/plugin.sh | sha256sum | cut -c1-64)
case ${1:-} in
  --check) [ -f build/proof/inputs.sha256 ] && [ "$(cat build/proof/inputs.sha256)" = "$digest" ] ;;
  *) echo "$digest" ;;
esac
