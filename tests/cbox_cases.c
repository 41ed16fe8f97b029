/*
 * cbox_cases.c: part of tests/test_cbox.c (cbox_parts.h): the tables of
 * hand-picked cases, each with the status, lost axes (and for
 * cbx_transform_cbox the kinds per axis) the oracle must agree with.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <math.h>

#include "cbox_parts.h"

/* ---------------------------------------------------------------------- */
/* Hard cases                                                             */
/* ---------------------------------------------------------------------- */

#define ROW(a, b, c, t) { a, b, c, t }
#define MAT(r0, r1, r2) { { r0, r1, r2 } }
/* cbox per axis: (c0, h0, c1, h1, c2, h2) */
#define CB(c0, h0, c1, h1, c2, h2) { { c0, c1, c2 }, { h0, h1, h2 } }
/* box per axis: (lo0, hi0, lo1, hi1, lo2, hi2) */
#define BOX(l0, h0, l1, h1, l2, h2) { { l0, l1, l2 }, { h0, h1, h2 } }
#define ID3 MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0))
const tc_case cbt_tc_hard[] = {
    /* identity on the cbox (0, 1)^3 = [-1, 1]^3 */
    { "identity, c = 0, h = 1", ID3, CB(0, 1, 0, 1, 0, 1), CBX_OK, 0, "AAA" },
    /* identity on a point cbox (h = 0): the image is a point */
    { "identity, point cbox (h = 0)", ID3, CB(1.5, 0, -2, 0, 3, 0), CBX_OK, 0, "AAA" },
    /* h = -0.0 is not < 0: a point, not empty; -0.0 entries and t */
    { "signed permutation with -0.0, h = -0.0",
      MAT(ROW(-0.0, 1, -0.0, -0.0), ROW(-0.0, -0.0, -1, 0), ROW(1, -0.0, 0, -0.0)),
      CB(-0.0, -0.0, 2, 0.5, -0.0, 0.0), CBX_OK, 0, "AAA" },
    /* all zeros, every sign: image exactly {0}, S = 0 */
    { "all-zero map, signed zeros",
      MAT(ROW(-0.0, -0.0, -0.0, -0.0), ROW(0.0, -0.0, 0.0, 0.0), ROW(-0.0, 0.0, -0.0, 0.0)),
      CB(-0.0, 0.0, 3, 1, -5, -0.0), CBX_OK, 0, "AAA" },
    /* rank deficient: row 1 is zero (image of row 1 is the point t = 5) */
    { "zero row (rank 2) with t = 5",
      MAT(ROW(1, 2, 3, 0), ROW(0, 0, 0, 5), ROW(-1, 0.5, 2, -1)),
      CB(0.1, 0.2, -0.3, 0.4, 0.5, 0.6), CBX_OK, 0, "AAA" },
    /* rank 1: every row a multiple of (1, 2, 3) */
    { "rank 1 map",
      MAT(ROW(1, 2, 3, 0), ROW(-2, -4, -6, 1), ROW(0.1, 0.2, 0.30000000000000004, 2)),
      CB(1e3, 1e-3, -7, 0.25, 0.1, 0.1), CBX_OK, 0, "AAA" },
    /* tiny-angle rotations: cos rounds to 1.0, sin to the angle */
    { "rotation 1e-8 about z",
      MAT(ROW(1.0, -1e-8, 0, 0), ROW(1e-8, 1.0, 0, 0), ROW(0, 0, 1, 0)),
      CB(0, 1e6, 0, 1, 0, 0), CBX_OK, 0, "AAA" },
    { "rotation 1e-15 about x, translated",
      MAT(ROW(1, 0, 0, 5), ROW(0, 1.0, -1e-15, -1e15), ROW(0, 1e-15, 1.0, 0.25)),
      CB(0, 1, 1e15, 0, 0, 1e15), CBX_OK, 0, "AAA" },
    { "rotation 1e-300 about y",
      MAT(ROW(1.0, 0, 1e-300, 0), ROW(0, 1, 0, 0), ROW(-1e-300, 0, 1.0, 0)),
      CB(0, 1e300, 1.5, 0.5, 0, 1e-300), CBX_OK, 0, "AAA" },
    /* a huge translation with a tiny box */
    { "translation 1e15, h = 1e-10",
      MAT(ROW(1, 0, 0, 1e15), ROW(0, 1, 0, -1e15), ROW(0.5, 0.5, 0, 1e15)),
      CB(0.3, 1e-10, -0.7, 1e-10, 0, 1e-10), CBX_OK, 0, "AAA" },
    /* 1e-200 next to 1e200: 1e200 needs class k >= 704, so |c|, |h| <= 2^314 */
    { "1e-200 next to 1e200",
      MAT(ROW(1e200, 1e-200, 1, 0), ROW(-1e-200, 1e200, 0, 1e-200), ROW(1, 1, 1, 0)),
      CB(1e-200, 1e-200, 3e-201, 2e-200, 1e200, 1e199), CBX_OK, 0, "AAA" },
    /* subnormal entries, centres and half-diagonals */
    { "subnormals everywhere",
      MAT(ROW(0x1p-1074, -0x1p-1074, 0x1p-1060, 0x1p-1074),
          ROW(-0x1p-1074, 0x1.8p-1070, 0, -0x1p-1074), ROW(1, -1, 0.5, 0)),
      CB(0x1p-1074, 0x1p-1074, -0x1p-1073, 0x1p-1074, 0x1p-1022, 0x1p-1030), CBX_OK, 0, "AAA" },
    /* unit entries, subnormal cbox: c +- h exact, centre of 0.5 * 2^-1074 */
    { "subnormal cbox, entry 0.5",
      MAT(ROW(0.5, 0, 0, 0), ROW(0, 0.5, 0, 0x1p-1074), ROW(0.5, 0.5, 0.5, 0)),
      CB(0x1p-1074, 0, 0x1p-1074, 0x1p-1074, -0x1p-1074, 0x1p-1074), CBX_OK, 0, "AAA" },
    /* class 509 at its corner: m = 2^509, c = h = 2^509 */
    { "m = 2^509, c = h = 2^509",
      MAT(ROW(0x1p509, 0, 0, 0), ROW(-0x1p509, 0x1p509, 0, 0),
          ROW(0x1p509, 0x1p509, 0x1p509, 0x1p1018)),
      CB(0x1p509, 0x1p509, -0x1p509, 0x1p509, 0, 0x1p509), CBX_OK, 0, "AAA" },
    /* class 1018: m = 2^1018 with |c|, h <= 1; t = -2^1018 */
    { "m = 2^1018, |c|, h <= 1, t = -2^1018",
      MAT(ROW(0x1p1018, 0, 0, 0), ROW(0, -0x1p1018, 0, 0x1p1018),
          ROW(0x1p1018, 0, 0, -0x1p1018)),
      CB(1, 0, -0.5, 0.5, 0, 1), CBX_OK, 0, "AAA" },
    /* class 0: m = 1 with c, h = 2^1018; every term 2^1018 */
    { "m = 1, c = h = 2^1018",
      MAT(ROW(1, 1, 1, 0x1p1018), ROW(1, -1, 0, 0), ROW(0, 0, -1, -0x1p1018)),
      CB(0x1p1018, 0x1p1018, -0x1p1018, 0x1p1018, 0, 0x1p1018), CBX_OK, 0, "AAA" },
    /* near cancellation: point cbox and t = -fl(m.c) */
    { "near cancellation t = -fl(m.c), h = 0",
      MAT(ROW(0.1, 0.2, 0.3, -0.6000000000000001),
          ROW(1e-3, 1.1, -0.7, -0.024499999999999966), ROW(1, 1, 1, -3)),
      CB(1, 0, 1, 0, 1, 0), CBX_OK, 0, "AAA" },
    /* --- outside the domain ------------------------------------------ */
    /* m = 2^509 with h one ulp beyond 2^509: neither class 509 nor 512 */
    { "m = 2^509, h = 2^509 + ulp (row 2 out)",
      MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0x1p509, 0, 0, 0)),
      CB(0, P509U, 0, 1, 0, 1), CBX_ERANGE, 4, "AAW" },
    /* m = 2^509 with c one ulp beyond 2^509 */
    { "m = 2^509, c = 2^509 + ulp (rows 0, 2 out)",
      MAT(ROW(0x1p509, 0, 0, 0), ROW(0, 1, 0, 0), ROW(-0x1p509, 0, 0, 0)),
      CB(P509U, 0, 0, 1, 0, 1), CBX_ERANGE, 5, "WAW" },
    /* t one ulp beyond 2^1018 */
    { "t = 2^1018 + ulp (row 1 out)",
      MAT(ROW(1, 0, 0, 0x1p1018), ROW(0, 1, 0, -P1018U), ROW(0, 0, 1, 0)),
      CB(0, 1, 0, 1, 0, 1), CBX_ERANGE, 2, "AWA" },
    /* m one ulp beyond 2^1018 even with c = h = 0 */
    { "m = 2^1018 + ulp, c = h = 0 (row 0 out)",
      MAT(ROW(P1018U, 0, 0, 0), ROW(0x1p1018, 0, 0, 0), ROW(0, 0, 0, 0)),
      CB(0, 0, 1, 1, 1, 1), CBX_ERANGE, 1, "WAA" },
    /* h one ulp beyond 2^1018: outside every class; rows 0 and 1 have a
     * zero coefficient there and drop the column (D), row 2 is lost */
    { "h2 = 2^1018 + ulp (row 2 lost, rows 0, 1 drop)", ID3,
      CB(0, 1, 0, 1, 0, P1018U), CBX_ERANGE, 4, "DDW" },
    /* h = +inf: not empty; only the row with m_11 != 0 is lost */
    { "h1 = +inf (row 1 lost, rows 0, 2 drop)", ID3, CB(0, 1, 0, INF, 0, 1),
      CBX_ERANGE, 2, "DWD" },
    /* c = -inf: only the row with m_00 != 0 is lost */
    { "c0 = -inf (row 0 lost, rows 1, 2 drop)", ID3, CB(-INF, 0, 0, 1, 0, 1),
      CBX_ERANGE, 1, "WDD" },
    /* an infinite translation: only its row */
    { "t = +inf (row 2 out)",
      MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, INF)),
      CB(0, 1, 0, 1, 0, 1), CBX_ERANGE, 4, "AAW" },
    /* --- empty and NaN ----------------------------------------------- */
    { "h = -2^-1074 (empty)", ID3, CB(0, 1, 0, -0x1p-1074, 0, 1), CBX_EMPTY, 0, "---" },
    { "h = -inf (empty)", ID3, CB(0, 1, 0, 1, 0, -INF), CBX_EMPTY, 0, "---" },
    /* empty wins over out-of-domain */
    { "h < 0 and t = +inf (empty)",
      MAT(ROW(1, 0, 0, INF), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0)),
      CB(0, -1, 0, 1, 0, 1), CBX_EMPTY, 0, "---" },
    { "NaN in h", ID3, CB(0, 1, 0, NAN, 0, 1), CBX_EINVAL, 0, "---" },
    { "NaN in t", MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, NAN), ROW(0, 0, 1, 0)),
      CB(0, 1, 0, 1, 0, 1), CBX_EINVAL, 0, "---" },
    /* NaN wins over empty */
    { "NaN in c and h < 0", ID3, CB(NAN, 1, 0, -1, 0, 1), CBX_EINVAL, 0, "---" },
};
const int cbt_n_tc_hard = (int)(sizeof cbt_tc_hard / sizeof cbt_tc_hard[0]);

/* Zero-coefficient columns are dropped (0 * x = 0 for every real x): a
 * row that is not full but whose dropped row is full (kind D) is computed
 * by the kernel on the dropped row; a row still not full after dropping is
 * lost (W: c = 0, h = +inf, CBX_ERANGE).  -0.0 counts as zero; a
 * subnormal coefficient does not.  NaN and h < 0 in a dropped column still
 * give EINVAL / EMPTY. */
const tc_case cbt_tc_drop[] = {
    /* every row has m_0 == 0: column 0 (c = -inf, h = +inf) is dropped */
    { "column 0 zero everywhere, c0 = -inf, h0 = +inf",
      MAT(ROW(0, 1, 2, 3), ROW(0, -1, 0.5, 0), ROW(0, 0.25, -4, -1)),
      CB(-INF, INF, 1, 0.5, -2, 1), CBX_OK, 0, "DDD" },
    /* -0.0 coefficients against h = +inf and c = +inf */
    { "-0.0 coefficients against c1 = +inf, h2 = +inf",
      MAT(ROW(1, -0.0, -0.0, 0.5), ROW(-2, -0.0, -0.0, -0.0), ROW(3, -0.0, -0.0, 1e300)),
      CB(0.75, 0.25, INF, 0, 1, INF), CBX_OK, 0, "DDD" },
    /* +0 and -0 mixed in one column, c = h = +inf */
    { "+0 / -0 in column 2, c2 = h2 = +inf",
      MAT(ROW(1, 2, 0.0, 0), ROW(-1, 0.5, -0.0, 7), ROW(0.125, -8, 0.0, -7)),
      CB(3, 1, -1, 2, INF, INF), CBX_OK, 0, "DDD" },
    /* huge (out-of-domain) but finite entries in a zero column */
    { "zero column, c0 = DBL_MAX, h0 = 2^1023",
      MAT(ROW(0, 1, 0, 0), ROW(-0.0, 0, 1, 0), ROW(0, 1, 1, 1)),
      CB(DBL_MAX, 0x1p1023, 2, 1, -3, 0.5), CBX_OK, 0, "DDD" },
    { "zero column, c1 = -(2^1018 + ulp), h1 = 2^1018 + ulp",
      MAT(ROW(1, 0, 0, 0), ROW(0, 0, 1, 0), ROW(1, -0.0, 1, 0)),
      CB(1, 1, -P1018U, P1018U, 1, 1), CBX_OK, 0, "DDD" },
    /* an all-zero map: every column dropped, the image is the point t */
    { "all-zero map, c = +-inf / DBL_MAX, h = +inf (points t)",
      MAT(ROW(0, -0.0, 0, 5), ROW(-0.0, 0, -0.0, -0x1p1018), ROW(0, 0, 0, -0.0)),
      CB(INF, INF, -INF, INF, DBL_MAX, INF), CBX_OK, 0, "DDD" },
    /* two zero columns in every row, one against c = +inf, one against
     * h = +inf */
    { "two zero columns (c0 = inf, h1 = inf) in every row",
      MAT(ROW(0, 0, 1, 0), ROW(0, -0.0, 2, 1), ROW(-0.0, 0, 3, -1)),
      CB(INF, 0, 0, INF, 0.5, 0.5), CBX_OK, 0, "DDD" },
    /* the dropped row at a class corner: m = 2^509, c = h = 2^509, and
     * t = 2^1018; row 1 has m_0 != 0 against c0 = inf: lost */
    { "drop, rest at m = 2^509, c = h = 2^509 (row 1 lost)",
      MAT(ROW(0, 0x1p509, 0, 0x1p1018), ROW(0x1p509, 0, 0, 0), ROW(0, 0, 0x1p509, 0)),
      CB(INF, INF, 0x1p509, 0x1p509, -0x1p509, 0x1p509), CBX_ERANGE, 2, "DWD" },
    /* mixes: one zero column dropped, but a nonzero column infinite */
    { "zero column 0 dropped, nonzero column 2 with h2 = +inf (lost)",
      MAT(ROW(0, 1, 1, 0), ROW(0, 1, 0, 0), ROW(-0.0, 0, 2, 0)),
      CB(INF, 1, 0, 1, 0, INF), CBX_ERANGE, 5, "WDW" },
    { "c0 = -inf: dropped where m_0 = 0, lost where not",
      MAT(ROW(1, 0, 0, 0), ROW(0, 1, 1, 0), ROW(1, 1, 0, 0)),
      CB(-INF, 0, 2, 1, 3, 0), CBX_ERANGE, 5, "WDW" },
    { "each row drops a different column, c0 = +inf",
      MAT(ROW(0, 1, 1, 0), ROW(1, 0, 1, 0), ROW(1, 1, 0, 0)),
      CB(INF, 0, 1, 1, 1, 1), CBX_ERANGE, 6, "DWW" },
    /* dropped, but the rest of the row is outside the domain */
    { "drop, but t = +inf (lost)",
      MAT(ROW(0, 1, 0, INF), ROW(0, 1, 0, 0), ROW(0, 0, 1, -INF)),
      CB(INF, 0, 1, 1, 1, 1), CBX_ERANGE, 5, "WDW" },
    { "drop, but t = 2^1018 + ulp (lost)",
      MAT(ROW(0, 1, 0, P1018U), ROW(0, 1, 0, 0x1p1018), ROW(0, 0, 1, 0)),
      CB(-INF, INF, 1, 1, 1, 1), CBX_ERANGE, 1, "WDD" },
    { "drop, but m = 2^509 with c = 2^509 + ulp (lost)",
      MAT(ROW(0, 0x1p509, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0x1p509, 0, 0)),
      CB(INF, 0, P509U, 0, 1, 1), CBX_ERANGE, 5, "WDW" },
    { "drop, but an infinite coefficient (lost)",
      MAT(ROW(0, INF, 0, 0), ROW(0, 1, 0, 0), ROW(0, -INF, 0, 0)),
      CB(INF, INF, 1, 0, 1, 1), CBX_ERANGE, 5, "WDW" },
    /* a subnormal coefficient is not zero: not dropped */
    { "m = 2^-1074 against c0 = +inf (not dropped: lost)",
      MAT(ROW(0x1p-1074, 1, 0, 0), ROW(-0x1p-1074, 0, 1, 0), ROW(0, 1, 1, 0)),
      CB(INF, 0, 1, 1, 1, 1), CBX_ERANGE, 3, "WWD" },
    /* near cancellation: t = -fl(m.c), h = 0; first with every column
     * finite (full rows, A: the zero columns change nothing), then with
     * column 2 infinite (dropped in row 0, lost in rows 1, 2) */
    { "full rows with -0.0, near cancellation (A)",
      MAT(ROW(0.1, 0.2, -0.0, -0.30000000000000004), ROW(1e-3, 0, 1.1, -1.1009999999999998),
          ROW(0, 1, 1, -2)),
      CB(1, 0, 1, 0, 1, 0), CBX_OK, 0, "AAA" },
    { "drop infinite column, near cancellation, h = 0",
      MAT(ROW(0.1, 0.2, -0.0, -0.30000000000000004), ROW(1e-3, 0, 1.1, -1.1009999999999998),
          ROW(0, 1, 1, -2)),
      CB(1, 0, 1, 0, INF, INF), CBX_ERANGE, 6, "DWW" },
    /* subnormal scale in the dropped row */
    { "drop, subnormal remaining row",
      MAT(ROW(0x1p-1074, 0, -0x1p-1074, 0x1p-1074), ROW(0, 0, 0x1p-1060, 0), ROW(0, 0, 0, 0)),
      CB(0x1p-1074, 0x1p-1074, -INF, INF, 0x1p-1022, 0x1p-1030), CBX_OK, 0, "DDD" },
    /* h = -0.0 in a dropped column is not negative */
    { "h0 = -0.0 and c0 = -inf in a zero column",
      MAT(ROW(0, 1, 0, 0), ROW(-0.0, 0, 1, 0), ROW(0, 1, 1, 0)),
      CB(-INF, -0.0, 1, 1, 1, 1), CBX_OK, 0, "DDD" },
    /* NaN / h < 0 in a dropped column still decide the status */
    { "NaN c in a zero column (EINVAL)",
      MAT(ROW(0, 1, 0, 0), ROW(0, 0, 1, 0), ROW(0, 1, 1, 0)),
      CB(NAN, 0, 1, 1, 1, 1), CBX_EINVAL, 0, "---" },
    { "NaN h in a zero column (EINVAL)",
      MAT(ROW(0, 1, 0, 0), ROW(0, 0, 1, 0), ROW(0, 1, 1, 0)),
      CB(INF, NAN, 1, 1, 1, 1), CBX_EINVAL, 0, "---" },
    { "h = -1 in a zero column (EMPTY)",
      MAT(ROW(0, 1, 0, 0), ROW(0, 0, 1, 0), ROW(0, 1, 1, 0)),
      CB(0, -1, 1, 1, 1, 1), CBX_EMPTY, 0, "---" },
    { "h = -inf, c = +inf in a zero column (EMPTY)",
      MAT(ROW(-0.0, 1, 0, 0), ROW(0, 0, 1, 0), ROW(0, 1, 1, 0)),
      CB(INF, -INF, 1, 1, 1, 1), CBX_EMPTY, 0, "---" },
};
const int cbt_n_tc_drop = (int)(sizeof cbt_tc_drop / sizeof cbt_tc_drop[0]);

const b2c_case cbt_b2c_hard[] = {
    /* representable centre and half: exact conversion is possible */
    { "[0,1], [-1,1], [2,6]", BOX(0, 1, -1, 1, 2, 6), CBX_OK, 0 },
    /* point boxes and signed zeros ([+0, -0] is not empty) */
    { "points, [-0,+0], [+0,-0]", BOX(3, 3, -0.0, 0.0, 0.0, -0.0), CBX_OK, 0 },
    /* one ulp wide: the centre 1 + 2^-53 is not representable */
    { "one ulp wide at 1 and at -2^100",
      BOX(1, 0x1.0000000000001p0, -0x1.0000000000001p100, -0x1p100, 0.1, 0.1),
      CBX_OK, 0 },
    /* subnormals: centre 1.5 * 2^-1074 not representable */
    { "subnormal ends", BOX(0x1p-1074, 0x1p-1073, -0x1p-1074, 0x1p-1074, -0x1p-1022,
                           0x1p-1074), CBX_OK, 0 },
    /* huge with a tiny width; translated unit box */
    { "1e15 with width 0.125, tiny at 1e15",
      BOX(1e15, 1e15 + 0.125, -1e15, -1e15 + 1e-10, 1e15 - 1, 1e15 + 1), CBX_OK, 0 },
    /* 1e-300 next to 1e300 */
    { "[-1e300, 1e-300], [1e-300, 1e300]",
      BOX(-1e300, 1e-300, 1e-300, 1e300, -1e-300, 1e-300), CBX_OK, 0 },
    /* the domain limit 2^CONV_EMAX exactly, full range */
    { "[-2^CONV_EMAX, 2^CONV_EMAX] and [2^CONV_EMAX, 2^CONV_EMAX]",
      BOX(-CLIM, CLIM, CLIM, CLIM, -CLIM, -CLIM), CBX_OK, 0 },
    { "near the limit, one ulp wide",
      BOX((CLIM * 0x1.fffffffffffffp-1), CLIM, -CLIM, -(CLIM * 0x1.fffffffffffffp-1), 0, CLIM),
      CBX_OK, 0 },
    /* one ulp beyond 2^CONV_EMAX */
    { "hi = 2^CONV_EMAX + ulp (axis 1 out)", BOX(0, 1, 0, P1019U, 0, 1), CBX_ERANGE, 2 },
    { "lo = -2^CONV_EMAX - ulp (axis 0 out)", BOX(-P1019U, 0, 0, 1, 0, 1), CBX_ERANGE, 1 },
    /* 2^1020, DBL_MAX, 1e308 */
    { "2^(CONV_EMAX+1), DBL_MAX, 1e308 (all out)",
      BOX((2 * CLIM), (2 * CLIM), -DBL_MAX, DBL_MAX, 1e308, 1e308), CBX_ERANGE, 7 },
    /* infinite ends: a half-line or the whole line is not empty, but out */
    { "[-inf, inf], [-inf, 0] (axes 0, 2 out)",
      BOX(-INF, INF, 0, 1, -INF, 0), CBX_ERANGE, 5 },
    { "[2, +inf] (axis 1 out)", BOX(0, 1, 2, INF, 0, 1), CBX_ERANGE, 2 },
    /* lo = +inf or hi = -inf: no real point, empty even when lo <= hi */
    { "[+inf, +inf] (no real point: empty)", BOX(-INF, INF, 0, 1, INF, INF), CBX_EMPTY, 0 },
    { "[-inf, -inf] (no real point: empty)", BOX(0, 1, -INF, -INF, 0, 1), CBX_EMPTY, 0 },
    /* empty */
    { "lo one ulp above hi (empty)", BOX(0, 1, 0x1.0000000000001p0, 1, 0, 1), CBX_EMPTY, 0 },
    { "[+inf, -inf] (empty)", BOX(0, 1, 0, 1, INF, -INF), CBX_EMPTY, 0 },
    { "empty and out of domain (empty)", BOX(1, 0, -INF, INF, 0, 1), CBX_EMPTY, 0 },
    /* NaN */
    { "NaN lo", BOX(NAN, 1, 0, 1, 0, 1), CBX_EINVAL, 0 },
    { "NaN hi and empty axis", BOX(1, 0, 0, NAN, 0, 1), CBX_EINVAL, 0 },
};
const int cbt_n_b2c_hard = (int)(sizeof cbt_b2c_hard / sizeof cbt_b2c_hard[0]);

const c2b_case cbt_c2b_hard[] = {
    /* exact: (0,1) -> [-1,1], (0.5,0.5) -> [0,1] */
    { "(0,1), (0.5,0.5), (3,4)", CB(0, 1, 0.5, 0.5, 3, 4), CBX_OK, 0 },
    /* point cboxes, h = -0.0 is not empty, c = -0.0 */
    { "h = 0, h = -0.0, c = -0.0", CB(7, 0, -3, -0.0, -0.0, 2), CBX_OK, 0 },
    /* 1 + 2^-53 is not representable: hi must round up */
    { "(1, 2^-53): c + h between doubles", CB(1, 0x1p-53, -1, 0x1p-53, 0x1p52, 0.5),
      CBX_OK, 0 },
    /* huge centre with tiny half, tiny centre with huge half */
    { "(1e15, 1e-10), (1e-300, 1e300)", CB(1e15, 1e-10, 1e-300, 1e300, -1e15, 1e-10),
      CBX_OK, 0 },
    /* subnormals */
    { "subnormal c and h", CB(0x1p-1074, 0x1p-1074, -0x1.8p-1073, 0x1p-1074, 0x1p-1022,
                              0x1p-1060), CBX_OK, 0 },
    /* the limit 2^CONV_EMAX: c + h = 2^1020 still finite */
    { "c = h = 2^CONV_EMAX, c = -2^CONV_EMAX", CB(CLIM, CLIM, -CLIM, CLIM,
                                        -CLIM, 0), CBX_OK, 0 },
    /* one ulp beyond */
    { "c = 2^CONV_EMAX + ulp (axis 0 out)", CB(P1019U, 0, 0, 1, 0, 1), CBX_ERANGE, 1 },
    { "h = 2^CONV_EMAX + ulp (axis 2 out)", CB(0, 1, 0, 1, 0, P1019U), CBX_ERANGE, 4 },
    { "c = DBL_MAX, h = 1e308 (axes 0, 1 out)", CB(DBL_MAX, 0, 0, 1e308, 0, 1),
      CBX_ERANGE, 3 },
    { "h = +inf, c = -inf (axes 1, 2 out)", CB(0, 1, 0, INF, -INF, 0), CBX_ERANGE, 6 },
    /* empty */
    { "h = -2^-1074 (empty)", CB(0, 1, 0, -0x1p-1074, 0, 1), CBX_EMPTY, 0 },
    { "h = -inf and c = inf (empty)", CB(INF, -INF, 0, 1, 0, 1), CBX_EMPTY, 0 },
    /* NaN */
    { "NaN c", CB(0, 1, NAN, 1, 0, 1), CBX_EINVAL, 0 },
    { "NaN h and h < 0 elsewhere", CB(0, -1, 0, 1, 0, NAN), CBX_EINVAL, 0 },
};
const int cbt_n_c2b_hard = (int)(sizeof cbt_c2b_hard / sizeof cbt_c2b_hard[0]);
