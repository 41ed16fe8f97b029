/*
 * Section 5 of tests/test_float.c (tests/float_parts.h): cbx_sphere_boxf
 * and cbx_ellipsoid_boxf against t -+ sqrt(s), exactly.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "float_parts.h"

/* ---- 5. spheres and ellipsoids ---------------------------------------- */

fstat flt_st_sph = { "cbx_sphere_boxf", 0, 0, 0, 0, 0, 0 };
fstat flt_st_ell = { "cbx_ellipsoid_boxf", 0, 0, 0, 0, 0, 0 };

/* One axis of a ball bound: lo <= t - sqrt(s') and hi >= t + sqrt(s'),
 * s' = s / 2^(2 sh), exactly (else 0), and each end within the proven
 * 80 u (|t| + sqrt s') + 2^-139 of the exact end, exactly (else -1); the
 * excess of each end over the exact end, in units of u (|t| + sqrt s') +
 * eta (statistics). */
static int ball_axis_ok(xu_exact *x, fstat *fs, const mpz_t s, unsigned long sh, double t,
                        double lo, double hi)
{
    double r, sc, m;
    long e;
    if (!xu_sqrt_lo_ok(x, s, sh, t, lo) || !xu_sqrt_hi_ok(x, s, sh, t, hi)) return 0;
    /* the proven tightness (ball_tight, binary32): 80 u (|t| + sqrt s') + 2^-139 */
    fs->checks += 2;
    if (!xu_sqrt_gap_ok(x, s, sh, t, lo, 80, 24, 139) || !xu_sqrt_gap_ok(x, s, sh, t, hi, 80, 24, 139))
        return -1;
    m = mpz_get_d_2exp(&e, s); /* s = m 2^e, m in [0.5, 1): statistics only */
    r = mpz_sgn(s) ? ldexp(sqrt(m * ((e & 1) ? 2.0 : 1.0)), (int)((e - (e & 1)) / 2 - (long)sh)) : 0.0;
    sc = 0x1p-24 * (fabs(t) + r) + 0x1p-149;
    flt_fs_excess(fs, ((t - r) - lo) / sc);
    flt_fs_excess(fs, (hi - (t + r)) / sc);
    return 1;
}

static int ball_out_common(fstat *fs, const char *what, cbx_status s, cbx_status want,
                           const cbx_box *od, const int in_dom[3])
{
    char why[120] = "";
    int i, bad = 0;
    fs->checks++;
    if (s != want) { bad = 1; snprintf(why, sizeof why, "status %d, expected %d", s, want); }
    for (i = 0; i < 3 && !bad; i++) {
        fs->checks++;
        if (od->lo[i] != od->lo[i] || od->hi[i] != od->hi[i]) { bad = 1; snprintf(why, sizeof why, "axis %d unset", i); }
        else if (want == CBX_EINVAL || !in_dom[i]) {
            if (!(flt_is_ninf(od->lo[i]) && flt_is_pinf(od->hi[i]))) { bad = 1; snprintf(why, sizeof why, "axis %d not whole", i); }
        } else if (!isfinite(od->lo[i]) || !isfinite(od->hi[i])) {
            bad = 1;
            snprintf(why, sizeof why, "axis %d not finite", i);
        }
    }
    if (bad) flt_fs_fail(fs, what, why);
    return bad;
}

void flt_run_sphere(xu_exact *x, const cbx_affine *ad, const char *what)
{
    cbx_affinef a;
    cbx_boxf o;
    cbx_box od;
    cbx_status s, want;
    int i, j, nan = 0, dom[3], bad;
    mpz_t S, z;
    flt_to_af(ad, &a);
    for (i = 0; i < 3; i++) {
        dom[i] = 1;
        for (j = 0; j < 4; j++) {
            if (ad->m[i][j] != ad->m[i][j]) nan = 1;
            if (!(fabs(ad->m[i][j]) <= (j < 3 ? 0x1p61 : 0x1p122))) dom[i] = 0;
        }
    }
    want = nan ? CBX_EINVAL : (dom[0] && dom[1] && dom[2]) ? CBX_OK : CBX_ERANGE;
    flt_nan_bf(&o);
    s = cbx_sphere_boxf(&a, &o);
    flt_from_bf(&o, &od);
    flt_st_sph.cases++;
    bad = ball_out_common(&flt_st_sph, what, s, want, &od, dom);
    mpz_inits(S, z, NULL);
    for (i = 0; i < 3 && !bad && want != CBX_EINVAL; i++) {
        if (!dom[i]) continue;
        mpz_set_ui(S, 0);
        for (j = 0; j < 3; j++) {
            xu_scaled_sh(z, ad->m[i][j], 1074);
            mpz_addmul(S, z, z);
        }
        flt_st_sph.checks += 2;
        int k = ball_axis_ok(x, &flt_st_sph, S, 1074, ad->m[i][3], od.lo[i], od.hi[i]);
        if (k <= 0) {
            bad = 1;
            flt_fs_fail(&flt_st_sph, what, k < 0 ? "an end beyond the proven tightness bound"
                                         : "an end inside the exact image of the ball");
        }
    }
    mpz_clears(S, z, NULL);
    if (bad) flt_st_sph.failed++;
}

void flt_run_ellipsoid(xu_exact *x, const double cen[3], const double rad[3],
                       const double rot[3][3], const char *what)
{
    float c[3], r[3], R[3][3];
    cbx_boxf o;
    cbx_box od;
    cbx_status s, want;
    int i, j, nan = 0, dom[3], bad;
    mpz_t S, z, w;
    for (i = 0; i < 3; i++) {
        c[i] = flt_F(cen[i]);
        r[i] = flt_F(rad[i]);
        for (j = 0; j < 3; j++) R[i][j] = flt_F(rot[i][j]);
        if (cen[i] != cen[i] || rad[i] != rad[i]) nan = 1;
        for (j = 0; j < 3; j++) if (rot[i][j] != rot[i][j]) nan = 1;
    }
    for (i = 0; i < 3; i++) {
        dom[i] = fabs(cen[i]) <= 0x1p122;
        for (j = 0; j < 3; j++)
            if (!(fabs(rot[i][j]) <= 0x1p30) || !(fabs(rad[j]) <= 0x1p30)) dom[i] = 0;
    }
    want = nan ? CBX_EINVAL : (dom[0] && dom[1] && dom[2]) ? CBX_OK : CBX_ERANGE;
    flt_nan_bf(&o);
    s = cbx_ellipsoid_boxf(c, r, (const float (*)[3])R, &o);
    flt_from_bf(&o, &od);
    flt_st_ell.cases++;
    bad = ball_out_common(&flt_st_ell, what, s, want, &od, dom);
    mpz_inits(S, z, w, NULL);
    for (i = 0; i < 3 && !bad && want != CBX_EINVAL; i++) {
        if (!dom[i]) continue;
        mpz_set_ui(S, 0);
        for (j = 0; j < 3; j++) { /* m_ij = rot_ij radii_j, times 2^2148, exactly */
            xu_scaled_sh(z, rot[i][j], 1074);
            xu_scaled_sh(w, rad[j], 1074);
            mpz_mul(z, z, w);
            mpz_addmul(S, z, z);
        }
        flt_st_ell.checks += 2;
        int k = ball_axis_ok(x, &flt_st_ell, S, 2148, cen[i], od.lo[i], od.hi[i]);
        if (k <= 0) {
            bad = 1;
            flt_fs_fail(&flt_st_ell, what, k < 0 ? "an end beyond the proven tightness bound"
                                         : "an end inside the exact image of the ellipsoid");
        }
    }
    mpz_clears(S, z, w, NULL);
    if (bad) flt_st_ell.failed++;
}

/* A random rotation in float (the quaternion's matrix, rounded). */
void flt_rand_rot_f(xu_rng *r, double R[3][3])
{
    int i, j;
    xu_rand_rotation(r, R);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) R[i][j] = xu_round_fmt(R[i][j]);
}

double flt_gen_ball_entry(xu_rng *r)
{
    int p = xu_rng_int(r, 0, 99);
    if (p < 3) return xu_rng_sign(r) * 0x1p61;
    if (p < 5) return xu_rng_sign(r) * 0x1.000002p61;          /* just out */
    if (p < 7) return xu_rng_sign(r) * HUGE_VAL;
    if (p < 15) return xu_gen_signed(r, -149, -30);             /* tiny rows */
    return xu_gen_signed(r, -40, 40);
}
