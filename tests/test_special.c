/*
 * test_special [-v]: special values, table-driven, for every public
 * function of certbox.h.
 *
 * The table is generated in code (make_table) as the cross product
 *     function x base input x input position x special value
 * and then run row by row (run_row).  Its columns (struct row):
 *   fn      the function called: transform_box, transform_cbox,
 *           box_to_cbox, cbox_to_box, sphere_box, ellipsoid_box;
 *   base    the otherwise ordinary input the value is placed into:
 *             ord    an ordinary map and box (|m| <= 3, box in [-4, 3]);
 *             point  a point box: lo == hi on every axis, h == 0 (for
 *                    sphere_box the linear part is 0, for ellipsoid_box
 *                    the radii are 0: the image is a point);
 *             empty  axis 1 empty: lo[1] > hi[1], h[1] = -1 (the four
 *                    box functions only);
 *             half   ord with lo[0] = -inf and hi[2] = +inf: two half-lines
 *                    (transform_box and box_to_cbox only);
 *             zcol   ord with column 1 of the map zero (+0, -0, +0 in rows
 *                    0, 1, 2) against c[1] = h[1] = +inf: every row drops
 *                    that column (transform_cbox only);
 *   pos     the one input position overwritten: m[i][j] (j = 3 is the
 *           translation), lo[j], hi[j], c[j], h[j], center[i], radii[j],
 *           rot[i][j] (every input of the function);
 *   val     the value written there, from vals[] below: NaN, -NaN, +inf,
 *           -inf, +0, -0, -+ smallest subnormal, largest subnormal,
 *           smallest normal, -+ DBL_MAX, -+ 1, and -+ each documented
 *           domain limit 2^254, 2^509, 2^1018, 2^1019 (just inside) and
 *           the next double above it in magnitude (just outside);
 *   expect  the status certbox.h's rules give (oracle(), written from the
 *           header and specs/cbx_spec.h, independently of the library and
 *           of exact_util; for transform_box and transform_cbox it is also
 *           cross-checked against exact_util's oracle, status and ends,
 *           check "oracle");
 *   ends    per output axis, the kind of its lower and its upper end (OK and
 *           ERANGE rows; enum E_A.. below, printed "AFULW"):
 *             A  in the domain: the kernel's finite end (transform_box: a
 *                full row, every input of the row finite and in the domain);
 *             F  transform_box, a finite map row that is not full (an
 *                infinite box end, or a box end outside the domain): the
 *                end from its vertex v_j = lo_j (m_j > 0), hi_j (m_j < 0),
 *                0 (m_j == 0, also -0; 0 * inf = 0), mirrored for the upper
 *                end, with the vertex in the domain: finite;
 *             U  transform_box, that vertex needs an infinite box end: the
 *                image is unbounded there; exactly -inf / +inf, no loss;
 *             L  transform_box, the vertex is outside the domain: exactly
 *                -inf / +inf, a loss;
 *             D  transform_cbox, a row that is not full but is once its
 *                zero-coefficient columns are dropped (c_j = h_j = 0 where
 *                m_j == 0, also -0; 0 * x = 0 whatever c_j, h_j, +-inf
 *                included; the map row finite and in the domain with those
 *                values): the kernel on the dropped row, finite (both ends
 *                of the axis);
 *             W  the whole axis is the whole line, a loss (transform_box:
 *                an infinite map entry; transform_cbox: not full even after
 *                dropping; the others: outside the domain).
 *           ERANGE iff some end is L or W.  A box axis with no real point
 *           (hi < lo, lo = +inf or hi = -inf) is EMPTY (transform_box,
 *           box_to_cbox).
 *
 * For every row, checks (a failure of any one fails the row):
 *   status     the status equals expect;
 *   out-set    the output was pre-filled with a NaN sentinel bit pattern;
 *              none of it may remain (no function documents a NaN output);
 *   nan-out    no other NaN in the output either;
 *   special    EINVAL: the whole space ([-inf,+inf]^3, or c = 0, h = +inf),
 *              EMPTY: the empty box (lo = +inf, hi = -inf, or c = 0,
 *              h = -inf), exactly, on every axis;
 *   whole      W axes exactly the whole line ([-inf, +inf], or c = 0,
 *              h = +inf);
 *   inf-end    U and L ends exactly -inf (lower) / +inf (upper);
 *   v-finite   F ends finite;
 *   v-contain  F ends on the right side of the exact vertex value
 *              V = t + sum_j m_j v_j (the exact inf / sup of the image over
 *              the real points of the box; mpq);
 *   v-tight    F ends within 12 u S_v + 2^-1065 of V, S_v = |t| +
 *              sum_j |m_j v_j| (exact, mpq);
 *   finite     A and D axes finite (and lo <= hi, h >= 0);
 *   contain    A and D axes contain the exact image (D: of the dropped
 *              box, where a dropped column adds exactly 0), decided exactly
 *              with GMP: boxes by the 8 corners (mpq_t), the conversions by
 *              the exact ends c -+ h / lo, hi, spheres and ellipsoids by
 *              lo <= t - sqrt(s) <=> t - lo >= 0 and (t - lo)^2 >= s
 *              (xu_sqrt_lo_ok / xu_sqrt_hi_ok; s exact);
 *   tight      transform_box: the proven bound of certbox.h (each end within
 *              12 u S + 2^-1065 of the exact end); transform_cbox: the same
 *              bound of specs/cbx_spec.h (cbox_tight; D axes: on the dropped
 *              row, 12 u S' + 2^-1065 with S' = |t| + sum_j |m_j c_j'| +
 *              |m_j h_j'|); the others (no bound
 *              is documented): a loose sanity bound, each end within
 *              2^-40 * (magnitude) + 2^-1060 (conversions) or + 2^-500
 *              (sphere, ellipsoid) of the exact end, only to catch a
 *              grossly wide box that would pass "contain";
 *   inputs     the inputs are unchanged.
 * Printed: one line per (function, position) with the expected statuses
 * and failures, per function the rows checked and failed (and, for
 * transform_box and transform_cbox, the ends of each kind per base
 * input), per check the items checked and
 * failed; -v prints every row with its ends.  The first failures are
 * printed with their inputs and outputs in hex (a reproducer).
 * Last line: "N passed, M failed" (rows); exit status 1 on failure.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <math.h>

#include "certbox.h"
#include "exact_util.h"

#define INF HUGE_VAL
#define MAX_FAIL_LOGS 30

/* ---------------------------------------------------------------------- */
/* The columns' values                                                    */
/* ---------------------------------------------------------------------- */

enum { FN_TBOX, FN_TCBOX, FN_B2C, FN_C2B, FN_SPH, FN_ELL, NFN };
static const char *const fn_name[NFN] = {
    "transform_box", "transform_cbox", "box_to_cbox", "cbox_to_box",
    "sphere_box", "ellipsoid_box"
};
/* positions per function (see slot()) and base inputs per function */
static const int fn_npos[NFN] = { 18, 18, 6, 6, 12, 15 };
/* bit b set: base input b is used with the function */
static const unsigned fn_bases[NFN] = { 0x0f, 0x17, 0x0f, 0x07, 0x03, 0x03 };
/* output form: 1 = cbx_cbox, 0 = cbx_box */
static const int fn_cout[NFN] = { 0, 1, 1, 0, 0, 0 };

enum { B_ORD, B_POINT, B_EMPTY, B_HALF, B_ZCOL, NBASE };
static const char *const base_name[NBASE] = { "ord", "point", "empty", "half", "zcol" };

typedef struct sval { const char *name; double v; } sval;
static const sval vals[] = {
    { "NaN", NAN },
    { "-NaN", -NAN },
    { "+inf", INF },
    { "-inf", -INF },
    { "+0", 0.0 },
    { "-0", -0.0 },
    { "2^-1074", 0x1p-1074 },             /* smallest subnormal        */
    { "-2^-1074", -0x1p-1074 },
    { "maxsub", 0x0.fffffffffffffp-1022 }, /* largest subnormal         */
    { "2^-1022", 0x1p-1022 },             /* smallest normal (DBL_MIN) */
    { "1", 1.0 },
    { "-1", -1.0 },
    { "2^254", 0x1p254 },                 /* ellipsoid limit: inside   */
    { "2^254+", 0x1.0000000000001p254 },  /*                  outside  */
    { "-2^254", -0x1p254 },
    { "-2^254-", -0x1.0000000000001p254 },
    { "2^509", 0x1p509 },                 /* sphere / class 509 limit  */
    { "2^509+", 0x1.0000000000001p509 },
    { "-2^509", -0x1p509 },
    { "-2^509-", -0x1.0000000000001p509 },
    { "2^1018", 0x1p1018 },               /* translation / coordinate  */
    { "2^1018+", 0x1.0000000000001p1018 },
    { "-2^1018", -0x1p1018 },
    { "-2^1018-", -0x1.0000000000001p1018 },
    { "2^1019", 0x1p1019 },               /* conversions' limit        */
    { "2^1019+", 0x1.0000000000001p1019 },
    { "-2^1019", -0x1p1019 },
    { "-2^1019-", -0x1.0000000000001p1019 },
    { "DBL_MAX", DBL_MAX },
    { "-DBL_MAX", -DBL_MAX },
};
#define NVAL ((int)(sizeof vals / sizeof vals[0]))

/* What one output end must be (column "ends"; printed as a letter):
 *   A  in the domain: the kernel's finite end (transform_box: a full row,
 *      every input of the row finite and in the domain; the 8-corner
 *      containment and the proven 12 u S + 2^-1065);
 *   F  transform_box, a finite map row that is not full: finite, from the
 *      vertex (v_j = lo_j if m_j > 0, hi_j if m_j < 0, 0 if m_j == 0;
 *      mirrored for the upper end) in the domain: on the right side of
 *      t + sum m_j v_j and within 12 u S_v + 2^-1065, S_v = |t| + sum
 *      |m_j v_j| (exact, mpq);
 *   U  transform_box: the image is unbounded on that side (the vertex
 *      needs an infinite box end): exactly -inf / +inf, not a loss;
 *   L  transform_box: the vertex is outside the domain: exactly -inf /
 *      +inf, a loss (CBX_ERANGE);
 *   W  the whole line (both ends of the axis), a loss: an infinite map
 *      entry (transform_box), not full even with its zero-coefficient
 *      columns dropped (transform_cbox), or outside the domain (the other
 *      functions);
 *   D  transform_cbox, both ends of an axis whose row is full only once
 *      its zero-coefficient columns are dropped (c_j = h_j = 0 where
 *      m_j == 0): the kernel on the dropped row, finite, checked like A on
 *      the dropped box. */
enum { E_A, E_F, E_U, E_L, E_W, E_D, NEND };
static const char end_char[NEND + 1] = "AFULWD";

/* One table row (see the header comment). */
typedef struct row {
    int fn, base, pos, val;
    cbx_status expect;
    unsigned char end[3][2]; /* [axis][0 lower, 1 upper] (not EINVAL/EMPTY) */
} row;

/* Every input any function reads. */
typedef struct input {
    cbx_affine a;
    cbx_box b;
    cbx_cbox cb;
    double center[3], radii[3], rot[3][3];
} input;

typedef struct output {
    cbx_box b;
    cbx_cbox cb;
} output;

/* ---------------------------------------------------------------------- */
/* Base inputs                                                            */
/* ---------------------------------------------------------------------- */

/* |m| <= 3: deep in the domain; column entries of magnitude <= 1 and > 1
 * both occur, so a coordinate of 2^1018 puts some rows in and some out. */
static const cbx_affine base_a = { {
    { 0.5, -2, 0.25, 1 },
    { 3, 0.125, -1, -4 },
    { -0.75, 1.5, 2, 0.5 },
} };
static const cbx_box ord_box = { { -1, 0.5, -4 }, { 2, 3, -1 } };
/* same box as ord_box, as centre / half */
static const cbx_cbox ord_cbox = { { 0.5, 1.75, -2.5 }, { 1.5, 1.25, 1.5 } };
/* a point with a zero coordinate (m = inf times 0) and |c| <= 1
 * (m = 2^1018 then stays in the domain) */
static const double point_c[3] = { 0.0, -0.5, 1.0 };

static const double ell_center[3] = { 1, -4, 0.5 };
static const double ell_radii[3] = { 1.5, 0.25, -2 };   /* negative is valid */
static const double ell_rot[3][3] = {                   /* not orthogonal    */
    { 0.5, -2, 0.25 }, { 3, 0.125, -1 }, { -0.75, 1.5, 2 }
};

static void base_input(int fn, int base, input *in)
{
    int i, j;
    memset(in, 0, sizeof *in);
    in->a = base_a;
    in->b = ord_box;
    in->cb = ord_cbox;
    memcpy(in->center, ell_center, sizeof in->center);
    memcpy(in->radii, ell_radii, sizeof in->radii);
    memcpy(in->rot, ell_rot, sizeof in->rot);
    if (base == B_POINT) {
        for (j = 0; j < 3; j++) {
            in->b.lo[j] = in->b.hi[j] = point_c[j];
            in->cb.c[j] = point_c[j];
            in->cb.h[j] = 0.0;
        }
        if (fn == FN_SPH)
            for (i = 0; i < 3; i++)
                for (j = 0; j < 3; j++) in->a.m[i][j] = 0.0;
        for (j = 0; j < 3; j++) in->radii[j] = 0.0;
    } else if (base == B_EMPTY) {
        in->b.lo[1] = 3.5;   /* > hi[1] = 3 */
        in->cb.h[1] = -1.0;
    } else if (base == B_HALF) {
        in->b.lo[0] = -INF;  /* x0 <= 2 */
        in->b.hi[2] = INF;   /* x2 >= -4 */
    } else if (base == B_ZCOL) {
        in->a.m[0][1] = 0.0; /* column 1 zero, both signs */
        in->a.m[1][1] = -0.0;
        in->a.m[2][1] = 0.0;
        in->cb.c[1] = INF;   /* unusable unless dropped */
        in->cb.h[1] = INF;
    }
}

/* The address of position pos of function fn in *in. */
static double *slot(input *in, int fn, int pos)
{
    switch (fn) {
    case FN_TBOX:
        if (pos < 12) return &in->a.m[pos / 4][pos % 4];
        return pos < 15 ? &in->b.lo[pos - 12] : &in->b.hi[pos - 15];
    case FN_TCBOX:
        if (pos < 12) return &in->a.m[pos / 4][pos % 4];
        return pos < 15 ? &in->cb.c[pos - 12] : &in->cb.h[pos - 15];
    case FN_B2C:
        return pos < 3 ? &in->b.lo[pos] : &in->b.hi[pos - 3];
    case FN_C2B:
        return pos < 3 ? &in->cb.c[pos] : &in->cb.h[pos - 3];
    case FN_SPH:
        return &in->a.m[pos / 4][pos % 4];
    default:
        if (pos < 3) return &in->center[pos];
        if (pos < 6) return &in->radii[pos - 3];
        return &in->rot[(pos - 6) / 3][(pos - 6) % 3];
    }
}

static void pos_name(int fn, int pos, char *buf, size_t n)
{
    switch (fn) {
    case FN_TBOX:
    case FN_TCBOX:
        if (pos < 12) snprintf(buf, n, "m[%d][%d]%s", pos / 4, pos % 4, pos % 4 == 3 ? " (t)" : "");
        else snprintf(buf, n, "%s[%d]", pos < 15 ? (fn == FN_TBOX ? "lo" : "c")
                                            : (fn == FN_TBOX ? "hi" : "h"), (pos - 12) % 3);
        break;
    case FN_B2C: snprintf(buf, n, "%s[%d]", pos < 3 ? "lo" : "hi", pos % 3); break;
    case FN_C2B: snprintf(buf, n, "%s[%d]", pos < 3 ? "c" : "h", pos % 3); break;
    case FN_SPH:
        snprintf(buf, n, "m[%d][%d]%s", pos / 4, pos % 4, pos % 4 == 3 ? " (t)" : "");
        break;
    default:
        if (pos < 3) snprintf(buf, n, "center[%d]", pos);
        else if (pos < 6) snprintf(buf, n, "radii[%d]", pos - 3);
        else snprintf(buf, n, "rot[%d][%d]", (pos - 6) / 3, (pos - 6) % 3);
    }
}

static void make_input(const row *r, input *in)
{
    base_input(r->fn, r->base, in);
    *slot(in, r->fn, r->pos) = vals[r->val].v;
}

/* ---------------------------------------------------------------------- */
/* The oracle: certbox.h's rules, written out again                       */
/* ---------------------------------------------------------------------- */

static int nan_(double x) { return x != x; }
/* |x| <= 2^k, exactly (ldexp of 1 is exact; false for NaN and inf) */
static int mag_le(double x, int k) { return fabs(x) <= ldexp(1.0, k); }

/* (m, c): both finite and |m| <= 2^k, |c| <= 2^(1018-k) for some
 * k in {0, 64, ..., 960, 509, 1018} (certbox.h, "Proven domain"). */
static int pair_dom(double m, double c)
{
    int k;
    if (!isfinite(m) || !isfinite(c)) return 0;
    for (k = 0; k <= 960; k += 64)
        if (mag_le(m, k) && mag_le(c, 1018 - k)) return 1;
    return (mag_le(m, 509) && mag_le(c, 509)) || (mag_le(m, 1018) && mag_le(c, 0));
}

/* Row i of transform_box / transform_cbox: the pairs with p[j] and q[j]
 * (lo/hi or c/h), and a finite translation of magnitude <= 2^1018. */
static int affine_row_dom(const cbx_affine *a, const double p[3], const double q[3], int i)
{
    int j;
    for (j = 0; j < 3; j++)
        if (!pair_dom(a->m[i][j], p[j]) || !pair_dom(a->m[i][j], q[j])) return 0;
    return isfinite(a->m[i][3]) && mag_le(a->m[i][3], 1018);
}

static int affine_nan(const cbx_affine *a)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++)
            if (nan_(a->m[i][j])) return 1;
    return 0;
}

static int nan3(const double v[3]) { return nan_(v[0]) || nan_(v[1]) || nan_(v[2]); }

static int is_pinf(double d) { return isinf(d) && d > 0; }
static int is_ninf(double d) { return isinf(d) && d < 0; }

/* [lo, hi] has no real point: hi < lo, lo = +inf or hi = -inf. */
static int no_point(double lo, double hi)
{
    return hi < lo || is_pinf(lo) || is_ninf(hi);
}

/* transform_box, one end of a finite map row that is not full: U when
 * the coordinate it needs is infinite, else F when the vertex is in the
 * domain, else L.  v[] receives the vertex (when not U). */
static int tbox_end(const input *in, int i, int upper, double v[3])
{
    int j, kind = E_F;
    for (j = 0; j < 3; j++) {
        double m = in->a.m[i][j];
        /* the lower end needs hi_j when m < 0, the upper end when m > 0 */
        int needs_hi = upper ? m > 0 : m < 0;
        double c = needs_hi ? in->b.hi[j] : in->b.lo[j];
        if (m == 0) {
            v[j] = 0.0;             /* 0 * x = 0 for every real x */
            continue;
        }
        if (isinf(c)) return E_U;   /* a half-line: m x has no bound there */
        v[j] = c;
    }
    for (j = 0; j < 3; j++)
        if (!pair_dom(in->a.m[i][j], v[j])) kind = E_L;
    if (!mag_le(in->a.m[i][3], 1018)) kind = E_L;
    return kind;
}

static int row_map_finite(const cbx_affine *a, int i)
{
    return isfinite(a->m[i][0]) && isfinite(a->m[i][1]) && isfinite(a->m[i][2])
           && isfinite(a->m[i][3]);
}

/* transform_cbox, row i with its zero-coefficient columns dropped: c_j and
 * h_j replaced by 0 where m_ij == 0 (+0 or -0; 0 * x = 0 for every real x,
 * so the image does not depend on x_j), copied elsewhere. */
static void tcbox_drop(const input *in, int i, double dc[3], double dh[3])
{
    int j;
    for (j = 0; j < 3; j++) {
        int z = in->a.m[i][j] == 0;
        dc[j] = z ? 0.0 : in->cb.c[j];
        dh[j] = z ? 0.0 : in->cb.h[j];
    }
}

static void set_axis(unsigned char end[3][2], int i, int lo, int hi)
{
    end[i][0] = (unsigned char)lo;
    end[i][1] = (unsigned char)hi;
}

/* Expected status; end[][] = the kind of every output end (A F U L W). */
static cbx_status oracle(int fn, const input *in, unsigned char end[3][2])
{
    int i, j, loss = 0;
    double v[3];
    for (i = 0; i < 3; i++) set_axis(end, i, E_A, E_A);
    switch (fn) {
    case FN_TBOX:
        if (affine_nan(&in->a) || nan3(in->b.lo) || nan3(in->b.hi)) return CBX_EINVAL;
        for (j = 0; j < 3; j++)
            if (no_point(in->b.lo[j], in->b.hi[j])) return CBX_EMPTY;
        for (i = 0; i < 3; i++) {
            int k;
            if (affine_row_dom(&in->a, in->b.lo, in->b.hi, i)) continue; /* A */
            if (!row_map_finite(&in->a, i)) {
                set_axis(end, i, E_W, E_W);
                loss = 1;
                continue;
            }
            for (k = 0; k < 2; k++) {
                end[i][k] = (unsigned char)tbox_end(in, i, k, v);
                if (end[i][k] == E_L) loss = 1;
            }
        }
        return loss ? CBX_ERANGE : CBX_OK;
    case FN_TCBOX:
        if (affine_nan(&in->a) || nan3(in->cb.c) || nan3(in->cb.h)) return CBX_EINVAL;
        for (j = 0; j < 3; j++)
            if (in->cb.h[j] < 0) return CBX_EMPTY;
        for (i = 0; i < 3; i++) {
            double dc[3], dh[3];
            if (affine_row_dom(&in->a, in->cb.c, in->cb.h, i)) continue; /* A */
            tcbox_drop(in, i, dc, dh);
            if (row_map_finite(&in->a, i) && affine_row_dom(&in->a, dc, dh, i))
                set_axis(end, i, E_D, E_D);
            else
                set_axis(end, i, E_W, E_W);
        }
        break;
    case FN_B2C:
        if (nan3(in->b.lo) || nan3(in->b.hi)) return CBX_EINVAL;
        for (j = 0; j < 3; j++)
            if (no_point(in->b.lo[j], in->b.hi[j])) return CBX_EMPTY;
        for (j = 0; j < 3; j++)
            if (!(isfinite(in->b.lo[j]) && isfinite(in->b.hi[j])
                  && mag_le(in->b.lo[j], 1019) && mag_le(in->b.hi[j], 1019)))
                set_axis(end, j, E_W, E_W);
        break;
    case FN_C2B:
        if (nan3(in->cb.c) || nan3(in->cb.h)) return CBX_EINVAL;
        for (j = 0; j < 3; j++)
            if (in->cb.h[j] < 0) return CBX_EMPTY;
        for (j = 0; j < 3; j++)
            if (!(isfinite(in->cb.c[j]) && isfinite(in->cb.h[j])
                  && mag_le(in->cb.c[j], 1019) && mag_le(in->cb.h[j], 1019)))
                set_axis(end, j, E_W, E_W);
        break;
    case FN_SPH:
        if (affine_nan(&in->a)) return CBX_EINVAL;
        for (i = 0; i < 3; i++) {
            int ok = isfinite(in->a.m[i][3]) && mag_le(in->a.m[i][3], 1018);
            for (j = 0; j < 3; j++)
                ok = ok && isfinite(in->a.m[i][j]) && mag_le(in->a.m[i][j], 509);
            if (!ok) set_axis(end, i, E_W, E_W);
        }
        break;
    default:
        if (nan3(in->center) || nan3(in->radii) || nan3(in->rot[0]) || nan3(in->rot[1])
            || nan3(in->rot[2]))
            return CBX_EINVAL;
        for (i = 0; i < 3; i++) {
            int ok = isfinite(in->center[i]) && mag_le(in->center[i], 1018);
            for (j = 0; j < 3; j++)
                ok = ok && isfinite(in->rot[i][j]) && mag_le(in->rot[i][j], 254)
                     && isfinite(in->radii[j]) && mag_le(in->radii[j], 254);
            if (!ok) set_axis(end, i, E_W, E_W);
        }
    }
    for (i = 0; i < 3; i++)
        if (end[i][0] == E_W) loss = 1;
    return loss ? CBX_ERANGE : CBX_OK;
}

/* The end kinds as "ab cd ef" (s: at least 9 chars). */
static void ends_str(const unsigned char end[3][2], char *s)
{
    int i, n = 0;
    for (i = 0; i < 3; i++) {
        if (i) s[n++] = ' ';
        s[n++] = end_char[end[i][0]];
        s[n++] = end_char[end[i][1]];
    }
    s[n] = '\0';
}

/* exact_util's oracle, where it has one (-1: none): the status and the
 * end kinds as a string like ends_str()'s ("" for EINVAL / EMPTY). */
static int xu_oracle(int fn, const input *in, cbx_status *st, char ends[9])
{
    int i;
    ends[0] = '\0';
    if (fn == FN_TBOX) {
        *st = xu_expected_status(&in->a, &in->b);
        if (*st == CBX_OK || *st == CBX_ERANGE) xu_ends_str(&in->a, &in->b, ends);
        return 0;
    }
    if (fn == FN_TCBOX) {
        *st = xu_cbox_expected_status(&in->a, &in->cb);
        if (*st == CBX_OK || *st == CBX_ERANGE) {
            unsigned char e[3][2];
            for (i = 0; i < 3; i++) {
                int kd = xu_cbox_axis_kind(&in->a, &in->cb, i);
                int ek = kd == XU_CAX_FULL ? E_A : kd == XU_CAX_DROP ? E_D : E_W;
                set_axis(e, i, ek, ek);
            }
            ends_str((const unsigned char (*)[2])e, ends);
        }
        return 0;
    }
    return -1;
}

/* ---------------------------------------------------------------------- */
/* Checks                                                                 */
/* ---------------------------------------------------------------------- */

enum { C_ORACLE, C_STATUS, C_UNSET, C_NANOUT, C_SPECIAL, C_WHOLE, C_FINITE,
       C_CONTAIN, C_TIGHT, C_INFEND, C_VFINITE, C_VCONTAIN, C_VTIGHT, C_INPUT, NCHECK };
static const char *const check_name[NCHECK] = {
    "oracle", "status", "out-set", "nan-out", "special", "whole", "finite",
    "contain", "tight", "inf-end", "v-finite", "v-contain", "v-tight", "inputs"
};
static const char *const check_unit[NCHECK] = {
    "rows", "rows", "rows", "rows", "rows", "axes", "axes", "axes", "axes",
    "ends", "ends", "ends", "ends", "rows"
};

typedef struct ctx {
    xu_exact x;
    mpq_t q, qa, qb, qc, qlo, qhi, tol, eps, eta;
    mpz_t s, z;
    long applied[NCHECK], failed[NCHECK];
    /* the current row */
    int flag[NCHECK];
    int row_failed;
    char why[200];
} ctx;

static void ctx_init(ctx *k)
{
    memset(k, 0, sizeof *k);
    xu_init(&k->x);
    mpq_inits(k->q, k->qa, k->qb, k->qc, k->qlo, k->qhi, k->tol, k->eps, k->eta, (mpq_ptr)0);
    mpz_inits(k->s, k->z, (mpz_ptr)0);
}

static void ctx_clear(ctx *k)
{
    xu_clear(&k->x);
    mpq_clears(k->q, k->qa, k->qb, k->qc, k->qlo, k->qhi, k->tol, k->eps, k->eta, (mpq_ptr)0);
    mpz_clears(k->s, k->z, (mpz_ptr)0);
}

static void apply(ctx *k, int c) { k->applied[c]++; }

static void fail(ctx *k, int c, const char *fmt, int axis)
{
    if (!k->flag[c]) k->failed[c]++;
    k->flag[c] = 1;
    if (!k->row_failed) snprintf(k->why, sizeof k->why, fmt, axis);
    k->row_failed = 1;
}

/* q = 2^-e */
static void q_pow2m(mpq_t q, unsigned e)
{
    mpq_set_ui(q, 1, 1);
    mpq_div_2exp(q, q, e);
}

/* k->tol = 2^-40 * mag + 2^-eta_e (mag >= 0, in k->qc) */
static void loose_tol(ctx *k, unsigned eta_e)
{
    q_pow2m(k->tol, 40);
    mpq_mul(k->tol, k->tol, k->qc);
    q_pow2m(k->eta, eta_e);
    mpq_add(k->tol, k->tol, k->eta);
}

static void q_abs_add(mpq_t acc, const mpq_t v)
{
    if (mpq_sgn(v) >= 0) mpq_add(acc, acc, v);
    else mpq_sub(acc, acc, v);
}

/* transform_box, in-domain axis i */
static void axis_tbox(ctx *k, const input *in, const cbx_box *o, int i)
{
    double lo = o->lo[i], hi = o->hi[i];
    apply(k, C_FINITE);
    if (!isfinite(lo) || !isfinite(hi) || lo > hi) {
        fail(k, C_FINITE, "axis %d in the domain but not finite with lo <= hi", i);
        return;
    }
    apply(k, C_CONTAIN);
    if (xu_corner_failures(&k->x, &in->a, &in->b, i, lo, hi))
        fail(k, C_CONTAIN, "axis %d: a corner's exact image is outside [lo, hi]", i);
    apply(k, C_TIGHT);
    xu_row_bounds(&k->x, &in->a, &in->b, i);
    if (!xu_lo_within_proven(&k->x, lo) || !xu_hi_within_proven(&k->x, hi))
        fail(k, C_TIGHT, "axis %d: an end beyond the proven 12 u S + 2^-1065", i);
}

/* transform_box, one end of kind F (upper = 0: the lower end): with
 * V = t + sum_j m_j v_j and S_v = |t| + sum_j |m_j v_j| over the vertex v
 * (exact, mpq): lo <= V and lo >= V - (12 u S_v + 2^-1065), mirrored for
 * the upper end.  V is the exact inf (sup) of the image over the real
 * points of the box (infinite box ends read as half-lines). */
static void end_tbox(ctx *k, const input *in, const cbx_box *o, int i, int upper)
{
    double e = upper ? o->hi[i] : o->lo[i], v[3];
    int j;
    apply(k, C_VFINITE);
    if (!isfinite(e)) {
        fail(k, C_VFINITE, "axis %d: an end whose vertex is in the domain is not finite", i);
        return;
    }
    tbox_end(in, i, upper, v);
    mpq_set_d(k->q, in->a.m[i][3]);          /* V   */
    mpq_abs(k->qc, k->q);                    /* S_v */
    for (j = 0; j < 3; j++) {
        mpq_set_d(k->qa, in->a.m[i][j]);
        mpq_set_d(k->qb, v[j]);
        mpq_mul(k->qa, k->qa, k->qb);
        mpq_add(k->q, k->q, k->qa);
        q_abs_add(k->qc, k->qa);
    }
    mpq_set_d(k->qlo, e);
    apply(k, C_VCONTAIN);
    if (upper ? mpq_cmp(k->qlo, k->q) < 0 : mpq_cmp(k->qlo, k->q) > 0)
        fail(k, C_VCONTAIN, "axis %d: a finite end is inside the exact inf / sup of the image", i);
    /* tol = 3 * 2^-51 S_v + 2^-1065 = 12 u S_v + 2^-1065 */
    q_pow2m(k->tol, 51);
    mpq_mul(k->tol, k->tol, k->qc);
    mpq_set_ui(k->eta, 3, 1);
    mpq_mul(k->tol, k->tol, k->eta);
    q_pow2m(k->eta, 1065);
    mpq_add(k->tol, k->tol, k->eta);
    if (upper) mpq_add(k->qa, k->q, k->tol);
    else mpq_sub(k->qa, k->q, k->tol);
    apply(k, C_VTIGHT);
    if (upper ? mpq_cmp(k->qlo, k->qa) > 0 : mpq_cmp(k->qlo, k->qa) < 0)
        fail(k, C_VTIGHT, "axis %d: an end beyond 12 u S_v + 2^-1065 of its vertex value", i);
}

/* transform_cbox, axis i of kind A (c, h: the input box) or D (c, h: the
 * dropped box of row i, tcbox_drop): the 8 corners c_j -+ h_j, and
 * cbox_tight of specs/cbx_spec.h on that box (for D: S' of the dropped
 * row). */
static void axis_tcbox(ctx *k, const input *in, const double c[3], const double h[3],
                       const cbx_cbox *o, int i)
{
    double oc = o->c[i], oh = o->h[i];
    unsigned cb;
    int j, bad = 0;
    apply(k, C_FINITE);
    if (!isfinite(oc) || !isfinite(oh) || oh < 0) {
        fail(k, C_FINITE, "axis %d (A or D) but c, h not finite with h >= 0", i);
        return;
    }
    mpq_set_d(k->qa, oc);
    mpq_set_d(k->qb, oh);
    mpq_sub(k->qlo, k->qa, k->qb);
    mpq_add(k->qhi, k->qa, k->qb);
    apply(k, C_CONTAIN);
    for (cb = 0; cb < 8; cb++) {
        mpq_set_d(k->q, in->a.m[i][3]);
        for (j = 0; j < 3; j++) {
            mpq_set_d(k->qa, c[j]);
            mpq_set_d(k->qb, h[j]);
            if ((cb >> j) & 1u) mpq_add(k->qa, k->qa, k->qb);
            else mpq_sub(k->qa, k->qa, k->qb);
            mpq_set_d(k->qb, in->a.m[i][j]);
            mpq_mul(k->qa, k->qa, k->qb);
            mpq_add(k->q, k->q, k->qa);
        }
        if (mpq_cmp(k->qlo, k->q) > 0 || mpq_cmp(k->q, k->qhi) > 0) bad++;
    }
    if (bad) fail(k, C_CONTAIN, "axis %d: a corner's exact image is outside [c - h, c + h]", i);
    /* C = t + sum m c, Hh = sum |m h|, Mag = |t| + sum |m c| + Hh */
    apply(k, C_TIGHT);
    mpq_set_d(k->q, in->a.m[i][3]);          /* C   */
    mpq_abs(k->qc, k->q);                    /* Mag */
    mpq_set_ui(k->tol, 0, 1);                /* Hh  */
    for (j = 0; j < 3; j++) {
        mpq_set_d(k->qa, in->a.m[i][j]);
        mpq_set_d(k->qb, c[j]);
        mpq_mul(k->qb, k->qb, k->qa);
        mpq_add(k->q, k->q, k->qb);
        q_abs_add(k->qc, k->qb);
        mpq_set_d(k->qb, h[j]);
        mpq_mul(k->qb, k->qb, k->qa);
        q_abs_add(k->tol, k->qb);
    }
    mpq_add(k->qc, k->qc, k->tol);
    /* qa = C - Hh - (3 * 2^-51 Mag + 2^-1065); qb = C + Hh + (...) */
    q_pow2m(k->eta, 51);
    mpq_mul(k->qc, k->qc, k->eta);
    mpq_set_ui(k->eta, 3, 1);
    mpq_mul(k->qc, k->qc, k->eta);
    q_pow2m(k->eta, 1065);
    mpq_add(k->qc, k->qc, k->eta);
    mpq_sub(k->qa, k->q, k->tol);
    mpq_sub(k->qa, k->qa, k->qc);
    mpq_add(k->qb, k->q, k->tol);
    mpq_add(k->qb, k->qb, k->qc);
    if (mpq_cmp(k->qlo, k->qa) < 0 || mpq_cmp(k->qhi, k->qb) > 0)
        fail(k, C_TIGHT, "axis %d: an end beyond cbox_tight (12 u S + 2^-1065)", i);
}

/* box_to_cbox, in-domain axis j: c - h <= lo and hi <= c + h */
static void axis_b2c(ctx *k, const input *in, const cbx_cbox *o, int j)
{
    double c = o->c[j], h = o->h[j];
    apply(k, C_FINITE);
    if (!isfinite(c) || !isfinite(h) || h < 0) {
        fail(k, C_FINITE, "axis %d in the domain but c, h not finite with h >= 0", j);
        return;
    }
    mpq_set_d(k->qa, c);
    mpq_set_d(k->qb, h);
    mpq_sub(k->qlo, k->qa, k->qb);
    mpq_add(k->qhi, k->qa, k->qb);
    mpq_set_d(k->qa, in->b.lo[j]);
    mpq_set_d(k->qb, in->b.hi[j]);
    apply(k, C_CONTAIN);
    if (mpq_cmp(k->qlo, k->qa) > 0 || mpq_cmp(k->qb, k->qhi) > 0)
        fail(k, C_CONTAIN, "axis %d: [c - h, c + h] does not contain [lo, hi]", j);
    apply(k, C_TIGHT);
    mpq_abs(k->qc, k->qa);
    mpq_abs(k->q, k->qb);
    mpq_add(k->qc, k->qc, k->q);
    loose_tol(k, 1060);
    mpq_sub(k->qa, k->qa, k->tol);
    mpq_add(k->qb, k->qb, k->tol);
    if (mpq_cmp(k->qlo, k->qa) < 0 || mpq_cmp(k->qhi, k->qb) > 0)
        fail(k, C_TIGHT, "axis %d: an end beyond the sanity bound", j);
}

/* cbox_to_box, in-domain axis j: lo <= c - h and c + h <= hi */
static void axis_c2b(ctx *k, const input *in, const cbx_box *o, int j)
{
    double lo = o->lo[j], hi = o->hi[j];
    apply(k, C_FINITE);
    if (!isfinite(lo) || !isfinite(hi) || lo > hi) {
        fail(k, C_FINITE, "axis %d in the domain but not finite with lo <= hi", j);
        return;
    }
    mpq_set_d(k->qlo, lo);
    mpq_set_d(k->qhi, hi);
    mpq_set_d(k->qc, in->cb.c[j]);
    mpq_set_d(k->q, in->cb.h[j]);
    mpq_sub(k->qa, k->qc, k->q);
    mpq_add(k->qb, k->qc, k->q);
    apply(k, C_CONTAIN);
    if (mpq_cmp(k->qlo, k->qa) > 0 || mpq_cmp(k->qb, k->qhi) > 0)
        fail(k, C_CONTAIN, "axis %d: [lo, hi] does not contain [c - h, c + h]", j);
    apply(k, C_TIGHT);
    mpq_abs(k->qc, k->qc);
    mpq_abs(k->q, k->q);
    mpq_add(k->qc, k->qc, k->q);
    loose_tol(k, 1060);
    mpq_sub(k->qa, k->qa, k->tol);
    mpq_add(k->qb, k->qb, k->tol);
    if (mpq_cmp(k->qlo, k->qa) < 0 || mpq_cmp(k->qhi, k->qb) > 0)
        fail(k, C_TIGHT, "axis %d: an end beyond the sanity bound", j);
}

/* One side of the loose sanity bound of t -+ sqrt(s') (s' = s / 2^(2 sh)):
 * g = distance from t to the end (>= 0); ok iff
 * g <= (1 + 2^-40) sqrt(s') + 2^-40 |t| + 2^-500, decided on squares. */
static int sqrt_side_sane(ctx *k, unsigned long sh, double t, double end)
{
    mpq_set_d(k->qa, end);
    mpq_set_d(k->qb, t);
    mpq_sub(k->qa, k->qa, k->qb);
    mpq_abs(k->qa, k->qa);                   /* g */
    mpq_abs(k->qc, k->qb);
    loose_tol(k, 500);                       /* 2^-40 |t| + 2^-500 */
    mpq_sub(k->qa, k->qa, k->tol);
    if (mpq_sgn(k->qa) <= 0) return 1;
    mpq_mul(k->qa, k->qa, k->qa);
    mpq_set_z(k->q, k->s);                   /* s' (1 + 2^-40)^2 */
    mpq_div_2exp(k->q, k->q, 2 * sh);
    q_pow2m(k->qb, 40);
    mpq_set_ui(k->qc, 1, 1);
    mpq_add(k->qb, k->qb, k->qc);
    mpq_mul(k->qb, k->qb, k->qb);
    mpq_mul(k->q, k->q, k->qb);
    return mpq_cmp(k->qa, k->q) <= 0;
}

/* sphere_box / ellipsoid_box, in-domain axis i */
static void axis_ball(ctx *k, int fn, const input *in, const cbx_box *o, int i)
{
    double lo = o->lo[i], hi = o->hi[i], t;
    unsigned long sh;
    int j;
    apply(k, C_FINITE);
    if (!isfinite(lo) || !isfinite(hi) || lo > hi) {
        fail(k, C_FINITE, "axis %d in the domain but not finite with lo <= hi", i);
        return;
    }
    /* s = sum_j b_j^2 scaled by 2^(2 sh): b_j = m[i][j] (sh = 1074) or
     * rot[i][j] * radii[j] (sh = 2148, a product of two doubles) */
    mpz_set_ui(k->s, 0);
    if (fn == FN_SPH) {
        sh = 1074;
        t = in->a.m[i][3];
        for (j = 0; j < 3; j++) {
            xu_scaled_sh(k->z, in->a.m[i][j], sh);
            mpz_addmul(k->s, k->z, k->z);
        }
    } else {
        sh = XU_SHIFT;
        t = in->center[i];
        for (j = 0; j < 3; j++) {
            xu_scaled_mul(&k->x, k->z, in->rot[i][j], in->radii[j]);
            mpz_addmul(k->s, k->z, k->z);
        }
    }
    apply(k, C_CONTAIN);
    if (!xu_sqrt_lo_ok(&k->x, k->s, sh, t, lo) || !xu_sqrt_hi_ok(&k->x, k->s, sh, t, hi))
        fail(k, C_CONTAIN, "axis %d: [lo, hi] does not contain t -+ sqrt(s)", i);
    apply(k, C_TIGHT);
    if (!sqrt_side_sane(k, sh, t, lo) || !sqrt_side_sane(k, sh, t, hi))
        fail(k, C_TIGHT, "axis %d: an end beyond the sanity bound", i);
}

/* ---------------------------------------------------------------------- */
/* Running one row                                                        */
/* ---------------------------------------------------------------------- */

/* A quiet NaN with a recognisable payload: "not written". */
static const uint64_t SENTINEL_BITS = UINT64_C(0x7ff8dead5eed0bad);

static double sentinel(void)
{
    double d;
    memcpy(&d, &SENTINEL_BITS, sizeof d);
    return d;
}

static int is_sentinel(double d)
{
    uint64_t b;
    memcpy(&b, &d, sizeof b);
    return b == SENTINEL_BITS;
}

static cbx_status call(int fn, const input *in, output *o)
{
    switch (fn) {
    case FN_TBOX: return cbx_transform_box(&in->a, &in->b, &o->b);
    case FN_TCBOX: return cbx_transform_cbox(&in->a, &in->cb, &o->cb);
    case FN_B2C: return cbx_box_to_cbox(&in->b, &o->cb);
    case FN_C2B: return cbx_cbox_to_box(&in->cb, &o->b);
    case FN_SPH: return cbx_sphere_box(&in->a, &o->b);
    default:
        return cbx_ellipsoid_box(in->center, in->radii,
                                 (const double (*)[3])in->rot, &o->b);
    }
}


/* Output axis i is the whole line (kind 1) or empty (kind 0), exactly. */
static int special_axis(int cform, const output *o, int i, int whole)
{
    if (cform)
        return o->cb.c[i] == 0 && (whole ? is_pinf(o->cb.h[i]) : is_ninf(o->cb.h[i]));
    return whole ? is_ninf(o->b.lo[i]) && is_pinf(o->b.hi[i])
                 : is_pinf(o->b.lo[i]) && is_ninf(o->b.hi[i]);
}

typedef struct verdict {
    cbx_status got;
    output out;
    input in;
} verdict;

/* Output field n (0..5): lo[0..2], hi[0..2] or c[0..2], h[0..2]. */
static double *field(int cform, output *o, int n)
{
    if (cform) return n < 3 ? &o->cb.c[n] : &o->cb.h[n - 3];
    return n < 3 ? &o->b.lo[n] : &o->b.hi[n - 3];
}

static int run_row(ctx *k, const row *r, verdict *v)
{
    input in0;
    int n, i, cform = fn_cout[r->fn];
    cbx_status xst;
    char xends[9], ends[9];

    memset(k->flag, 0, sizeof k->flag);
    k->row_failed = 0;
    k->why[0] = '\0';

    make_input(r, &v->in);
    in0 = v->in;
    for (n = 0; n < 6; n++) *field(cform, &v->out, n) = sentinel();
    v->got = call(r->fn, &v->in, &v->out);

    apply(k, C_INPUT);
    if (memcmp(&in0, &v->in, sizeof in0) != 0) fail(k, C_INPUT, "the call modified its inputs", 0);

    if (xu_oracle(r->fn, &v->in, &xst, xends) == 0) {
        apply(k, C_ORACLE);
        ends_str((const unsigned char (*)[2])r->end, ends);
        if (xst != r->expect
            || ((r->expect == CBX_OK || r->expect == CBX_ERANGE) && strcmp(xends, ends) != 0))
            fail(k, C_ORACLE, "the table's oracle and exact_util's disagree", 0);
    }
    apply(k, C_STATUS);
    if (v->got != r->expect) fail(k, C_STATUS, "wrong status", 0);

    apply(k, C_UNSET);
    apply(k, C_NANOUT);
    for (n = 0; n < 6; n++) {
        double d = *field(cform, &v->out, n);
        if (is_sentinel(d)) fail(k, C_UNSET, "output field %d not written (sentinel left)", n);
        else if (nan_(d)) fail(k, C_NANOUT, "output field %d is a NaN", n);
    }

    if (r->expect == CBX_EINVAL || r->expect == CBX_EMPTY) {
        apply(k, C_SPECIAL);
        for (i = 0; i < 3; i++)
            if (!special_axis(cform, &v->out, i, r->expect == CBX_EINVAL)) {
                fail(k, C_SPECIAL, r->expect == CBX_EINVAL ? "EINVAL: axis %d is not the whole line"
                                                          : "EMPTY: axis %d is not empty", i);
                break;
            }
        return k->row_failed;
    }
    for (i = 0; i < 3; i++) {
        int e;
        if (r->end[i][0] == E_W) {
            apply(k, C_WHOLE);
            if (!special_axis(cform, &v->out, i, 1))
                fail(k, C_WHOLE, "axis %d (W) is not exactly the whole line", i);
            continue;
        }
        if (r->end[i][0] == E_D) { /* transform_cbox: the dropped row */
            double dc[3], dh[3];
            tcbox_drop(&v->in, i, dc, dh);
            axis_tcbox(k, &v->in, dc, dh, &v->out.cb, i);
            continue;
        }
        if (r->end[i][0] != E_A) { /* transform_box, each end on its own */
            for (e = 0; e < 2; e++) {
                double d = e ? v->out.b.hi[i] : v->out.b.lo[i];
                if (r->end[i][e] == E_F) {
                    end_tbox(k, &v->in, &v->out.b, i, e);
                    continue;
                }
                apply(k, C_INFEND);
                if (!(e ? is_pinf(d) : is_ninf(d)))
                    fail(k, C_INFEND, e ? "axis %d: the upper end must be +inf (unbounded or lost)"
                                        : "axis %d: the lower end must be -inf (unbounded or lost)",
                         i);
            }
            continue;
        }
        switch (r->fn) {
        case FN_TBOX: axis_tbox(k, &v->in, &v->out.b, i); break;
        case FN_TCBOX: axis_tcbox(k, &v->in, v->in.cb.c, v->in.cb.h, &v->out.cb, i); break;
        case FN_B2C: axis_b2c(k, &v->in, &v->out.cb, i); break;
        case FN_C2B: axis_c2b(k, &v->in, &v->out.b, i); break;
        default: axis_ball(k, r->fn, &v->in, &v->out.b, i); break;
        }
    }
    return k->row_failed;
}

/* ---------------------------------------------------------------------- */
/* The table                                                              */
/* ---------------------------------------------------------------------- */

static long make_table(row *t)
{
    long n = 0;
    int fn, b, p, v;
    for (fn = 0; fn < NFN; fn++)
        for (b = 0; b < NBASE; b++)
            if (fn_bases[fn] & (1u << b))
            for (p = 0; p < fn_npos[fn]; p++)
                for (v = 0; v < NVAL; v++) {
                    if (t) {
                        input in;
                        row *r = &t[n];
                        r->fn = fn;
                        r->base = b;
                        r->pos = p;
                        r->val = v;
                        make_input(r, &in);
                        r->expect = oracle(fn, &in, r->end);
                    }
                    n++;
                }
    return n;
}

static void print_row_id(FILE *fp, const row *r)
{
    char pn[32];
    pos_name(r->fn, r->pos, pn, sizeof pn);
    fprintf(fp, "%-14s %-5s %-13s = %-9s", fn_name[r->fn], base_name[r->base], pn,
            vals[r->val].name);
}

static void print_inputs(FILE *fp, int fn, const input *in)
{
    int i;
    switch (fn) {
    case FN_TBOX:
        xu_print_case(fp, &in->a, &in->b);
        break;
    case FN_TCBOX:
    case FN_SPH:
        for (i = 0; i < 3; i++)
            fprintf(fp, "  m[%d] = {%a, %a, %a | %a}\n", i, in->a.m[i][0], in->a.m[i][1],
                    in->a.m[i][2], in->a.m[i][3]);
        if (fn == FN_SPH) break;
        /* fall through */
    case FN_C2B:
        for (i = 0; i < 3; i++)
            fprintf(fp, "  in c[%d] = %a, h[%d] = %a\n", i, in->cb.c[i], i, in->cb.h[i]);
        break;
    case FN_B2C:
        xu_print_box(fp, "in", &in->b);
        break;
    default:
        for (i = 0; i < 3; i++)
            fprintf(fp, "  center[%d] = %a  radii[%d] = %a  rot[%d] = {%a, %a, %a}\n", i,
                    in->center[i], i, in->radii[i], i, in->rot[i][0], in->rot[i][1],
                    in->rot[i][2]);
    }
}

static void print_output(FILE *fp, int fn, const output *o)
{
    int i;
    if (fn_cout[fn])
        for (i = 0; i < 3; i++)
            fprintf(fp, "  out c[%d] = %a, h[%d] = %a\n", i, o->cb.c[i], i, o->cb.h[i]);
    else
        xu_print_box(fp, "out", &o->b);
}

int main(int argc, char **argv)
{
    static const cbx_status st_of[4] = { CBX_OK, CBX_EMPTY, CBX_EINVAL, CBX_ERANGE };
    int verbose = argc > 1 && strcmp(argv[1], "-v") == 0;
    long n, k, failed = 0, logs = 0;
    long fn_rows[NFN] = { 0 }, fn_fail[NFN] = { 0 }, fn_st[NFN][4];
    long tbox_ends[NBASE][NEND], tcbox_axes[NBASE][NEND];
    long pos_rows[NFN][18], pos_fail[NFN][18], pos_st[NFN][18][4];
    row *t;
    ctx c;
    int fn, p, s;

    if (argc > 2 || (argc == 2 && !verbose)) {
        fprintf(stderr, "usage: %s [-v]\n", argv[0]);
        return 2;
    }
    memset(fn_st, 0, sizeof fn_st);
    memset(tbox_ends, 0, sizeof tbox_ends);
    memset(tcbox_axes, 0, sizeof tcbox_axes);
    memset(pos_rows, 0, sizeof pos_rows);
    memset(pos_fail, 0, sizeof pos_fail);
    memset(pos_st, 0, sizeof pos_st);

    n = make_table(NULL);
    t = malloc((size_t)n * sizeof *t);
    if (!t) {
        fprintf(stderr, "out of memory\n");
        return 2;
    }
    make_table(t);
    ctx_init(&c);

    printf("-- special-value table: %d values x positions x base inputs x %d functions"
           " = %ld rows --\n", NVAL, NFN, n);
    for (k = 0; k < n; k++) {
        const row *r = &t[k];
        verdict v;
        int bad = run_row(&c, r, &v);
        int si = xu_status_index(r->expect);
        fn_rows[r->fn]++;
        pos_rows[r->fn][r->pos]++;
        if (r->fn == FN_TBOX && (r->expect == CBX_OK || r->expect == CBX_ERANGE)) {
            int i, e;
            for (i = 0; i < 3; i++)
                for (e = 0; e < 2; e++) tbox_ends[r->base][r->end[i][e]]++;
        }
        if (r->fn == FN_TCBOX && (r->expect == CBX_OK || r->expect == CBX_ERANGE)) {
            int i;
            for (i = 0; i < 3; i++) tcbox_axes[r->base][r->end[i][0]]++;
        }
        if (si >= 0) {
            fn_st[r->fn][si]++;
            pos_st[r->fn][r->pos][si]++;
        }
        if (bad) {
            failed++;
            fn_fail[r->fn]++;
            pos_fail[r->fn][r->pos]++;
        }
        if (verbose || (bad && logs < MAX_FAIL_LOGS)) {
            char ends[9] = "-";
            if (r->expect == CBX_OK || r->expect == CBX_ERANGE)
                ends_str((const unsigned char (*)[2])r->end, ends);
            printf("  ");
            print_row_id(stdout, r);
            printf(" expect %-10s got %-10s ends %-8s %s\n", cbx_status_name(r->expect),
                   cbx_status_name(v.got), ends, bad ? "FAIL" : "ok");
        }
        if (bad && logs < MAX_FAIL_LOGS) {
            logs++;
            printf("FAIL: %s\n", c.why);
            print_inputs(stdout, r->fn, &v.in);
            print_output(stdout, r->fn, &v.out);
        }
    }

    printf("\nper function and position (expected statuses; rows = base inputs x %d values):\n",
           NVAL);
    for (fn = 0; fn < NFN; fn++) {
        for (p = 0; p < fn_npos[fn]; p++) {
            char pn[32];
            pos_name(fn, p, pn, sizeof pn);
            printf("  %-14s %-13s %4ld rows: OK %3ld EMPTY %3ld EINVAL %3ld ERANGE %3ld  "
                   "%ld failed\n", fn_name[fn], pn, pos_rows[fn][p], pos_st[fn][p][0],
                   pos_st[fn][p][1], pos_st[fn][p][2], pos_st[fn][p][3], pos_fail[fn][p]);
        }
    }
    printf("\nper check:\n");
    for (s = 0; s < NCHECK; s++)
        printf("  check %-8s %7ld %-4s checked, %ld failed\n", check_name[s], c.applied[s],
               check_unit[s], c.failed[s]);
    printf("\nper function:\n");
    for (fn = 0; fn < NFN; fn++) {
        printf("  %-14s %5ld rows checked, %ld failed  (expected", fn_name[fn], fn_rows[fn],
               fn_fail[fn]);
        for (s = 0; s < 4; s++) printf(" %s %ld", cbx_status_name(st_of[s]), fn_st[fn][s]);
        printf(")\n");
    }
    printf("\ntransform_box ends by kind (OK and ERANGE rows; A full row, F vertex, "
           "U unbounded, L lost, W whole line):\n");
    for (p = 0; p < NBASE; p++) {
        if (!(fn_bases[FN_TBOX] & (1u << p))) continue;
        printf("  base %-5s", base_name[p]);
        for (s = 0; s < E_D; s++) printf("  %c %5ld", end_char[s], tbox_ends[p][s]);
        printf("\n");
    }
    printf("transform_cbox axes by kind (OK and ERANGE rows; A full row, D zero columns "
           "dropped, W lost):\n");
    for (p = 0; p < NBASE; p++) {
        if (!(fn_bases[FN_TCBOX] & (1u << p))) continue;
        printf("  base %-5s  A %5ld  D %5ld  W %5ld\n", base_name[p], tcbox_axes[p][E_A],
               tcbox_axes[p][E_D], tcbox_axes[p][E_W]);
    }
    ctx_clear(&c);
    free(t);
    printf("%ld passed, %ld failed\n", n - failed, failed);
    return failed ? 1 : 0;
}
