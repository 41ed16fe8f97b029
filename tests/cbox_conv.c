/*
 * cbox_conv.c: part of tests/test_cbox.c (cbox_parts.h): the oracle and
 * checks of cbx_box_to_cbox and cbx_cbox_to_box (status, domain, exact
 * containment, the proven conv_gap, sanity), the round trips box -> cbox ->
 * box and cbox -> box -> cbox, and the reproducers printed in hex.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <math.h>

#include "cbox_parts.h"

/* ---------------------------------------------------------------------- */
/* Conversions: oracle and checks                                          */
/* ---------------------------------------------------------------------- */

static int conv_ok(double x) { return fabs(x) <= ldexp(1.0, CONV_EMAX); }

/* gap <= 16 u (|x| + |y|) + 2^-1066: conv_gap of cbx_spec.h, the proven
 * tightness of both conversions (x, y the axis' two inputs) */
static int within_conv(ctx *k, const mpz_t gap, double x, double y)
{
    xu_scaled_d(&k->x, k->t, fabs(x));
    xu_scaled_d(&k->x, k->p, fabs(y));
    mpz_add(k->t, k->t, k->p);                   /* |x| + |y| */
    mpz_set_ui(k->p, 1);
    mpz_mul_2exp(k->p, k->p, XU_SHIFT - 1066 + 49);
    mpz_add(k->t, k->t, k->p);                   /* + 2^-1066 2^49 */
    mpz_mul_2exp(k->p, gap, 49);                 /* gap / (16 u) */
    return mpz_cmp(k->p, k->t) <= 0;
}

static int box_has_nan(const cbx_box *b)
{
    int j;
    for (j = 0; j < 3; j++)
        if (xu_is_nan(b->lo[j]) || xu_is_nan(b->hi[j])) return 1;
    return 0;
}

cbx_status cbt_b2c_expected(const cbx_box *in, int *oob)
{
    int j;
    *oob = 0;
    if (box_has_nan(in)) return CBX_EINVAL;
    if (xu_is_empty(in)) return CBX_EMPTY;
    for (j = 0; j < 3; j++)
        if (!conv_ok(in->lo[j]) || !conv_ok(in->hi[j])) *oob |= 1 << j;
    return *oob ? CBX_ERANGE : CBX_OK;
}

cbx_status cbt_c2b_expected(const cbx_cbox *in, int *oob)
{
    int j;
    *oob = 0;
    if (xu_cbox_has_nan(NULL, in)) return CBX_EINVAL;
    if (xu_cbox_is_empty(in)) return CBX_EMPTY;
    for (j = 0; j < 3; j++)
        if (!conv_ok(in->c[j]) || !conv_ok(in->h[j])) *oob |= 1 << j;
    return *oob ? CBX_ERANGE : CBX_OK;
}

/* k->S = max(|lo|, |hi|) scaled */
static void abs_max_scaled(ctx *k, double p, double q)
{
    double m = fabs(p) > fabs(q) ? fabs(p) : fabs(q);
    xu_scaled_d(&k->x, k->S, m);
}

int cbt_b2c_run(ctx *k, group *g, const cbx_box *in, cbx_cbox *out,
                   verdict *v, double *mx)
{
    cbx_box in0 = *in;
    int i, oob;
    char why[160];

    for (i = 0; i < 3; i++) out->c[i] = out->h[i] = NAN;
    cbt_v_init(v);
    v->got = cbx_box_to_cbox(in, out);
    v->expected = cbt_b2c_expected(in, &oob);
    *mx = 0;
    v->applied[F_INPUT]++;
    if (memcmp(&in0, in, sizeof in0)) cbt_v_fail(v, F_INPUT, "the call modified its input");
    cbt_check_status(v);
    cbt_check_unset_c(v, out);
    if (v->expected == CBX_EINVAL || v->expected == CBX_EMPTY) {
        cbt_check_cspecial(v, out, v->expected == CBX_EINVAL);
        return v->failed;
    }
    for (i = 0; i < 3; i++) {
        int tiny, bad_lo, bad_hi, bad;
        double ulo, uhi, avg;
        if (oob & (1 << i)) {
            v->applied[F_OOB]++;
            snprintf(why, sizeof why, "axis %d out of domain but not c = 0, h = +inf", i);
            cbt_check_cwhole_axis(v, out, i, F_OOB, why);
            continue;
        }
        v->applied[F_FINITE]++;
        if (!isfinite(out->c[i]) || !isfinite(out->h[i])) {
            snprintf(why, sizeof why, "axis %d in domain but out c = %g, h = %g", i,
                     out->c[i], out->h[i]);
            cbt_v_fail(v, F_FINITE, why);
            continue;
        }
        cbt_cbox_ends(k, out->c[i], out->h[i]);
        xu_scaled_d(&k->x, k->elo, in->lo[i]);
        xu_scaled_d(&k->x, k->ehi, in->hi[i]);
        mpz_sub(k->olo, k->elo, k->olo);   /* lo - (c - h) */
        mpz_sub(k->ohi, k->ohi, k->ehi);   /* (c + h) - hi */
        abs_max_scaled(k, in->lo[i], in->hi[i]);
        tiny = xu_scale_tiny(k->S);
        ulo = cbt_side_units(k, k->olo, k->S, tiny, &bad_lo);
        uhi = cbt_side_units(k, k->ohi, k->S, tiny, &bad_hi);
        /* the brief's measure: ((c+h) - hi + lo - (c-h)) / 2 */
        mpz_add(k->g, k->olo, k->ohi);
        mpz_tdiv_q_2exp(k->g, k->g, 1);
        avg = cbt_side_units(k, k->g, k->S, tiny, &bad);
        v->applied[F_CONTAIN]++;
        if (mpz_sgn(k->olo) < 0 || mpz_sgn(k->ohi) < 0) {
            snprintf(why, sizeof why, "axis %d: [c-h, c+h] does not contain [lo, hi] "
                     "(excess lo %.3g, hi %.3g)", i, ulo, uhi);
            cbt_v_fail(v, F_CONTAIN, why);
        }
        v->applied[F_CSPEC]++;
        if (!within_conv(k, k->olo, in->lo[i], in->hi[i])
            || !within_conv(k, k->ohi, in->lo[i], in->hi[i])) {
            snprintf(why, sizeof why, "axis %d: beyond the proven conv_gap "
                     "(excess lo %.3g, hi %.3g)", i, ulo, uhi);
            cbt_v_fail(v, F_CSPEC, why);
        }
        v->applied[tiny ? F_TINYABS : F_SANITY]++;
        if (bad) {
            snprintf(why, sizeof why, "axis %d: sanity bound (mean excess %.3g%s)", i,
                     avg, tiny ? ", tiny scale: gap > 2^-1000" : "");
            cbt_v_fail(v, tiny ? F_TINYABS : F_SANITY, why);
        }
        cbt_ex_add(&g->lo, ulo, tiny, mpz_sgn(k->olo) == 0);
        cbt_ex_add(&g->hi, uhi, tiny, mpz_sgn(k->ohi) == 0);
        cbt_ex_add(&g->main, avg, tiny, mpz_sgn(k->g) == 0);
        if (!tiny && avg > *mx) *mx = avg;
    }
    return v->failed;
}

int cbt_c2b_run(ctx *k, group *g, const cbx_cbox *in, cbx_box *out,
                   verdict *v, double *mx)
{
    cbx_cbox in0 = *in;
    int i, oob;
    char why[160];

    for (i = 0; i < 3; i++) out->lo[i] = out->hi[i] = NAN;
    cbt_v_init(v);
    v->got = cbx_cbox_to_box(in, out);
    v->expected = cbt_c2b_expected(in, &oob);
    *mx = 0;
    v->applied[F_INPUT]++;
    if (memcmp(&in0, in, sizeof in0)) cbt_v_fail(v, F_INPUT, "the call modified its input");
    cbt_check_status(v);
    v->applied[F_UNSET]++;
    for (i = 0; i < 3; i++)
        if (xu_is_nan(out->lo[i]) || xu_is_nan(out->hi[i])) {
            cbt_v_fail(v, F_UNSET, "NaN left in out (field not written)");
            break;
        }
    if (v->expected == CBX_EINVAL || v->expected == CBX_EMPTY) {
        int whole = v->expected == CBX_EINVAL, ok = 1;
        v->applied[F_SPECIAL]++;
        for (i = 0; i < 3; i++)
            ok &= whole ? cbt_is_ninf(out->lo[i]) && cbt_is_pinf(out->hi[i])
                        : cbt_is_pinf(out->lo[i]) && cbt_is_ninf(out->hi[i]);
        if (!ok)
            cbt_v_fail(v, F_SPECIAL, whole ? "EINVAL: out is not [-inf,+inf]^3"
                                       : "EMPTY: out is not lo = +inf, hi = -inf");
        return v->failed;
    }
    for (i = 0; i < 3; i++) {
        int tiny, bad_lo, bad_hi;
        double ulo, uhi;
        if (oob & (1 << i)) {
            v->applied[F_OOB]++;
            if (!cbt_is_ninf(out->lo[i]) || !cbt_is_pinf(out->hi[i])) {
                snprintf(why, sizeof why, "axis %d out of domain but not [-inf,+inf]", i);
                cbt_v_fail(v, F_OOB, why);
            }
            continue;
        }
        v->applied[F_FINITE]++;
        if (!isfinite(out->lo[i]) || !isfinite(out->hi[i]) || out->lo[i] > out->hi[i]) {
            snprintf(why, sizeof why, "axis %d in domain but out = [%g, %g]", i,
                     out->lo[i], out->hi[i]);
            cbt_v_fail(v, F_FINITE, why);
            continue;
        }
        cbt_cbox_ends(k, in->c[i], in->h[i]);
        xu_scaled_d(&k->x, k->elo, out->lo[i]);
        xu_scaled_d(&k->x, k->ehi, out->hi[i]);
        mpz_sub(k->olo, k->olo, k->elo);   /* (c - h) - lo */
        mpz_sub(k->ohi, k->ehi, k->ohi);   /* hi - (c + h) */
        /* S = |c| + h */
        xu_scaled_d(&k->x, k->S, fabs(in->c[i]));
        xu_scaled_d(&k->x, k->g, in->h[i]);
        mpz_add(k->S, k->S, k->g);
        tiny = xu_scale_tiny(k->S);
        ulo = cbt_side_units(k, k->olo, k->S, tiny, &bad_lo);
        uhi = cbt_side_units(k, k->ohi, k->S, tiny, &bad_hi);
        v->applied[F_CONTAIN]++;
        if (mpz_sgn(k->olo) < 0 || mpz_sgn(k->ohi) < 0) {
            snprintf(why, sizeof why, "axis %d: [lo, hi] does not contain [c-h, c+h] "
                     "(excess lo %.3g, hi %.3g)", i, ulo, uhi);
            cbt_v_fail(v, F_CONTAIN, why);
        }
        v->applied[F_CSPEC]++;
        if (!within_conv(k, k->olo, in->c[i], in->h[i])
            || !within_conv(k, k->ohi, in->c[i], in->h[i])) {
            snprintf(why, sizeof why, "axis %d: beyond the proven conv_gap "
                     "(excess lo %.3g, hi %.3g)", i, ulo, uhi);
            cbt_v_fail(v, F_CSPEC, why);
        }
        v->applied[tiny ? F_TINYABS : F_SANITY]++;
        if (bad_lo || bad_hi) {
            snprintf(why, sizeof why, "axis %d: sanity bound (excess lo %.3g, hi %.3g%s)",
                     i, ulo, uhi, tiny ? ", tiny scale: gap > 2^-1000" : "");
            cbt_v_fail(v, tiny ? F_TINYABS : F_SANITY, why);
        }
        cbt_ex_add(&g->lo, ulo, tiny, mpz_sgn(k->olo) == 0);
        cbt_ex_add(&g->hi, uhi, tiny, mpz_sgn(k->ohi) == 0);
        cbt_ex_add(&g->main, ulo > uhi ? ulo : uhi, tiny,
               mpz_sgn(k->olo) == 0 && mpz_sgn(k->ohi) == 0);
        if (!tiny && ulo > *mx) *mx = ulo;
        if (!tiny && uhi > *mx) *mx = uhi;
    }
    return v->failed;
}

/* box -> cbox -> box must contain the box (b2c OK assumed by the caller). */
void cbt_roundtrip_box(ctx *k, group *g, const cbx_box *in,
                          const cbx_cbox *cb, verdict *v)
{
    cbx_box back;
    int j;
    cbx_status s = cbx_cbox_to_box(cb, &back);
    if (s != CBX_OK) { g->rt_skipped++; return; }
    g->rt_n++;
    v->applied[F_ROUND]++;
    for (j = 0; j < 3; j++) {
        if (!(back.lo[j] <= in->lo[j] && in->hi[j] <= back.hi[j])) {
            cbt_v_fail(v, F_ROUND, "box -> cbox -> box does not contain the box");
            return;
        }
        /* widening in units of u max(|lo|,|hi|) + eta */
        abs_max_scaled(k, in->lo[j], in->hi[j]);
        if (!xu_scale_tiny(k->S)) {
            double u;
            xu_scaled_d(&k->x, k->olo, in->lo[j]);
            xu_scaled_d(&k->x, k->g, back.lo[j]);
            mpz_sub(k->olo, k->olo, k->g);
            u = xu_units(&k->x, k->olo, k->S);
            if (u > g->rt_max) g->rt_max = u;
            xu_scaled_d(&k->x, k->ohi, in->hi[j]);
            xu_scaled_d(&k->x, k->g, back.hi[j]);
            mpz_sub(k->ohi, k->g, k->ohi);
            u = xu_units(&k->x, k->ohi, k->S);
            if (u > g->rt_max) g->rt_max = u;
        }
    }
}

/* cbox -> box -> cbox must contain the cbox (exactly). */
void cbt_roundtrip_cbox(ctx *k, group *g, const cbx_cbox *in,
                           const cbx_box *bx, verdict *v)
{
    cbx_cbox back;
    int j;
    cbx_status s = cbx_box_to_cbox(bx, &back);
    if (s != CBX_OK) { g->rt_skipped++; return; }
    g->rt_n++;
    v->applied[F_ROUND]++;
    for (j = 0; j < 3; j++) {
        cbt_cbox_ends(k, in->c[j], in->h[j]);
        mpz_set(k->elo, k->olo);
        mpz_set(k->ehi, k->ohi);
        cbt_cbox_ends(k, back.c[j], back.h[j]);
        if (mpz_cmp(k->olo, k->elo) > 0 || mpz_cmp(k->ohi, k->ehi) < 0) {
            cbt_v_fail(v, F_ROUND, "cbox -> box -> cbox does not contain the cbox");
            return;
        }
        xu_scaled_d(&k->x, k->S, fabs(in->c[j]));
        xu_scaled_d(&k->x, k->g, in->h[j]);
        mpz_add(k->S, k->S, k->g);
        if (!xu_scale_tiny(k->S)) {
            double u;
            mpz_sub(k->g, k->elo, k->olo);
            u = xu_units(&k->x, k->g, k->S);
            if (u > g->rt_max) g->rt_max = u;
            mpz_sub(k->g, k->ohi, k->ehi);
            u = xu_units(&k->x, k->g, k->S);
            if (u > g->rt_max) g->rt_max = u;
        }
    }
}

/* ---------------------------------------------------------------------- */
/* Printing reproducers (hex)                                             */
/* ---------------------------------------------------------------------- */

void cbt_print_cbox(const char *label, const cbx_cbox *b)
{
    int j;
    for (j = 0; j < 3; j++)
        printf("  %s[%d]: c = %a, h = %a   (%.17g, %.17g)\n", label, j, b->c[j],
               b->h[j], b->c[j], b->h[j]);
}

void cbt_print_affine(const cbx_affine *a)
{
    int i;
    for (i = 0; i < 3; i++)
        printf("  m[%d] = {%a, %a, %a | %a}\n", i, a->m[i][0], a->m[i][1],
               a->m[i][2], a->m[i][3]);
}

int cbt_log_head(const char *what, long id, const verdict *v)
{
    if (cbt_fail_logs++ >= MAX_FAIL_LOGS) return 0;
    printf("FAIL %s %ld: %s (status %s, expected %s)\n", what, id, v->why,
           cbx_status_name(v->got), cbx_status_name(v->expected));
    return 1;
}
