#!/bin/sh
# Generate the project-local Why3 configuration (build/proof/why3.conf) with
# two prover entries that keep floats out of the SMT floating-point theory:
#   cvc4r = CVC4 1.8 with proofs/cvc4_real.drv
#   z3r   = Z3 4.8 with proofs/z3_real.drv
# Driver paths in why3.conf are taken as written, so they are made absolute
# here, at build time.  See proofs/README.md for why this setup is trusted.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-$here/../build/proof}
mkdir -p "$out"
out=$(cd "$out" && pwd)
datadir=$(why3 --print-datadir)
for d in cvc4_real z3_real; do
  sed "s#@DATADIR@#$datadir#g" "$here/$d.drv.in" > "$out/$d.drv"
done
cvc4=$(command -v cvc4)
z3=$(command -v z3)
cat > "$out/why3.conf" <<CONF
[main]
datadir = "$datadir"
libdir = "$(why3 --print-libdir)"
magic = 14
memlimit = 4000
running_provers_max = 2
timelimit = 10

[prover]
name = "CVC4"
version = "$($cvc4 --version | sed -n 's/.*CVC4 version \([^ ]*\).*/\1/p' | head -1)"
alternative = "real"
shortcut = "cvc4r"
command = "$cvc4 --stats --tlimit=%t000 --lang=smt2 %f"
command_steps = "$cvc4 --stats --rlimit=%S --lang=smt2 %f"
driver = "$out/cvc4_real.drv"
in_place = false
interactive = false

[prover]
name = "Z3"
version = "$($z3 -version | sed -n 's/Z3 version \([^ ]*\).*/\1/p')"
alternative = "real"
shortcut = "z3r"
command = "$z3 -smt2 -T:%t sat.random_seed=42 nlsat.randomize=false smt.random_seed=42 -st %f"
command_steps = "$z3 -smt2 sat.random_seed=42 nlsat.randomize=false smt.random_seed=42 -st rlimit=%S %f"
driver = "$out/z3_real.drv"
in_place = false
interactive = false
CONF
echo "$out/why3.conf"
