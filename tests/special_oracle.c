/*
 * special_oracle.c: the oracle of test_special (tests/test_special.c):
 * certbox.h's rules written out again, from the header and
 * specs/cbx_spec.h, independently of the library and of exact_util: the
 * expected status of a row and the kind of every output end; and
 * exact_util's oracle for transform_box and transform_cbox, to cross-check
 * it (check "oracle").
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <float.h>
#include <math.h>

#include "certbox.h"
#include "exact_util.h"
#include "special_parts.h"

/* ---------------------------------------------------------------------- */
/* The oracle: certbox.h's rules, written out again                       */
/* ---------------------------------------------------------------------- */

int spc_nan_(double x) { return x != x; }
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
            if (spc_nan_(a->m[i][j])) return 1;
    return 0;
}

static int nan3(const double v[3]) { return spc_nan_(v[0]) || spc_nan_(v[1]) || spc_nan_(v[2]); }

int spc_is_pinf(double d) { return isinf(d) && d > 0; }
int spc_is_ninf(double d) { return isinf(d) && d < 0; }

/* [lo, hi] has no real point: hi < lo, lo = +inf or hi = -inf. */
static int no_point(double lo, double hi)
{
    return hi < lo || spc_is_pinf(lo) || spc_is_ninf(hi);
}

/* transform_box, one end of a finite map row that is not full: U when
 * the coordinate it needs is infinite, else F when the vertex is in the
 * domain, else L.  v[] receives the vertex (when not U). */
int spc_tbox_end(const input *in, int i, int upper, double v[3])
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
void spc_tcbox_drop(const input *in, int i, double dc[3], double dh[3])
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
cbx_status spc_oracle(int fn, const input *in, unsigned char end[3][2])
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
                end[i][k] = (unsigned char)spc_tbox_end(in, i, k, v);
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
            spc_tcbox_drop(in, i, dc, dh);
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
void spc_ends_str(const unsigned char end[3][2], char *s)
{
    int i, n = 0;
    for (i = 0; i < 3; i++) {
        if (i) s[n++] = ' ';
        s[n++] = spc_end_char[end[i][0]];
        s[n++] = spc_end_char[end[i][1]];
    }
    s[n] = '\0';
}

/* exact_util's oracle, where it has one (-1: none): the status and the
 * end kinds as a string like spc_ends_str()'s ("" for EINVAL / EMPTY). */
int spc_xu_oracle(int fn, const input *in, cbx_status *st, char ends[9])
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
            spc_ends_str((const unsigned char (*)[2])e, ends);
        }
        return 0;
    }
    return -1;
}
