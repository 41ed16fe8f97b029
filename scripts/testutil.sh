#!/bin/sh
# The exact oracles and helpers every test, fuzz harness and the demo link
# (tests/): one list for the Makefile (TESTUTIL), scripts/cross.sh,
# scripts/fuzz.sh and scripts/evidence.py, so that a new file is added in
# one place.  The oracles (--oracles: only these, which the bench links);
# then the parts of the longer tests, whose drivers (tests/test_NAME.c:
# main, the arguments, the order of the suites, the summary) declare them
# through tests/NAME_parts.h.
ORACLES="tests/exact_domain.c tests/exact_fixed.c tests/exact_check.c tests/exact_stats.c"
ORACLES="$ORACLES tests/exact_gen.c tests/exact_slerp.c tests/exact_proj.c tests/proj_oracle.c tests/psph_oracle.c tests/pnear_oracle.c tests/pball_oracle.c tests/proj_cases.c"
if [ "${1:-}" = --oracles ]; then echo "$ORACLES"; exit 0; fi
echo "$ORACLES" \
     "tests/cbox_check.c tests/cbox_conv.c tests/cbox_cases.c tests/cbox_random.c" \
     "tests/tight_check.c tests/tight_gen.c tests/tight_cases.c" \
     "tests/classes_gen.c tests/classes_kernels.c tests/classes_motion.c tests/classes_misuse.c" \
     "tests/plane_cases.c tests/plane_box.c tests/plane_cbox.c tests/plane_balls.c" \
     "tests/sphere_check.c tests/sphere_oracle.c tests/sphere_cases.c" \
     "tests/float_util.c tests/float_box.c tests/float_cbox.c tests/float_ball.c" \
     "tests/imat_check.c tests/imat_gen.c tests/imat_teeth.c" \
     "tests/special_cases.c tests/special_check.c tests/special_oracle.c" \
     "tests/chain_exact.c tests/chain_cases.c" \
     "tests/batch_gen.c tests/batch_check.c" \
     "tests/trs_exact.c tests/trs_gen.c tests/trs_special.c" \
     "tests/pwide_cases.c" \
     "tests/scene_exact.c tests/scene_gen.c" \
     "tests/gltf_exact.c tests/gltf_files.c"
