/*
 * test_exact [N] [seed]: cbx_transform_box against exact rational arithmetic.
 *
 * First a table of hand-picked hard cases, then N random cases (default
 * 1000000) from a fixed-seed generator.  For every case: the status equals
 * the one computed exactly from the spec, every field of *out is written,
 * EINVAL / EMPTY outputs are exact, and each output axis follows the rules
 * of exact_util.h: full rows (rule A) are finite, contain the exact image
 * (exact comparison with L_i and H_i) and stay within the proven bound
 * 12 u S + 2^-1065; on other rows with a finite map (rule B: infinite box
 * ends as half-spaces, boxes outside the domain) each end is exactly
 * -inf / +inf where the image is unbounded or the vertex is outside the
 * domain, and otherwise finite, on the right side of the exact vertex
 * value and within 12 u S_v + 2^-1065; rows with an infinite map entry
 * (rule C) are exactly [-inf, +inf].  The table also gives, by hand, the
 * rows with a loss and the kind of each of the six ends (A F U L W, see
 * exact_util.h), compared with the oracle.  Every 100th random case (and
 * every table case) also checks the 8 corners with plain mpq_t arithmetic
 * (extended corners for rule B).  Excess statistics are printed; the last
 * line is "N passed, M failed" (read by CI).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <math.h>
#include <time.h>

#include "certbox.h"
#include "exact_util.h"

#define MAX_FAIL_LOGS 20
#ifndef CORNER_EVERY /* -DCORNER_EVERY=1 checks the corners on every case */
#define CORNER_EVERY 100
#endif

/* ---------------------------------------------------------------------- */
/* Hard cases                                                             */
/* ---------------------------------------------------------------------- */

typedef struct hard_case {
    const char *name;
    cbx_affine a;
    cbx_box in;
    cbx_status expect; /* written by hand from the spec                    */
    int loss;          /* rows expected with a loss (bit i = row i)        */
    int perm;          /* permutation / sign flip / small integers: the
                          exact image box is representable in binary64   */
    const char *ends;  /* the six end kinds, "lo hi" per axis (A full row,
                          F vertex, U unbounded, L lost, W whole line)     */
} hard_case;

/* A row is {m[i][0], m[i][1], m[i][2], t_i}; a box is given per axis as
 * (lo0, hi0, lo1, hi1, lo2, hi2), which reads better than lo[] then hi[]. */
#define ROW XU_ROW
#define MAT XU_MAT
#define BOX XU_BOX

static const hard_case hard_cases[] = {
    /* --- permutations and sign flips: exact image representable ------ */
    /* identity on the unit cube */
    { "identity, unit cube",
      MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0)),
      BOX(0, 1, 0, 1, 0, 1), CBX_OK, 0, 1, "AA AA AA" },
    /* cyclic permutation with integer translation */
    { "cyclic permutation + integer t",
      MAT(ROW(0, 1, 0, 5), ROW(0, 0, 1, -7), ROW(1, 0, 0, 0)),
      BOX(-1, 2, 3, 4, -6, -5), CBX_OK, 0, 1, "AA AA AA" },
    /* sign flips, a degenerate (point) axis */
    { "sign flips diag(-1,1,-1) + t",
      MAT(ROW(-1, 0, 0, 1), ROW(0, 1, 0, 2), ROW(0, 0, -1, 3)),
      BOX(-3, 5, 0, 0, 1, 2), CBX_OK, 0, 1, "AA AA AA" },
    /* signed permutation with scales 2 and 3: image still dyadic */
    { "signed permutation, scales 2,3",
      MAT(ROW(0, -2, 0, 1), ROW(0, 0, 3, 0), ROW(-1, 0, 0, -4)),
      BOX(1, 2, -5, 7, -0.5, 0.25), CBX_OK, 0, 1, "AA AA AA" },
    /* permutation whose zeros are -0.0; box [0,-0] on axis 2 is NOT empty
     * (+0 > -0 is false) */
    { "permutation with -0.0 entries, box [+0,-0]",
      MAT(ROW(-0.0, 1, -0.0, -0.0), ROW(-0.0, -0.0, -1, 0), ROW(1, -0.0, 0, -0.0)),
      BOX(-0.0, 0.0, -2, -1, 0.0, -0.0), CBX_OK, 0, 1, "AA AA AA" },
    /* swap with large but exact integers */
    { "swap x0,x1 with 2^52-size integers",
      MAT(ROW(0, 1, 0, -4503599627370496.0), ROW(1, 0, 0, 1), ROW(0, 0, -1, 0)),
      BOX(-7, 9007199254740991.0, 4503599627370496.0, 4503599627370497.0, 3, 3),
      CBX_OK, 0, 1, "AA AA AA" },

    /* --- subnormals -------------------------------------------------- */
    /* smallest subnormal everywhere: products are 2^-2148 */
    { "2^-1074 entries, t and coords",
      MAT(ROW(0x1p-1074, -0x1p-1074, 0x1p-1074, 0x1p-1074),
          ROW(-0x1p-1074, -0x1p-1074, 0x1p-1074, -0x1p-1074),
          ROW(0x1p-1074, 0x1p-1074, -0x1p-1074, 0)),
      BOX(-0x1p-1074, 0x1p-1074, 0x1p-1074, 0x1p-1074, -0x1p-1074, 0),
      CBX_OK, 0, 0, "AA AA AA" },
    /* the smallest normal everywhere */
    { "2^-1022 entries, t and coords",
      MAT(ROW(0x1p-1022, -0x1p-1022, 0x1p-1022, -0x1p-1022),
          ROW(-0x1p-1022, 0x1p-1022, 0x1p-1022, 0x1p-1022),
          ROW(0x1p-1022, 0x1p-1022, 0x1p-1022, 0)),
      BOX(-0x1p-1022, 0x1p-1022, 0x1p-1022, 0x1p-1022, -0x1p-1022, -0x1p-1022),
      CBX_OK, 0, 0, "AA AA AA" },
    /* subnormal coordinates with unit entries: 0.5 * 2^-1074 is not
     * representable, so the eta term of the bound is what saves it */
    { "subnormal coords, unit entries",
      MAT(ROW(1, -1, 0, 0), ROW(0.5, 0, 0, 0), ROW(0, 0, 3, 0x1p-1074)),
      BOX(0x1p-1074, 0x1p-1073, -0x1p-1074, 0, 0x1p-1022, 0x1p-1022),
      CBX_OK, 0, 0, "AA AA AA" },
    /* subnormal entries with the largest coordinates of class k = 0 */
    { "subnormal entries, coords up to 2^1018",
      MAT(ROW(0x1p-1074, 0x1.8p-1070, -0x1p-1060, 0),
          ROW(-0x1.fffffffffffffp-1023, 0x1p-1074, 0x1p-1074, 0x1p-1074),
          ROW(0x1p-1074, 0, 1, -1)),
      BOX(-0x1p1018, 0x1p1018, 1e300, 1e300, -3, 5), CBX_OK, 0, 0, "AA AA AA" },

    /* --- the largest magnitudes of the domain ------------------------ */
    /* class k = 509 at its corner: only in the domain through k = 509 */
    { "m = 2^509 with coords 2^509",
      MAT(ROW(0x1p509, 0, 0, 0), ROW(-0x1p509, 0x1p509, 0, 0),
          ROW(0x1p509, 0x1p509, 0x1p509, 0x1p1018)),
      BOX(-0x1p509, 0x1p509, -0x1p509, 0x1p509, -0x1p509, 0x1p509),
      CBX_OK, 0, 0, "AA AA AA" },
    /* class k = 1018: m = 2^1018 with |c| <= 1 */
    { "m = 2^1018 with coords 1",
      MAT(ROW(0x1p1018, 0, 0, 0), ROW(0, -0x1p1018, 0, 0),
          ROW(0x1p1018, 0, 0, -0x1p1018)),
      BOX(-1, 1, 0.5, 1, -0x1p1018, 0x1p1018), CBX_OK, 0, 0, "AA AA AA" },
    /* class k = 0: m = 1 with |c| <= 2^1018; row 0 reaches 2^1020 */
    { "m = 1 with coords 2^1018",
      MAT(ROW(1, 1, 1, 0x1p1018), ROW(1, -1, 0, 0), ROW(0, 0, -1, -0x1p1018)),
      BOX(-0x1p1018, 0x1p1018, -0x1p1018, 0x1p1018, 0x1p1017, 0x1p1018),
      CBX_OK, 0, 0, "AA AA AA" },
    /* t = 2^1018 against negative terms of the same size; row 1 cancels
     * to exactly 0 at the top of the range */
    { "t = 2^1018 vs negative terms ~2^1018",
      MAT(ROW(-0x1p1018, -0x1.fffffffffffffp1017, -0x1p1017, 0x1p1018),
          ROW(-0x1p1018, 0, 0, 0x1p1018),
          ROW(0x1p960, -0x1p960, 0x1p1018, -0x1p1018)),
      BOX(1, 1, 0.75, 1, -1, 1), CBX_OK, 0, 0, "AA AA AA" },
    /* every product and t at 2^1018 with the same sign: |y| = 2^1020 */
    { "four 2^1018 terms of one sign",
      MAT(ROW(0x1p1018, 0x1p1018, 0x1p1018, 0x1p1018),
          ROW(-0x1p1018, -0x1p1018, -0x1p1018, -0x1p1018),
          ROW(0x1.fffffffffffffp1017, -0x1.fffffffffffffp1017,
              0x1.fffffffffffffp1017, -0x1p1018)),
      BOX(1, 1, -1, -1, 0.5, 1), CBX_OK, 0, 0, "AA AA AA" },
    /* mixed classes within one row: 1018, 509 and 0 */
    { "classes 1018, 509, 0 in one row",
      MAT(ROW(0x1p1018, 0x1p509, 1, 0x1p1018),
          ROW(-1, 0x1p-1074, 0x1p-1074, -0x1p-1074),
          ROW(0x1.5p1017, -0x1.3p508, -0x1.7p-1, 0)),
      BOX(-1, 1, -0x1p509, 0x1p509, -0x1p1018, 0x1p1018), CBX_OK, 0, 0, "AA AA AA" },
    /* class boundaries hit exactly: (2^64, 2^954) and (2^960, 2^58) */
    { "class boundaries k = 64 and k = 960",
      MAT(ROW(0x1p64, 0, 0, 0), ROW(0, 0x1p960, 0, 0), ROW(-0x1p64, -0x1p960, 1, 0)),
      BOX(0x1p954, 0x1p954, -0x1p58, 0x1p58, 0, 1), CBX_OK, 0, 0, "AA AA AA" },

    /* --- cancellation ------------------------------------------------ */
    /* t = -(m x) exactly: image is exactly 0 */
    { "exact cancellation to 0",
      MAT(ROW(0.1, 0, 0, -0.1), ROW(3, -7, 0.5, 3.5), ROW(-1, 1, 1, -1)),
      BOX(1, 1, 1, 1, 1, 1), CBX_OK, 0, 0, "AA AA AA" },
    /* t = -fl(m x): the image is the (tiny) rounding error of the sum */
    { "near cancellation t = -fl(m.x)",
      MAT(ROW(0.1, 0.2, 0.3, -0.6000000000000001),
          ROW(1e-3, 1.1, -0.7, -0.024499999999999966),
          ROW(0.1, 0, 0, -0.10000000000000002)),
      BOX(1, 1, 1, 1, 1, 1), CBX_OK, 0, 0, "AA AA AA" },
    /* same at scale 1e200 (class 384) */
    { "near cancellation at 1e200",
      MAT(ROW(1e100, 3e99, -7e98, 8.9e199), ROW(1e100, 0, 0, -1e200),
          ROW(-1e100, -3e99, 7e98, -8.9e199)),
      BOX(1e100, 1e100, 7e99, 7e99, 3e101, 3e101), CBX_OK, 0, 0, "AA AA AA" },
    /* cancellation against a non-point box */
    { "near cancellation, interval box",
      MAT(ROW(1e-3, 1.1, -0.7, -0.024499999999999966),
          ROW(0.1, 0.2, 0.3, -0.6000000000000001), ROW(1, 1, 1, -3)),
      BOX(1234.5, 1234.5000000000002, 0.3, 0.30000000000000004, 2.2, 2.2),
      CBX_OK, 0, 0, "AA AA AA" },

    /* --- signed zeros and point boxes -------------------------------- */
    /* all zeros, all signs: the image is exactly 0 and S = 0 */
    { "all zeros with signs",
      MAT(ROW(-0.0, -0.0, -0.0, -0.0), ROW(0.0, -0.0, 0.0, 0.0),
          ROW(-0.0, 0.0, -0.0, 0.0)),
      BOX(-0.0, -0.0, -0.0, 0.0, 0.0, -0.0), CBX_OK, 0, 0, "AA AA AA" },
    /* -0.0 coordinates with ordinary entries */
    { "-0.0 coordinates",
      MAT(ROW(2, -3, 0.5, 1), ROW(-0.0, 1e-3, -7, 0), ROW(1, 1, 1, -0.0)),
      BOX(-0.0, -0.0, -0.0, 1, -2, -0.0), CBX_OK, 0, 0, "AA AA AA" },
    /* point box with an inexact rotation-like matrix */
    { "point box, decimal matrix",
      MAT(ROW(0.36, -0.48, 0.8, 10), ROW(0.8, 0.6, 0, -3), ROW(-0.48, 0.64, 0.6, 0.5)),
      BOX(0.3, 0.3, -1.7, -1.7, 2.5, 2.5), CBX_OK, 0, 0, "AA AA AA" },
    /* point box at the largest coordinates of class k = 0 */
    { "point box at 2^1018 / -1e306",
      MAT(ROW(1, -1, 0.5, 0), ROW(0.75, 0.25, 0, -0x1p1018), ROW(-1, 0, 1, 1)),
      BOX(0x1p1018, 0x1p1018, -1e306, -1e306, 1, 1), CBX_OK, 0, 0, "AA AA AA" },

    /* --- tiny-angle rotations (cos(a) rounds to 1.0 for these a) ------ */
    { "rotation 1e-8 about z",
      MAT(ROW(1.0, -1e-8, 0, 0), ROW(1e-8, 1.0, 0, 0), ROW(0, 0, 1, 0)),
      BOX(-1e6, 1e6, -1, 1, 0, 0), CBX_OK, 0, 0, "AA AA AA" },
    { "rotation 1e-15 about x, translated",
      MAT(ROW(1, 0, 0, 5), ROW(0, 1.0, -1e-15, -1e15), ROW(0, 1e-15, 1.0, 0.25)),
      BOX(-1, 1, 1e15, 1e15, -1e15, 1e15), CBX_OK, 0, 0, "AA AA AA" },
    { "rotation 1e-300 about y",
      MAT(ROW(1.0, 0, 1e-300, 0), ROW(0, 1, 0, 0), ROW(-1e-300, 0, 1.0, 0)),
      BOX(-1e300, 1e300, 1, 2, -1e-300, 1e-300), CBX_OK, 0, 0, "AA AA AA" },
    /* cos = the double just below 1, sin = 2^-26 (exact pair) */
    { "rotation with cos = 1 - 2^-53",
      MAT(ROW(0x1.fffffffffffffp-1, -1.4901161193847656e-08, 0, 0),
          ROW(1.4901161193847656e-08, 0x1.fffffffffffffp-1, 0, 0), ROW(0, 0, 1, 0)),
      BOX(-1e10, 1e10, -1e10, 1e10, -1, 1), CBX_OK, 0, 0, "AA AA AA" },

    /* --- 1e-300 next to 1e300 in one matrix --------------------------- */
    /* 1e300 > 2^960, so its column needs class 1018: |x0|, |x2| <= 1 */
    { "1e-300 next to 1e300",
      MAT(ROW(1e300, 1e-300, 1, 0), ROW(-1e-300, 1, 1e300, -1e300),
          ROW(0.5, 1e-300, -1e300, 1e-300)),
      BOX(-1, 0.75, -1e300, 1e299, 0.125, 1), CBX_OK, 0, 0, "AA AA AA" },

    /* --- outside the domain: CBX_ERANGE where an end is lost --------- */
    /* 1e300 entries with coords up to 1e300 in every row: the end whose
     * vertex is x0 = 1 is proven (class 1018), the other one is lost */
    { "1e300 matrix, 1e300 coords (all rows out)",
      MAT(ROW(1e300, 0, 0, 0), ROW(-1e300, 1, 0, 0), ROW(1e300, 0, 1, 0)),
      BOX(1, 1e300, 0, 1, 0, 1), CBX_ERANGE, 7, 0, "FL LF FL" },
    /* only row 0 out (its upper end); rows 1 and 2 must still be proven */
    { "one row out, two proven",
      MAT(ROW(1e300, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 2, 1)),
      BOX(1, 1e300, -1, 1, 3, 4), CBX_ERANGE, 1, 0, "FL AA AA" },
    /* |t| just above 2^1018 */
    { "t = 2^1018 (1 + 2^-52)",
      MAT(ROW(1, 0, 0, 0x1.0000000000001p1018), ROW(0, 1, 0, 0x1p1018),
          ROW(0, 0, 1, -0x1p1018)),
      BOX(0, 1, 0, 1, 0, 1), CBX_ERANGE, 1, 0, "LL AA AA" },
    /* |m| just above 2^1018 even with coordinate 1 */
    { "m = 2^1018 (1 + 2^-52), coord 1",
      MAT(ROW(0x1p1018, 0, 0, 0), ROW(-0x1.0000000000001p1018, 0, 0, 0),
          ROW(0, 0, 0, 0)),
      BOX(1, 1, 0, 0, 0, 0), CBX_ERANGE, 2, 0, "AA LL AA" },
    /* zero entries, coordinate just above 2^1018: outside every class
     * (no full row), but a zero column has vertex 0: every end proven */
    { "zero column, coord 2^1018 (1 + 2^-52): rule B",
      MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(1, 1, 0, 0)),
      BOX(0, 1, 0, 1, 0, 0x1.0000000000001p1018), CBX_OK, 0, 0, "FF FF FF" },
    /* m = 2^509 with c just above 2^509: neither class 509 nor 512 */
    { "m = 2^509, coord 2^509 (1 + 2^-52)",
      MAT(ROW(1, 0, 0, 0), ROW(-1, 1, 0, 0), ROW(0x1p509, 0, 0, 0)),
      BOX(-0x1p509, 0x1.0000000000001p509, 0, 1, 0, 1), CBX_ERANGE, 4, 0, "AA AA FL" },
    /* m just above 2^64 with c = 2^954 */
    { "m = 2^64 (1 + 2^-52), coord 2^954",
      MAT(ROW(0x1.0000000000001p64, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0)),
      BOX(0x1p954, 0x1p954, 0, 1, 0, 1), CBX_ERANGE, 1, 0, "LL AA AA" },
    /* the largest finite translation */
    { "t = DBL_MAX",
      MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, DBL_MAX)),
      BOX(0, 1, 0, 1, 0, 1), CBX_ERANGE, 4, 0, "AA AA LL" },
    /* a finite box with a huge end only one side needs: x0 in
     * [0, DBL_MAX]; row 0 (m = 1) proves its lower end, row 1 (m = -1) its
     * upper end, row 2 (m = 0 on x0) both */
    { "x0 in [0, DBL_MAX]: huge end lost where needed",
      MAT(ROW(1, 0, 0, 0), ROW(-1, 0, 0, 0.5), ROW(0, 1, 0, 0)),
      BOX(0, DBL_MAX, 0, 1, 0, 1), CBX_ERANGE, 3, 0, "FL LF FF" },

    /* --- half-spaces: infinite box ends (rule B) ----------------------- */
    /* x0 >= 0: identity rows; row 0 unbounded above only */
    { "half-space x0 >= 0, identity",
      MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0)),
      BOX(0, HUGE_VAL, -1, 1, 2, 3), CBX_OK, 0, 0, "FU FF FF" },
    /* the whole space in, rows of zeros (+0 and -0) and one identity row:
     * 0 * inf counts as 0, so rows 0 and 1 are the point t */
    { "whole space, zero rows (+-0) and x0",
      MAT(ROW(0, 0, 0, 5), ROW(-0.0, 0, -0.0, -0.0), ROW(1, 0, 0, 0)),
      BOX(-HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL),
      CBX_OK, 0, 0, "FF FF UU" },
    /* x0 <= 3 against a negative coefficient: bounded below, by -6 + 1 */
    { "x0 <= 3 with m = -2 (bounded below)",
      MAT(ROW(-2, 0.5, 0, 1), ROW(0.1, 0, 0, 0), ROW(0, 0, -3, 0)),
      BOX(-HUGE_VAL, 3, -1, 1, -HUGE_VAL, -0.5), CBX_OK, 0, 0, "FU UF FU" },
    /* two columns unbounded in opposite directions: both ends unbounded */
    { "x0 >= 0, x1 >= 0, m = (1, -1): unbounded both ways",
      MAT(ROW(1, -1, 0, 0), ROW(1, 1, 0, 0), ROW(0, 0, 1, 0)),
      BOX(0, HUGE_VAL, 0, HUGE_VAL, 0.25, 0.5), CBX_OK, 0, 0, "UU FU FF" },
    /* a half-space whose bounded end has its vertex out of the domain */
    { "x0 <= 2 with m = 1e300: upper vertex lost",
      MAT(ROW(1e300, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0)),
      BOX(-HUGE_VAL, 2, 0, 1, 0, 1), CBX_ERANGE, 1, 0, "UL FF FF" },
    /* a half-space with a translation out of the domain */
    { "x0 >= 0 with t = DBL_MAX",
      MAT(ROW(1, 0, 0, DBL_MAX), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0)),
      BOX(0, HUGE_VAL, 0, 1, 0, 1), CBX_ERANGE, 1, 0, "LU FF FF" },
    /* the largest magnitudes of the domain at a half-space's vertex */
    { "x0 >= -2^1018, m = 1, t = 2^1018",
      MAT(ROW(1, 0, 0, 0x1p1018), ROW(0, -0x1p1018, 0, 0), ROW(0, 0, 0x1p509, 0)),
      BOX(-0x1p1018, HUGE_VAL, 0, 0, -HUGE_VAL, 0x1p509), CBX_OK, 0, 0, "FU FF UF" },
    /* subnormal vertex values, unbounded the other way */
    { "subnormal vertex, half-lines",
      MAT(ROW(0x1p-1074, -0x1p-1074, 0, 0x1p-1074), ROW(0.5, 0, 0, 0),
          ROW(0, 0, -1, -0x1p-1074)),
      BOX(0x1p-1074, HUGE_VAL, -HUGE_VAL, 0x1p-1073, 0x1p-1074, HUGE_VAL),
      CBX_OK, 0, 0, "FU FU UF" },
    /* infinite map entry next to half-spaces: that row whole, rest proven */
    { "m[1][1] = +inf with a half-space box",
      MAT(ROW(1, 0, 0, 0), ROW(0, HUGE_VAL, 0, 0), ROW(0, 0, -1, 0)),
      BOX(-HUGE_VAL, 1, 0, 0, 2, HUGE_VAL), CBX_ERANGE, 2, 0, "UF WW UF" },
};

#define N_HARD ((int)(sizeof hard_cases / sizeof hard_cases[0]))

/* ---------------------------------------------------------------------- */
/* Driver                                                                 */
/* ---------------------------------------------------------------------- */

static long fail_logs;

static void log_failure(const char *what, long id, const cbx_affine *a,
                        const cbx_box *in, const cbx_box *out,
                        const xu_verdict *v)
{
    if (fail_logs++ >= MAX_FAIL_LOGS) return;
    printf("FAIL %s %ld: %s (status %s, expected %s)\n", what, id, v->why,
           cbx_status_name(v->got), cbx_status_name(v->expected));
    xu_print_case(stdout, a, in);
    xu_print_box(stdout, "out", out);
}

/* The table is also a test of the oracle: a hand-written status, loss
 * mask or end-kind string that disagrees with xu_expected_status /
 * xu_loss_mask / xu_ends_str fails. */
static void run_hard(xu_exact *x, xu_stats *st, xu_stats *all, long *perm_n,
                     long *perm_exact)
{
    int n, i;
    printf("-- hard cases (%d) --\n", N_HARD);
    for (n = 0; n < N_HARD; n++) {
        const hard_case *h = &hard_cases[n];
        cbx_box out;
        xu_verdict v;
        int table_ok, exact = 1, e;
        double mx = 0;
        char ends[9];
        xu_run_case(x, &h->a, &h->in, &out, 1, &v);
        xu_ends_str(&h->a, &h->in, ends);
        table_ok = xu_expected_status(&h->a, &h->in) == h->expect
                   && xu_loss_mask(&h->a, &h->in) == h->loss
                   && strcmp(ends, h->ends) == 0;
        if (!table_ok) {
            if (!v.failed)
                snprintf(v.why, sizeof v.why, "table says %s/loss %d/ends %s, oracle %s/loss "
                        "%d/ends %s", cbx_status_name(h->expect), h->loss, h->ends,
                        cbx_status_name(v.expected), xu_loss_mask(&h->a, &h->in), ends);
            v.failed = 1;
        }
        xu_stats_add(st, &v, &h->a, &h->in);
        xu_stats_add(all, &v, &h->a, &h->in);
        for (i = 0; i < 3; i++) {
            for (e = 0; e < 2; e++)
                if (v.ax[i].end_checked[e] && v.ax[i].ex_end[e] > mx) mx = v.ax[i].ex_end[e];
            if (!v.ax[i].checked) { exact = 0; continue; }
            exact &= v.ax[i].exact;
            if (v.ax[i].ex_lo > mx) mx = v.ax[i].ex_lo;
            if (v.ax[i].ex_hi > mx) mx = v.ax[i].ex_hi;
        }
        if (h->perm) {
            (*perm_n)++;
            *perm_exact += exact;
        }
        printf("  %-52s %-10s %s  max excess %7.3f%s  %s\n", h->name,
               cbx_status_name(v.got), ends, mx, h->perm && exact ? " (exact box)" : "",
               v.failed ? "FAIL" : "ok");
        if (v.failed) log_failure("hard", n, &h->a, &h->in, &out, &v);
    }
}

static void run_random(xu_exact *x, xu_stats *st, xu_stats *all, long n,
                       uint64_t seed)
{
    xu_rng r;
    long c;
    r.s = seed;
    for (c = 0; c < n; c++) {
        cbx_affine a;
        cbx_box in, out;
        xu_verdict v;
        int corners = c % CORNER_EVERY == 0;
        xu_gen_case(&r, &a, &in);
        if (xu_run_case(x, &a, &in, &out, corners, &v))
            log_failure("random", c, &a, &in, &out, &v);
        xu_stats_add(st, &v, &a, &in);
        xu_stats_add(all, &v, &a, &in);
    }
}

/* Parse argv[k] as a number, or exit with a usage message (a typo must
 * not silently run 0 cases). */
int main(int argc, char **argv)
{
    long n = (long)xu_arg_num(argc, argv, 1, 1000000ULL, "[N] [seed]");
    uint64_t seed = (uint64_t)xu_arg_num(argc, argv, 2, 0x5eed0fce27b0c5ULL, "[N] [seed]");
    xu_exact x;
    xu_stats hard, rnd, all;
    long perm_n = 0, perm_exact = 0, passed, failed;
    clock_t t0 = clock();

    if (n < 0) n = 0;
    xu_init(&x);
    xu_stats_init(&hard);
    xu_stats_init(&rnd);
    xu_stats_init(&all);

    run_hard(&x, &hard, &all, &perm_n, &perm_exact);
    run_random(&x, &rnd, &all, n, seed);

    xu_stats_print(stdout, "hard cases", &hard);
    printf("  permutation/sign-flip cases: %ld, output exactly equal to the "
           "exact box: %ld (not required: the library widens)\n",
           perm_n, perm_exact);
    printf("\n");
    xu_stats_print(stdout, "random cases", &rnd);
    if (rnd.axes > rnd.axes_tiny) {
        printf("  largest normal-scale excess: axis %d of\n", rnd.worst_axis);
        xu_print_case(stdout, &rnd.worst_a, &rnd.worst_in);
    }
    printf("  seed 0x%llx, corner checks on every %d-th case\n",
           (unsigned long long)seed, CORNER_EVERY);
    printf("  CPU time %.2f s\n", (double)(clock() - t0) / CLOCKS_PER_SEC);
    printf("\n");
    xu_stats_print(stdout, "totals (hard + random)", &all);

    xu_clear(&x);
    failed = all.failed;
    passed = all.cases - failed;
    printf("%ld passed, %ld failed\n", passed, failed);
    return failed ? 1 : 0;
}
