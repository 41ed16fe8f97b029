/*
 * Sections 3 and 4 of tests/test_float.c (tests/float_parts.h):
 * cbx_transform_cboxf against the exact image of the (dropped) input box,
 * and the conversions cbx_box_to_cboxf and cbx_cbox_to_boxf.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "float_parts.h"

/* ---- 3. cbx_transform_cboxf ------------------------------------------- */

fstat flt_st_cbox = { "cbx_transform_cboxf", 0, 0, 0, 0, 0, 0 };

/* (oc - oh) and (oc + oh) against the exact ends of the image of the
 * (dropped) input box on axis i; adds the excess (axes with u S >=
 * 2^XU_TINY eta, as test_exact reports them); 0 on failure. */
static int cbox_axis_ok(xu_exact *x, const cbx_affine *a, const cbx_cbox *d, int i,
                        double oc, double oh, char *why, size_t nwhy)
{
    mpz_t C, H, S, z, lo, hi, gap;
    int j, ok = 1, tiny;
    mpz_inits(C, H, S, z, lo, hi, gap, NULL);
    xu_scaled_d(x, C, a->m[i][3]);
    mpz_abs(S, C);
    mpz_set_ui(H, 0);
    for (j = 0; j < 3; j++) {
        xu_scaled_mul(x, z, a->m[i][j], d->c[j]);
        mpz_add(C, C, z);
        mpz_abs(z, z);
        mpz_add(S, S, z);
        xu_scaled_mul(x, z, a->m[i][j], d->h[j]);
        mpz_abs(z, z);
        mpz_add(H, H, z);
        mpz_add(S, S, z);
    }
    /* exact image [C - H, C + H]; output [oc - oh, oc + oh] */
    xu_scaled_d(x, lo, oc);
    xu_scaled_d(x, z, oh);
    mpz_add(hi, lo, z);
    mpz_sub(lo, lo, z);
    mpz_sub(gap, C, H);
    mpz_sub(gap, gap, lo); /* >= 0: contained below */
    tiny = mpz_sizeinbase(S, 2) <= (size_t)(XU_SHIFT - 149 + 24 + XU_TINY);
    if (mpz_sgn(gap) < 0) { ok = 0; snprintf(why, nwhy, "axis %d: lower end not contained", i); }
    else if (!tiny) flt_fs_excess(&flt_st_cbox, xu_units(x, gap, S));
    /* the proven bound: gap <= 12 u S + 2^-140 (scaled: gap 2^24 <= 12 S + 2^(SHIFT-116)) */
    mpz_mul_2exp(z, gap, 24);
    mpz_mul_ui(gap, S, 12);
    mpz_set_ui(C, 1);
    mpz_mul_2exp(C, C, XU_SHIFT - 140 + 24);
    mpz_add(gap, gap, C);
    if (ok && mpz_cmp(z, gap) > 0) { ok = 0; snprintf(why, nwhy, "axis %d: lower end beyond 12uS+2^-140", i); }
    /* upper */
    xu_scaled_d(x, C, a->m[i][3]);
    for (j = 0; j < 3; j++) {
        xu_scaled_mul(x, z, a->m[i][j], d->c[j]);
        mpz_add(C, C, z);
    }
    mpz_add(gap, C, H);
    mpz_sub(gap, hi, gap);
    if (mpz_sgn(gap) < 0) { ok = 0; snprintf(why, nwhy, "axis %d: upper end not contained", i); }
    else if (!tiny) flt_fs_excess(&flt_st_cbox, xu_units(x, gap, S));
    mpz_mul_2exp(z, gap, 24);
    mpz_mul_ui(gap, S, 12);
    mpz_set_ui(C, 1);
    mpz_mul_2exp(C, C, XU_SHIFT - 140 + 24);
    mpz_add(gap, gap, C);
    if (ok && mpz_cmp(z, gap) > 0) { ok = 0; snprintf(why, nwhy, "axis %d: upper end beyond 12uS+2^-140", i); }
    mpz_clears(C, H, S, z, lo, hi, gap, NULL);
    return ok;
}

void flt_run_cbox(xu_exact *x, const cbx_affine *ad, const cbx_cbox *cd, const char *what)
{
    cbx_affinef a;
    cbx_cboxf c, o, ip;
    cbx_cbox od;
    cbx_status s, s2, want = xu_cbox_expected_status(ad, cd);
    char why[160] = "";
    int i, bad = 0;
    flt_to_af(ad, &a);
    flt_to_cf(cd, &c);
    flt_nan_cf(&o);
    s = cbx_transform_cboxf(&a, &c, &o);
    flt_from_cf(&o, &od);
    flt_st_cbox.cases++;
    flt_st_cbox.checks += 2;
    if (s != want) { bad = 1; snprintf(why, sizeof why, "status %d, expected %d", s, want); }
    for (i = 0; i < 3 && !bad; i++) {
        flt_st_cbox.checks++;
        if (od.c[i] != od.c[i] || od.h[i] != od.h[i]) {
            bad = 1;
            snprintf(why, sizeof why, "axis %d left unset", i);
        } else if (want == CBX_EINVAL || want == CBX_EMPTY) {
            if (!(od.c[i] == 0 && (want == CBX_EINVAL ? flt_is_pinf(od.h[i]) : flt_is_ninf(od.h[i])))) {
                bad = 1;
                snprintf(why, sizeof why, "axis %d: special output wrong", i);
            }
        } else {
            int k = xu_cbox_axis_kind(ad, cd, i);
            if (k == XU_CAX_LOST) {
                if (!(od.c[i] == 0 && flt_is_pinf(od.h[i]))) {
                    bad = 1;
                    snprintf(why, sizeof why, "axis %d: lost axis not (0, +inf)", i);
                }
            } else {
                cbx_cbox d;
                xu_cbox_dropped(ad, cd, i, &d);
                if (!isfinite(od.c[i]) || !isfinite(od.h[i])) {
                    bad = 1;
                    snprintf(why, sizeof why, "axis %d: proven axis not finite", i);
                } else if (!cbox_axis_ok(x, ad, k == XU_CAX_FULL ? cd : &d, i, od.c[i], od.h[i],
                                         why, sizeof why)) {
                    bad = 1;
                }
                flt_st_cbox.checks += 4;
            }
        }
    }
    ip = c;
    s2 = cbx_transform_cboxf(&a, &ip, &ip);
    flt_st_cbox.checks++;
    if (s2 != s || memcmp(&ip, &o, sizeof o)) {
        bad = 1;
        snprintf(why, sizeof why, "in-place call differs");
    }
    if (bad) {
        flt_st_cbox.failed++;
        flt_fs_fail(&flt_st_cbox, what, why);
    }
}

/* A cbox case: the map and the centers of a random box case, half-widths
 * within the same class, zero columns against infinite or huge entries,
 * some NaN and negative half-widths. */
void flt_gen_cbox(xu_rng *r, cbx_affine *a, cbx_cbox *c)
{
    cbx_box b;
    int j, p = xu_rng_int(r, 0, 99);
    xu_gen_case(r, a, &b);
    for (j = 0; j < 3; j++) {
        double lo = b.lo[j], hi = b.hi[j];
        c->c[j] = isfinite(lo) ? lo : (isfinite(hi) ? hi : 0.0);
        c->h[j] = fabs(xu_round_fmt(isfinite(hi) && isfinite(lo) ? hi - lo : c->c[j]));
        if (!isfinite(c->h[j])) c->h[j] = FLT_MAX;
    }
    if (p < 10) { /* zero column against an unusable center or half-width */
        int i = xu_rng_int(r, 0, 2);
        j = xu_rng_int(r, 0, 2);
        a->m[0][j] = a->m[1][j] = 0.0;
        a->m[i][j] = xu_rng_sign(r) * 0.0;
        if (xu_rng_int(r, 0, 1)) c->c[j] = xu_rng_sign(r) * HUGE_VAL;
        else c->h[j] = xu_rng_int(r, 0, 1) ? HUGE_VAL : FLT_MAX;
    } else if (p < 13) {
        double m = xu_gen_mag(r, -149, 10);
        c->h[xu_rng_int(r, 0, 2)] = m > 0 ? -m : -0x1p-149; /* empty */
    } else if (p < 15) {
        c->c[xu_rng_int(r, 0, 2)] = NAN;
    } else if (p < 18) {
        c->h[xu_rng_int(r, 0, 2)] = HUGE_VAL;
    }
}

/* ---- 4. conversions ---------------------------------------------------- */

fstat flt_st_b2c = { "cbx_box_to_cboxf", 0, 0, 0, 0, 0, 0 };
fstat flt_st_c2b = { "cbx_cbox_to_boxf", 0, 0, 0, 0, 0, 0 };

static int conv_in(double x) { return fabs(x) <= 0x1p123; }

void flt_run_b2c(xu_exact *x, const cbx_box *bd, const char *what)
{
    cbx_boxf b;
    cbx_cboxf o;
    cbx_cbox od;
    cbx_status s, want;
    char why[120] = "";
    int j, nan = 0, empty = 0, out = 0, bad = 0;
    flt_to_bf(bd, &b);
    for (j = 0; j < 3; j++) {
        if (bd->lo[j] != bd->lo[j] || bd->hi[j] != bd->hi[j]) nan = 1;
        if (bd->hi[j] < bd->lo[j] || flt_is_pinf(bd->lo[j]) || flt_is_ninf(bd->hi[j])) empty = 1;
        if (!conv_in(bd->lo[j]) || !conv_in(bd->hi[j])) out = 1;
    }
    want = nan ? CBX_EINVAL : empty ? CBX_EMPTY : out ? CBX_ERANGE : CBX_OK;
    flt_nan_cf(&o);
    s = cbx_box_to_cboxf(&b, &o);
    flt_from_cf(&o, &od);
    flt_st_b2c.cases++;
    flt_st_b2c.checks++;
    if (s != want) { bad = 1; snprintf(why, sizeof why, "status %d, expected %d", s, want); }
    for (j = 0; j < 3 && !bad; j++) {
        flt_st_b2c.checks++;
        if (od.c[j] != od.c[j] || od.h[j] != od.h[j]) { bad = 1; snprintf(why, sizeof why, "axis %d unset", j); }
        else if (want == CBX_EINVAL || want == CBX_EMPTY) {
            if (!(od.c[j] == 0 && (want == CBX_EINVAL ? flt_is_pinf(od.h[j]) : flt_is_ninf(od.h[j]))))
                { bad = 1; snprintf(why, sizeof why, "axis %d special output", j); }
        } else if (!conv_in(bd->lo[j]) || !conv_in(bd->hi[j])) {
            if (!(od.c[j] == 0 && flt_is_pinf(od.h[j]))) { bad = 1; snprintf(why, sizeof why, "axis %d not whole", j); }
        } else {
            mpz_t lo, hi, c, h;
            mpz_inits(lo, hi, c, h, NULL);
            xu_scaled_d(x, lo, bd->lo[j]);
            xu_scaled_d(x, hi, bd->hi[j]);
            xu_scaled_d(x, c, od.c[j]);
            xu_scaled_d(x, h, od.h[j]);
            flt_st_b2c.checks += 2;
            if (!isfinite(od.c[j]) || !isfinite(od.h[j])) { bad = 1; snprintf(why, sizeof why, "axis %d not finite", j); }
            else {
                mpz_sub(c, c, h); /* c - h <= lo */
                if (mpz_cmp(c, lo) > 0) { bad = 1; snprintf(why, sizeof why, "axis %d: c-h > lo", j); }
                mpz_add(c, c, h);
                mpz_add(c, c, h); /* c + h >= hi */
                if (mpz_cmp(c, hi) < 0) { bad = 1; snprintf(why, sizeof why, "axis %d: c+h < hi", j); }
                if (!bad) { /* excess of the half-width over (hi - lo)/2, units of u|x| + eta */
                    double w = od.h[j] - (bd->hi[j] - bd->lo[j]) / 2;
                    double sc = fmax(fabs(bd->lo[j]), fabs(bd->hi[j]));
                    flt_fs_excess(&flt_st_b2c, w / (0x1p-24 * sc + 0x1p-149));
                }
            }
            mpz_clears(lo, hi, c, h, NULL);
        }
    }
    if (bad) { flt_st_b2c.failed++; flt_fs_fail(&flt_st_b2c, what, why); }
}

void flt_run_c2b(xu_exact *x, const cbx_cbox *cd, const char *what)
{
    cbx_cboxf c;
    cbx_boxf o;
    cbx_box od;
    cbx_status s, want;
    char why[120] = "";
    int j, nan = 0, empty = 0, out = 0, bad = 0;
    flt_to_cf(cd, &c);
    for (j = 0; j < 3; j++) {
        if (cd->c[j] != cd->c[j] || cd->h[j] != cd->h[j]) nan = 1;
        if (cd->h[j] < 0) empty = 1;
        if (!conv_in(cd->c[j]) || !conv_in(cd->h[j])) out = 1;
    }
    want = nan ? CBX_EINVAL : empty ? CBX_EMPTY : out ? CBX_ERANGE : CBX_OK;
    flt_nan_bf(&o);
    s = cbx_cbox_to_boxf(&c, &o);
    flt_from_bf(&o, &od);
    flt_st_c2b.cases++;
    flt_st_c2b.checks++;
    if (s != want) { bad = 1; snprintf(why, sizeof why, "status %d, expected %d", s, want); }
    for (j = 0; j < 3 && !bad; j++) {
        flt_st_c2b.checks++;
        if (od.lo[j] != od.lo[j] || od.hi[j] != od.hi[j]) { bad = 1; snprintf(why, sizeof why, "axis %d unset", j); }
        else if (want == CBX_EINVAL) {
            if (!(flt_is_ninf(od.lo[j]) && flt_is_pinf(od.hi[j]))) { bad = 1; snprintf(why, sizeof why, "axis %d special", j); }
        } else if (want == CBX_EMPTY) {
            if (!(flt_is_pinf(od.lo[j]) && flt_is_ninf(od.hi[j]))) { bad = 1; snprintf(why, sizeof why, "axis %d special", j); }
        } else if (!conv_in(cd->c[j]) || !conv_in(cd->h[j])) {
            if (!(flt_is_ninf(od.lo[j]) && flt_is_pinf(od.hi[j]))) { bad = 1; snprintf(why, sizeof why, "axis %d not whole", j); }
        } else {
            mpz_t lo, hi, c, h;
            mpz_inits(lo, hi, c, h, NULL);
            xu_scaled_d(x, lo, od.lo[j]);
            xu_scaled_d(x, hi, od.hi[j]);
            xu_scaled_d(x, c, cd->c[j]);
            xu_scaled_d(x, h, cd->h[j]);
            flt_st_c2b.checks += 2;
            if (!isfinite(od.lo[j]) || !isfinite(od.hi[j])) { bad = 1; snprintf(why, sizeof why, "axis %d not finite", j); }
            else {
                mpz_sub(c, c, h); /* lo <= c - h */
                if (mpz_cmp(lo, c) > 0) { bad = 1; snprintf(why, sizeof why, "axis %d: lo > c-h", j); }
                mpz_add(c, c, h);
                mpz_add(c, c, h); /* hi >= c + h */
                if (mpz_cmp(hi, c) < 0) { bad = 1; snprintf(why, sizeof why, "axis %d: hi < c+h", j); }
                if (!bad) {
                    double sc = fabs(cd->c[j]) + cd->h[j];
                    double w = (od.hi[j] - od.lo[j]) / 2 - cd->h[j];
                    flt_fs_excess(&flt_st_c2b, w / (0x1p-24 * sc + 0x1p-149));
                }
            }
            mpz_clears(lo, hi, c, h, NULL);
        }
    }
    if (bad) { flt_st_c2b.failed++; flt_fs_fail(&flt_st_c2b, what, why); }
}
