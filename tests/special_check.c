/*
 * special_check.c: the checks of test_special (tests/test_special.c, where
 * they are described): per output axis and end, exactly (GMP, mpq / mpz)
 * for every function; and running one row: the call on a sentinel-filled
 * output, then every check that applies to it.
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
/* Checks                                                                 */
/* ---------------------------------------------------------------------- */

const char *const spc_check_name[NCHECK] = {
    "oracle", "status", "out-set", "nan-out", "special", "whole", "finite",
    "contain", "tight", "inf-end", "v-finite", "v-contain", "v-tight", "inputs"
};
const char *const spc_check_unit[NCHECK] = {
    "rows", "rows", "rows", "rows", "rows", "axes", "axes", "axes", "axes",
    "ends", "ends", "ends", "ends", "rows"
};

void spc_ctx_init(ctx *k)
{
    memset(k, 0, sizeof *k);
    xu_init(&k->x);
    mpq_inits(k->q, k->qa, k->qb, k->qc, k->qlo, k->qhi, k->tol, k->eps, k->eta, (mpq_ptr)0);
    mpz_inits(k->s, k->z, (mpz_ptr)0);
}

void spc_ctx_clear(ctx *k)
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
    spc_tbox_end(in, i, upper, v);
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
        return o->cb.c[i] == 0 && (whole ? spc_is_pinf(o->cb.h[i]) : spc_is_ninf(o->cb.h[i]));
    return whole ? spc_is_ninf(o->b.lo[i]) && spc_is_pinf(o->b.hi[i])
                 : spc_is_pinf(o->b.lo[i]) && spc_is_ninf(o->b.hi[i]);
}

/* Output field n (0..5): lo[0..2], hi[0..2] or c[0..2], h[0..2]. */
static double *field(int cform, output *o, int n)
{
    if (cform) return n < 3 ? &o->cb.c[n] : &o->cb.h[n - 3];
    return n < 3 ? &o->b.lo[n] : &o->b.hi[n - 3];
}

int spc_run_row(ctx *k, const row *r, verdict *v)
{
    input in0;
    int n, i, cform = spc_fn_cout[r->fn];
    cbx_status xst;
    char xends[9], ends[9];

    memset(k->flag, 0, sizeof k->flag);
    k->row_failed = 0;
    k->why[0] = '\0';

    spc_make_input(r, &v->in);
    in0 = v->in;
    for (n = 0; n < 6; n++) *field(cform, &v->out, n) = sentinel();
    v->got = call(r->fn, &v->in, &v->out);

    apply(k, C_INPUT);
    if (memcmp(&in0, &v->in, sizeof in0) != 0) fail(k, C_INPUT, "the call modified its inputs", 0);

    if (spc_xu_oracle(r->fn, &v->in, &xst, xends) == 0) {
        apply(k, C_ORACLE);
        spc_ends_str((const unsigned char (*)[2])r->end, ends);
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
        else if (spc_nan_(d)) fail(k, C_NANOUT, "output field %d is a NaN", n);
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
            spc_tcbox_drop(&v->in, i, dc, dh);
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
                if (!(e ? spc_is_pinf(d) : spc_is_ninf(d)))
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
