/*
 * tight_cases.c: part of tests/test_tight.c (tight_parts.h): the hard
 * cases of section 0 (permutations, 0.1 * 3, exact cancellation, subnormal
 * results, the boundaries 2^-968 and 2^1015 of the exception, special
 * inputs).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <math.h>
#include <gmp.h>
#include <mpfr.h>

#include "tight_parts.h"

/* ---------------------------------------------------------------------- */
/* Hard cases                                                             */
/* ---------------------------------------------------------------------- */

#define ROW(a, b, c, t) { a, b, c, t }
#define MAT(r0, r1, r2) { { r0, r1, r2 } }
#define BOX(l0, h0, l1, h1, l2, h2) { { l0, l1, l2 }, { h0, h1, h2 } }

const hard tgt_hard_cases[] = {
    { "identity, unit cube", MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0)),
      BOX(0, 1, 0, 1, 0, 1) },
    { "cyclic permutation + integer t", MAT(ROW(0, 1, 0, 5), ROW(0, 0, 1, -7), ROW(1, 0, 0, 0)),
      BOX(-1, 2, 3, 4, -6, -5) },
    { "signed permutation, scales 2,3",
      MAT(ROW(0, -2, 0, 1), ROW(0, 0, 3, 0), ROW(-1, 0, 0, -4)),
      BOX(1, 2, -5, 7, -0.5, 0.25) },
    { "0.1 * 3 and 0.1 * -3", MAT(ROW(0.1, 0, 0, 0), ROW(-0.1, 0, 0, 0), ROW(0.1, 0.2, 0, 0)),
      BOX(3, 3, 1, 1, 0, 0) },
    { "permutation with -0.0, box [+0,-0]",
      MAT(ROW(-0.0, 1, -0.0, -0.0), ROW(-0.0, -0.0, -1, 0), ROW(1, -0.0, 0, -0.0)),
      BOX(-0.0, 0.0, -2, -1, 0.0, -0.0) },
    { "2^52-size integers, sum 2^53 + 1",
      MAT(ROW(1, 1, 0, 0), ROW(1, 1, 1, 0x1p53), ROW(-1, 0, 0, 0x1p53)),
      BOX(0x1p52, 0x1p52, 0x1p52 + 1, 0x1p52 + 1, 0.5, 0.5) },
    { "exact cancellation to 0", MAT(ROW(0.1, 0, 0, -0.1), ROW(3, -7, 0.5, 3.5), ROW(-1, 1, 1, -1)),
      BOX(1, 1, 1, 1, 1, 1) },
    { "near cancellation t = -fl(m.x)",
      MAT(ROW(0.1, 0.2, 0.3, -0.6000000000000001),
          ROW(1e-3, 1.1, -0.7, -0.024499999999999966), ROW(0.1, 0, 0, -0.10000000000000002)),
      BOX(1, 1, 1, 1, 1, 1) },
    { "near cancellation at 1e200",
      MAT(ROW(1e100, 3e99, -7e98, 8.9e199), ROW(1e100, 0, 0, -1e200),
          ROW(-1e100, -3e99, 7e98, -8.9e199)),
      BOX(1e100, 1e100, 7e99, 7e99, 3e101, 3e101) },
    { "E = rounding error of 0.1 * 0.1",
      MAT(ROW(0.1, 0, 0, -0.010000000000000002), ROW(0.1, 0, 0, -0.01), ROW(-0.1, 0, 0, 0.01)),
      BOX(0.1, 0.1, 0, 0, 0, 0) },
    { "E = -2^-1074 and +2^-1074",
      MAT(ROW(1, -1, 0, -0x1p-1074), ROW(1, -1, 0, 0x1p-1074), ROW(0x1p-1074, 0, 0, 0)),
      BOX(1, 1, 1, 1, 0, 0) },
    { "E = 2^-1074 * 0.5 (a half of the smallest subnormal)",
      MAT(ROW(0.5, 0, 0, 0), ROW(-0.5, 0, 0, 0), ROW(0.75, 0, 0, 0)),
      BOX(0x1p-1074, 0x1p-1074, 0, 0, 0x1p-1074, 0x1p-1074) },
    { "1 + 2^-1000 - 1 (exact, tiny)",
      MAT(ROW(1, 1, 0, -1), ROW(1, -1, 0, 0), ROW(1, 1, 1, -2)),
      BOX(1, 1, 0x1p-1000, 0x1p-1000, 0x1p-1020, 0x1p-1020) },
    { "boundary: product exactly 2^-968 (outside the exception)",
      MAT(ROW(0x1p-968, 0, 0, 0), ROW(0x1p-968, 0, 0, 1), ROW(0x1p-484, 0, 0, 0)),
      BOX(1, 1, 0, 0, 0x1p-484, 0x1p-484) },
    { "boundary: product 2^-968 * 1.5 (outside the exception)",
      MAT(ROW(0x1.8p-968, 0, 0, 0), ROW(0x1p-968, 0x1.8p-968, 0, 0), ROW(3, 0, 0, 0)),
      BOX(1, 1, 1, 1, 0x1p-969, 0x1p-969) },
    { "boundary: product 2^-969 (in the exception)",
      MAT(ROW(0x1p-969, 0, 0, 0), ROW(0x1p-969, 0, 0, 1), ROW(0x1p-1074, 0, 0, 0)),
      BOX(1, 1, 0, 0, 1, 1) },
    { "boundary: t = 2^1015 exactly (outside the exception)",
      MAT(ROW(0.1, 0, 0, 0x1p1015), ROW(-0.1, 0, 0, -0x1p1015), ROW(1, 0, 0, 0x1p1015)),
      BOX(3, 3, 0, 0, -1, -1) },
    { "boundary: t = 2^1015 + ulp (in the exception)",
      MAT(ROW(0.1, 0, 0, 0x1.0000000000001p1015), ROW(0, 0, 0, -0x1.0000000000001p1015),
          ROW(1, 0, 0, 0x1p1016)),
      BOX(3, 3, 0, 0, -1, -1) },
    { "boundary: E just below 2^1015",
      MAT(ROW(0x1p1014, 0x1p1013, 0, 0), ROW(0x1p1014, 0x1p1013, 0.1, 0), ROW(0, 0, 0, 0)),
      BOX(1, 1, 0.5, 0.5, -1, -1) },
    { "all zeros with signs",
      MAT(ROW(-0.0, -0.0, -0.0, -0.0), ROW(0.0, -0.0, 0.0, 0.0), ROW(-0.0, 0.0, -0.0, 0.0)),
      BOX(-0.0, -0.0, -0.0, 0.0, 0.0, -0.0) },
    { "decimal rotation-like matrix, point box",
      MAT(ROW(0.36, -0.48, 0.8, 10), ROW(0.8, 0.6, 0, -3), ROW(-0.48, 0.64, 0.6, 0.5)),
      BOX(0.3, 0.3, -1.7, -1.7, 2.5, 2.5) },
    { "half-spaces with zero columns",
      MAT(ROW(1, 0, -0.0, 0.1), ROW(0, -3, 0, 0), ROW(0.1, 0.2, 0.3, 0)),
      BOX(-INF, 1, 0.1, INF, -INF, INF) },
    { "half-space, finite ends from the vertex",
      MAT(ROW(0.1, -0.2, 0, 1), ROW(-0.1, 0.2, 0, -1), ROW(0, 0, 0.3, 0.7)),
      BOX(0.3, INF, -INF, 0.7, 1, 1) },
    { "huge unneeded end (out of the domain)",
      MAT(ROW(0.1, 0, 0, 0), ROW(-0.1, 0, 0, 0), ROW(0.1, 0.3, 0, 0)),
      BOX(0.7, DBL_MAX, 0, 0, 0, 0) },
    { "infinite map entry", MAT(ROW(INF, 0, 0, 0), ROW(0.1, 0, 0, 0.2), ROW(0, 0, 0, -INF)),
      BOX(1, 2, 3, 4, 5, 6) },
    { "NaN in the map", MAT(ROW(NAN, 0, 0, 0), ROW(0.1, 0, 0, 0.2), ROW(0, 0, 0, 1)),
      BOX(1, 2, 3, 4, 5, 6) },
    { "NaN in the box", MAT(ROW(1, 0, 0, 0), ROW(0.1, 0, 0, 0.2), ROW(0, 0, 0, 1)),
      BOX(1, 2, NAN, 4, 5, 6) },
    { "empty box (hi < lo)", MAT(ROW(1, 0, 0, 0), ROW(0.1, 0, 0, 0.2), ROW(0, 0, 0, 1)),
      BOX(1, 2, 4, 3, 5, 6) },
    { "empty box (lo = +inf)", MAT(ROW(1, 0, 0, 0), ROW(0.1, 0, 0, 0.2), ROW(0, 0, 0, 1)),
      BOX(INF, INF, 3, 4, 5, 6) },
};
const int tgt_n_hard = (int)(sizeof tgt_hard_cases / sizeof tgt_hard_cases[0]);
