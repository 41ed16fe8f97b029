/*
 * The disks and ellipses of test_plane (tests/plane_parts.h):
 * cbx_disk_box2, cbx_ellipse_box2 and their binary32 twins, decided
 * exactly in integers (containment and the proven 80 u (|t| + sqrt s) +
 * eta) and against cbx_sphere_box / cbx_ellipsoid_box on the embedding;
 * hard cases, then random ones.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "plane_parts.h"

/* ---- disks and ellipses ---------------------------------------------- */

const ballfmt plt_bf64 = { 0, 0x1p509, 0x1p1018, 0x1p254, 53, 1064 };
const ballfmt plt_bf32 = { 1, 0x1p61, 0x1p122, 0x1p30, 24, 139 };

#define SH_DISK 1200UL  /* m 2^sh and t 2^(sh - uexp) integers            */
#define SH_ELL2 2148UL  /* rot * radii 2^sh integers                      */

typedef struct balltally {
    long cases, failed, checks, axes;
    long status[4];
    double max_units;           /* largest end excess, units of u (|t| + sqrt s) + eta */
} balltally;

/* One in-domain axis: containment and the proven tightness of both ends,
 * exactly; 0 if both hold. */
static int ball2_axis(xu_exact *x, balltally *t, const ballfmt *F, const mpz_t s,
                      unsigned long sh, double c, double lo, double hi, char *why, size_t n)
{
    double m, r, sc, ex;
    long e;
    t->axes++;
    t->checks += 4;
    if (!isfinite(lo) || !isfinite(hi)) {
        snprintf(why, n, "in-domain axis not finite [%g, %g]", lo, hi);
        return 1;
    }
    if (!xu_sqrt_lo_ok(x, s, sh, c, lo) || !xu_sqrt_hi_ok(x, s, sh, c, hi)) {
        snprintf(why, n, "t -+ sqrt(s) not inside [%a, %a]", lo, hi);
        return 1;
    }
    if (!xu_sqrt_gap_ok(x, s, sh, c, lo, 80, F->uexp, F->eexp)
        || !xu_sqrt_gap_ok(x, s, sh, c, hi, 80, F->uexp, F->eexp)) {
        snprintf(why, n, "an end beyond the proven 80 u (|t| + sqrt s) + eta");
        return 1;
    }
    m = mpz_get_d_2exp(&e, s); /* statistics only: sqrt s' in double */
    r = mpz_sgn(s) ? ldexp(sqrt(m * ((e & 1) ? 2.0 : 1.0)), (int)((e - (e & 1)) / 2 - (long)sh)) : 0.0;
    sc = ldexp(1.0, -(int)F->uexp) * (fabs(c) + r) + ldexp(1.0, F->f32 ? -149 : -1074);
    ex = ((c - r) - lo) / sc;
    if (ex > t->max_units) t->max_units = ex;
    ex = (hi - (c + r)) / sc;
    if (ex > t->max_units) t->max_units = ex;
    return 0;
}

/* The statuses, special outputs and axes of a disk or an ellipse, given
 * each axis's s (valid where dom[i]). */
static int ball2_judge(xu_exact *x, balltally *t, const ballfmt *F, int nan, const int dom[2],
                       mpz_t s[2], unsigned long sh, const double c[2], cbx_status got,
                       const double lo[2], const double hi[2], char *why, size_t n)
{
    cbx_status want = nan ? CBX_EINVAL : (dom[0] && dom[1]) ? CBX_OK : CBX_ERANGE;
    int i;
    t->checks++;
    if (got != want) {
        snprintf(why, n, "status %s, expected %s", cbx_status_name(got), cbx_status_name(want));
        return 1;
    }
    if (xu_status_index(got) >= 0) t->status[xu_status_index(got)]++;
    for (i = 0; i < 2; i++) {
        if (nan || !dom[i]) {
            t->checks++;
            if (!plt_is_ninf(lo[i]) || !plt_is_pinf(hi[i])) {
                snprintf(why, n, "axis %d must be [-inf, +inf], is [%g, %g]", i, lo[i], hi[i]);
                return 1;
            }
            continue;
        }
        if (ball2_axis(x, t, F, s[i], sh, c[i], lo[i], hi[i], why, n)) return 1;
    }
    return 0;
}

/* A value for a disk or an ellipse: mostly moderate, some at the domain's
 * edges and beyond, zeros, subnormals, infinities and NaN. */
static double gen_ball_val(xu_rng *r, const ballfmt *F, double edge)
{
    int k = xu_rng_int(r, 0, 99);
    double v;
    if (k < 70) v = xu_gen_signed(r, -25, 25);
    else if (k < 78) v = xu_rng_sign(r) * edge * (xu_rng_int(r, 0, 1) ? 1.0 : 0.75);
    else if (k < 84) v = xu_rng_sign(r) * edge * 2.0;
    else if (k < 88) v = xu_rng_sign(r) * 0.0;
    else if (k < 92) v = xu_rng_sign(r) * ldexp(1.0, F->f32 ? -149 : -1074) * xu_rng_int(r, 1, 9);
    else if (k < 96) v = xu_gen_signed(r, -300, 300);
    else if (k < 98) v = xu_rng_sign(r) * HUGE_VAL;
    else v = NAN;
    return xu_round_fmt(v);
}

static void fail_ball(balltally *t, const char *fam, const char *what, const char *why)
{
    t->failed++;
    plt_fail(fam, what, why);
}

/* One disk: m[i] = {m_i0, m_i1, t_i}. */
static void run_disk(xu_exact *x, balltally *t, const ballfmt *F, const double m[2][3], const char *what)
{
    const char *fam = F->f32 ? "cbx_disk_box2f" : "cbx_disk_box2";
    double lo[2], hi[2], c[2], rlo[3], rhi[3];
    int dom[2], nan = 0, i, j;
    cbx_status got, ref;
    char why[160];
    mpz_t s[2], z;
    t->cases++;
    for (i = 0; i < 2; i++)
        for (j = 0; j < 3; j++) nan |= xu_is_nan(m[i][j]);
    if (F->f32) {
        cbx_affine2f a, a0;
        cbx_box2f o;
        cbx_affinef a3;
        cbx_boxf r3;
        memset(&a3, 0, sizeof a3);
        for (i = 0; i < 2; i++) {
            for (j = 0; j < 3; j++) a.m[i][j] = (float)m[i][j];
            a3.m[i][0] = a.m[i][0]; a3.m[i][1] = a.m[i][1]; a3.m[i][3] = a.m[i][2];
        }
        a0 = a;
        memset(&o, 0xff, sizeof o);
        got = cbx_disk_box2f(&a, &o);
        ref = cbx_sphere_boxf(&a3, &r3);
        if (memcmp(&a, &a0, sizeof a)) { fail_ball(t, fam, what, "an input changed"); return; }
        for (i = 0; i < 2; i++) { lo[i] = o.lo[i]; hi[i] = o.hi[i]; rlo[i] = r3.lo[i]; rhi[i] = r3.hi[i]; }
    } else {
        cbx_affine2 a, a0;
        cbx_box2 o;
        cbx_affine a3;
        cbx_box r3;
        memset(&a3, 0, sizeof a3);
        for (i = 0; i < 2; i++) {
            for (j = 0; j < 3; j++) a.m[i][j] = m[i][j];
            a3.m[i][0] = a.m[i][0]; a3.m[i][1] = a.m[i][1]; a3.m[i][3] = a.m[i][2];
        }
        a0 = a;
        memset(&o, 0xff, sizeof o);
        got = cbx_disk_box2(&a, &o);
        ref = cbx_sphere_box(&a3, &r3);
        if (memcmp(&a, &a0, sizeof a)) { fail_ball(t, fam, what, "an input changed"); return; }
        for (i = 0; i < 2; i++) { lo[i] = o.lo[i]; hi[i] = o.hi[i]; rlo[i] = r3.lo[i]; rhi[i] = r3.hi[i]; }
    }
    t->checks++;
    if (got != ref || memcmp(lo, rlo, sizeof lo) || memcmp(hi, rhi, sizeof hi)) {
        fail_ball(t, fam, what, "not the bits of the sphere's box on the 3D embedding");
        return;
    }
    mpz_init(s[0]); mpz_init(s[1]); mpz_init(z);
    for (i = 0; i < 2; i++) {
        c[i] = m[i][2];
        dom[i] = !nan && isfinite(m[i][0]) && isfinite(m[i][1]) && isfinite(m[i][2])
                 && fabs(m[i][0]) <= F->sb && fabs(m[i][1]) <= F->sb && fabs(m[i][2]) <= F->rt;
        if (!dom[i]) continue;
        for (j = 0; j < 2; j++) {
            xu_scaled_sh(z, m[i][j], SH_DISK);
            mpz_addmul(s[i], z, z);
        }
    }
    if (ball2_judge(x, t, F, nan, dom, s, SH_DISK, c, got, lo, hi, why, sizeof why))
        fail_ball(t, fam, what, why);
    mpz_clear(s[0]); mpz_clear(s[1]); mpz_clear(z);
}

/* One ellipse: e[0] = center, e[1] = radii, e[2], e[3] = rot rows. */
static void run_ellipse(xu_exact *x, balltally *t, const ballfmt *F, const double e[4][2], const char *what)
{
    const char *fam = F->f32 ? "cbx_ellipse_box2f" : "cbx_ellipse_box2";
    double lo[2], hi[2], c[2], rlo[2], rhi[2];
    int dom[2], nan = 0, i, j;
    cbx_status got, ref;
    char why[160];
    mpz_t s[2], z, w;
    t->cases++;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 2; j++) nan |= xu_is_nan(e[i][j]);
    if (F->f32) {
        float cen[2], rad[2], rot[2][2], cen3[3] = { 0 }, rad3[3] = { 0 }, rot3[3][3] = { { 0 } };
        float k0[2], k1[2], k2[2][2];
        cbx_box2f o;
        cbx_boxf r3;
        for (j = 0; j < 2; j++) {
            cen3[j] = cen[j] = (float)e[0][j];
            rad3[j] = rad[j] = (float)e[1][j];
            rot3[0][j] = rot[0][j] = (float)e[2][j];
            rot3[1][j] = rot[1][j] = (float)e[3][j];
        }
        memcpy(k0, cen, sizeof k0); memcpy(k1, rad, sizeof k1); memcpy(k2, rot, sizeof k2);
        memset(&o, 0xff, sizeof o);
        got = cbx_ellipse_box2f(cen, rad, (const float(*)[2])rot, &o);
        ref = cbx_ellipsoid_boxf(cen3, rad3, (const float(*)[3])rot3, &r3);
        if (memcmp(k0, cen, sizeof k0) || memcmp(k1, rad, sizeof k1) || memcmp(k2, rot, sizeof k2)) {
            fail_ball(t, fam, what, "an input changed");
            return;
        }
        for (i = 0; i < 2; i++) { lo[i] = o.lo[i]; hi[i] = o.hi[i]; rlo[i] = r3.lo[i]; rhi[i] = r3.hi[i]; }
    } else {
        double cen[2], rad[2], rot[2][2], cen3[3] = { 0 }, rad3[3] = { 0 }, rot3[3][3] = { { 0 } };
        double k0[2], k1[2], k2[2][2];
        cbx_box2 o;
        cbx_box r3;
        for (j = 0; j < 2; j++) {
            cen3[j] = cen[j] = e[0][j];
            rad3[j] = rad[j] = e[1][j];
            rot3[0][j] = rot[0][j] = e[2][j];
            rot3[1][j] = rot[1][j] = e[3][j];
        }
        memcpy(k0, cen, sizeof k0); memcpy(k1, rad, sizeof k1); memcpy(k2, rot, sizeof k2);
        memset(&o, 0xff, sizeof o);
        got = cbx_ellipse_box2(cen, rad, (const double(*)[2])rot, &o);
        ref = cbx_ellipsoid_box(cen3, rad3, (const double(*)[3])rot3, &r3);
        if (memcmp(k0, cen, sizeof k0) || memcmp(k1, rad, sizeof k1) || memcmp(k2, rot, sizeof k2)) {
            fail_ball(t, fam, what, "an input changed");
            return;
        }
        for (i = 0; i < 2; i++) { lo[i] = o.lo[i]; hi[i] = o.hi[i]; rlo[i] = r3.lo[i]; rhi[i] = r3.hi[i]; }
    }
    t->checks++;
    if (got != ref || memcmp(lo, rlo, sizeof lo) || memcmp(hi, rhi, sizeof hi)) {
        fail_ball(t, fam, what, "not the bits of the ellipsoid's box on the 3D embedding");
        return;
    }
    mpz_init(s[0]); mpz_init(s[1]); mpz_init(z); mpz_init(w);
    for (i = 0; i < 2; i++) {
        const double *rot_i = e[2 + i];
        c[i] = e[0][i];
        dom[i] = !nan && isfinite(c[i]) && fabs(c[i]) <= F->rt;
        for (j = 0; j < 2; j++)
            dom[i] = dom[i] && isfinite(rot_i[j]) && isfinite(e[1][j])
                     && fabs(rot_i[j]) <= F->eb && fabs(e[1][j]) <= F->eb;
        if (!dom[i]) continue;
        for (j = 0; j < 2; j++) {
            xu_scaled_sh(z, rot_i[j], 1074);
            xu_scaled_sh(w, e[1][j], 1074);
            mpz_mul(z, z, w);           /* rot_ij radii_j 2^2148, exactly */
            mpz_addmul(s[i], z, z);
        }
    }
    if (ball2_judge(x, t, F, nan, dom, s, SH_ELL2, c, got, lo, hi, why, sizeof why))
        fail_ball(t, fam, what, why);
    mpz_clear(s[0]); mpz_clear(s[1]); mpz_clear(z); mpz_clear(w);
}

static const double disk_hard[][2][3] = {
    { { 1, 0, 0 }, { 0, 1, 0 } },                   /* the unit disk          */
    { { 3, 4, 0.1 }, { -5, 12, -7 } },              /* exact norms 5 and 13   */
    { { 0, 0, 1 }, { -0.0, 0, -1 } },               /* a point (zero rows)    */
    { { 0x1p509, -0x1p509, 0x1p1018 }, { 1, 1, -0x1p1018 } }, /* the domain's edges */
    { { 0x1p510, 0, 0 }, { 1, 0, 0 } },             /* just outside           */
    { { 0x1p-1074, 0x1p-1074, 0 }, { 0x1p-600, 0x1p-601, 1e-300 } }, /* tiny rows */
    { { HUGE_VAL, 0, 0 }, { 1, 1, 1 } },
    { { 1, 0, NAN }, { 1, 1, 1 } },
};
static const double ell_hard[][4][2] = {
    { { 0, 0 }, { 1, 1 }, { 1, 0 }, { 0, 1 } },                 /* unit circle   */
    { { 5, -5 }, { 3, 0.5 }, { 0.6, -0.8 }, { 0.8, 0.6 } },     /* rotated       */
    { { 0, 0 }, { -2, 0 }, { 1, 0 }, { 0, 1 } },                /* negative, zero radii */
    { { 0x1p1018, 0 }, { 0x1p254, 0x1p254 }, { 0x1p254, -0x1p254 }, { 1, 1 } }, /* edges */
    { { 0, 0 }, { 0x1p255, 1 }, { 1, 0 }, { 0, 1 } },           /* radius outside */
    { { 0, 0 }, { 1, 1 }, { NAN, 0 }, { 0, 1 } },
    { { -HUGE_VAL, 0 }, { 1, 1 }, { 1, 0 }, { 0, 1 } },
};

long plt_balls(xu_exact *x, const ballfmt *F, long n, uint64_t seed, long *passed)
{
    balltally td, te;
    xu_rng r;
    long c;
    int k, i, j;
    char what[64];
    memset(&td, 0, sizeof td);
    memset(&te, 0, sizeof te);
    for (k = 0; k < (int)(sizeof disk_hard / sizeof disk_hard[0]); k++) {
        double m[2][3];
        for (i = 0; i < 2; i++)
            for (j = 0; j < 3; j++) m[i][j] = xu_round_fmt(disk_hard[k][i][j]);
        snprintf(what, sizeof what, "hard disk %d", k);
        run_disk(x, &td, F, (const double(*)[3])m, what);
    }
    for (k = 0; k < (int)(sizeof ell_hard / sizeof ell_hard[0]); k++) {
        double e[4][2];
        for (i = 0; i < 4; i++)
            for (j = 0; j < 2; j++) e[i][j] = xu_round_fmt(ell_hard[k][i][j]);
        snprintf(what, sizeof what, "hard ellipse %d", k);
        run_ellipse(x, &te, F, (const double(*)[2])e, what);
    }
    r.s = seed;
    for (c = 0; c < n; c++) {
        double m[2][3], e[4][2];
        for (i = 0; i < 2; i++) {
            m[i][0] = gen_ball_val(&r, F, F->sb);
            m[i][1] = gen_ball_val(&r, F, F->sb);
            m[i][2] = gen_ball_val(&r, F, F->rt);
        }
        snprintf(what, sizeof what, "random disk %ld", c);
        run_disk(x, &td, F, (const double(*)[3])m, what);
        for (i = 0; i < 4; i++)
            for (j = 0; j < 2; j++) e[i][j] = gen_ball_val(&r, F, i == 0 ? F->rt : F->eb);
        snprintf(what, sizeof what, "random ellipse %ld", c);
        run_ellipse(x, &te, F, (const double(*)[2])e, what);
    }
    printf("test_plane: %s: %ld cases, %ld in-domain axes, %ld checks, %ld failed; statuses OK %ld, "
           "EINVAL %ld, ERANGE %ld; largest end excess %.2f units of u (|t| + sqrt s) + eta (proven: 80)\n",
           F->f32 ? "cbx_disk_box2f" : "cbx_disk_box2", td.cases, td.axes, td.checks, td.failed,
           td.status[0], td.status[2], td.status[3], td.max_units);
    printf("test_plane: %s: %ld cases, %ld in-domain axes, %ld checks, %ld failed; statuses OK %ld, "
           "EINVAL %ld, ERANGE %ld; largest end excess %.2f units of u (|t| + sqrt s) + eta (proven: 80)\n",
           F->f32 ? "cbx_ellipse_box2f" : "cbx_ellipse_box2", te.cases, te.axes, te.checks, te.failed,
           te.status[0], te.status[2], te.status[3], te.max_units);
    *passed += td.cases - td.failed + te.cases - te.failed;
    return td.failed + te.failed;
}
