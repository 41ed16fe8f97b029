#!/bin/sh
# Run one phase of make check and say how long it took:
#   sh scripts/timed.sh NAME COMMAND...
# prints "check: NAME: N s" after COMMAND, and exits with COMMAND's status.
name=$1; shift
start=$(date +%s)
"$@"; rc=$?
echo "check: $name: $(($(date +%s) - start)) s$( [ $rc = 0 ] || echo ", FAILED (exit $rc)")"
exit $rc
