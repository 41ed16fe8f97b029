#!/bin/sh
# The exact oracles and helpers every test, fuzz harness and the demo link
# (tests/): one list for the Makefile (TESTUTIL), scripts/cross.sh,
# scripts/fuzz.sh and scripts/evidence.py, so that a new oracle file is
# added in one place.
echo "tests/exact_util.c tests/proj_oracle.c tests/psph_oracle.c tests/pnear_oracle.c tests/pball_oracle.c tests/proj_cases.c"
