/*
 * The exact and MPFR oracle of tests/test_sphere.c (tests/sphere_parts.h):
 * the squared row norms s as integers, t -+ sqrt(s) in MPFR with the
 * precision raised on cancellation, points of the unit ball and their exact
 * images.
 */
#include <limits.h>
#include <math.h>
#include <string.h>

#include "sphere_parts.h"

/* ---------------------------------------------------------------------- */
/* Exact and MPFR context                                                 */
/* ---------------------------------------------------------------------- */

void spt_ctx_init(ctx *k)
{
    int i;
    xu_init(&k->x);
    for (i = 0; i < 3; i++) mpz_init(k->s[i]);
    mpz_inits(k->z, k->y, k->w, k->q, (mpz_ptr)0);
    mpfr_inits2(PREC0, k->S, k->R, k->T, k->EL, k->EH, k->G, k->D, (mpfr_ptr)0);
}

void spt_ctx_clear(ctx *k)
{
    int i;
    xu_clear(&k->x);
    for (i = 0; i < 3; i++) mpz_clear(k->s[i]);
    mpz_clears(k->z, k->y, k->w, k->q, (mpz_ptr)0);
    mpfr_clears(k->S, k->R, k->T, k->EL, k->EH, k->G, k->D, (mpfr_ptr)0);
}

/* sphere: s_i = sum_j (m_ij 2^1074)^2, i.e. scaled by 2^(2*1074) */
void spt_sphere_s(ctx *k, const cbx_affine *a, int i)
{
    int j;
    mpz_set_ui(k->s[i], 0);
    for (j = 0; j < 3; j++) {
        xu_scaled_sh(k->z, a->m[i][j], SH_SPHERE);
        mpz_addmul(k->s[i], k->z, k->z);
    }
}

/* ellipsoid: s_i = sum_j (rot_ij radii_j 2^2148)^2 */
void spt_ell_s(ctx *k, const double radii[3], const double rot[3][3], int i)
{
    int j;
    mpz_set_ui(k->s[i], 0);
    for (j = 0; j < 3; j++) {
        xu_scaled_mul(&k->x, k->z, rot[i][j], radii[j]);
        mpz_addmul(k->s[i], k->z, k->z);
    }
}

/* the double nearest sqrt(s / 2^(2 sh)) (for generators) */
double spt_sqrt_rn(ctx *k, const mpz_t s, unsigned long sh)
{
    mpfr_set_prec(k->S, PREC0);
    mpfr_set_z(k->S, s, MPFR_RNDN);
    mpfr_div_2ui(k->S, k->S, 2 * sh, MPFR_RNDN);
    mpfr_sqrt(k->S, k->S, MPFR_RNDN);
    return mpfr_get_d(k->S, MPFR_RNDN);
}

/* ulp of the exact end X (the spacing of binary64 at |X|) */
static long ulp_exp(mpfr_t X)
{
    long e;
    if (mpfr_zero_p(X)) return -1074;
    e = (long)mpfr_get_exp(X) - 53; /* |X| in [2^(E-1), 2^E) */
    return e < -1074 ? -1074 : e;
}

/* Compute t -+ sqrt(s') (s' = s / 2^(2 sh)) in MPFR and measure lo, hi.
 * Precision: every end must be known to 2^-128 relative.  A first pass at
 * PREC0 bits; when t and sqrt(s') cancel (the end is 2^-c times the
 * larger of the two), again at c + PREC0 bits.  No end can be smaller than
 * 2^-5316 times the top unless it is 0: s' is a multiple of 2^-4296 and t
 * of 2^-1074, so t^2 - s' != 0 is at least 2^-4296 and the end is at least
 * that over |t| + sqrt(s') <= 2^1020.  PRECMAX covers it, and there s' is
 * held exactly. */
void spt_mp_row(ctx *k, const mpz_t s, unsigned long sh, double t,
                double lo, double hi, rowres *r)
{
    mpfr_prec_t prec = PREC0;
    int exS, exR, exL, exH;
    memset(r, 0, sizeof *r);
    for (;;) {
        long top, need = 0;
        int ok = 1;
        mpfr_set_prec(k->S, prec);
        mpfr_set_prec(k->R, prec);
        mpfr_set_prec(k->T, prec);
        mpfr_set_prec(k->EL, prec);
        mpfr_set_prec(k->EH, prec);
        exS = mpfr_set_z(k->S, s, MPFR_RNDN);
        mpfr_div_2ui(k->S, k->S, 2 * sh, MPFR_RNDN); /* exact */
        exR = mpfr_sqrt(k->R, k->S, MPFR_RNDN);
        mpfr_set_d(k->T, t, MPFR_RNDN);               /* exact */
        exL = mpfr_sub(k->EL, k->T, k->R, MPFR_RNDN);
        exH = mpfr_add(k->EH, k->T, k->R, MPFR_RNDN);
        if (mpfr_zero_p(k->R)) break; /* both ends are t, exact */
        top = (long)mpfr_get_exp(k->R);
        if (!mpfr_zero_p(k->T) && (long)mpfr_get_exp(k->T) > top)
            top = (long)mpfr_get_exp(k->T);
        if (!(exS == 0 && exR == 0 && exL == 0)) {
            if (mpfr_zero_p(k->EL)) ok = 0, need = PRECMAX;
            else if (top - (long)mpfr_get_exp(k->EL) + 128 > (long)prec) {
                ok = 0;
                need = top - (long)mpfr_get_exp(k->EL);
            }
        }
        if (!(exS == 0 && exR == 0 && exH == 0)) {
            if (mpfr_zero_p(k->EH)) ok = 0, need = PRECMAX;
            else if (top - (long)mpfr_get_exp(k->EH) + 128 > (long)prec) {
                long nh = top - (long)mpfr_get_exp(k->EH);
                ok = 0;
                if (nh > need) need = nh;
            }
        }
        if (ok || prec >= PRECMAX) break;
        r->raised = 1;
        need += PREC0;
        prec = need > 2 * (long)prec ? (mpfr_prec_t)need : 2 * prec;
        if (prec > PRECMAX) prec = PRECMAX;
    }

    /* scale |t| + sqrt(s'), tiny when u * scale < 2^-1000 */
    mpfr_set_prec(k->D, prec + 8);
    mpfr_abs(k->D, k->T, MPFR_RNDN);
    mpfr_add(k->D, k->D, k->R, MPFR_RNDN);
    r->tiny = mpfr_cmp_ui_2exp(k->D, 1, -947) < 0;
    r->big = mpfr_cmp_ui_2exp(k->D, 1, -480) >= 0;
    /* cancellation: |end| < (|t| + sqrt(s'))/4 */
    r->cancel_lo = mpfr_zero_p(k->EL)
                   || mpfr_get_exp(k->EL) < mpfr_get_exp(k->D) - 2;
    r->cancel_hi = mpfr_zero_p(k->EH)
                   || mpfr_get_exp(k->EH) < mpfr_get_exp(k->D) - 2;
    /* the proven bound (specs/cbx_spec.h, ball_gap): 80 u scale + 2^-1064,
     * rounded up */
    mpfr_t P;
    mpfr_init2(P, 128);
    mpfr_mul_ui(P, k->D, 80, MPFR_RNDU);
    mpfr_mul_2si(P, P, -53, MPFR_RNDU);
    {
        mpfr_t E;
        mpfr_init2(E, 64);
        mpfr_set_ui_2exp(E, 1, -1064, MPFR_RNDN);
        mpfr_add(P, P, E, MPFR_RNDU);
        mpfr_clear(E);
    }
    /* D = u * scale + eta */
    mpfr_mul_2si(k->D, k->D, -53, MPFR_RNDN);
    mpfr_set_prec(k->G, 64);
    mpfr_set_ui_2exp(k->G, 1, -1074, MPFR_RNDN);
    mpfr_add(k->D, k->D, k->G, MPFR_RNDN);

    mpfr_set_prec(k->G, prec + 64);
    /* lower end: exact_lo - lo */
    mpfr_sub_d(k->G, k->EL, lo, MPFR_RNDN);
    r->exact_lo = mpfr_zero_p(k->G);
    r->over_proven = mpfr_cmp(k->G, P) > 0;
    r->bad_lo = mpfr_cmp_ui_2exp(k->G, 1, -1064) > 0;
    mpfr_mul_2si(k->G, k->G, -ulp_exp(k->EL), MPFR_RNDN);
    r->ulps_lo = mpfr_get_d(k->G, MPFR_RNDN);
    mpfr_sub_d(k->G, k->EL, lo, MPFR_RNDN);
    mpfr_div(k->G, k->G, k->D, MPFR_RNDN);
    r->units_lo = mpfr_get_d(k->G, MPFR_RNDN);
    r->bad_lo = r->bad_lo && r->units_lo > SANITY;
    /* upper end: hi - exact_hi */
    mpfr_set_d(k->T, hi, MPFR_RNDN);
    mpfr_sub(k->G, k->T, k->EH, MPFR_RNDN);
    r->exact_hi = mpfr_zero_p(k->G);
    r->over_proven |= mpfr_cmp(k->G, P) > 0;
    mpfr_clear(P);
    r->bad_hi = mpfr_cmp_ui_2exp(k->G, 1, -1064) > 0;
    mpfr_mul_2si(k->G, k->G, -ulp_exp(k->EH), MPFR_RNDN);
    r->ulps_hi = mpfr_get_d(k->G, MPFR_RNDN);
    mpfr_sub(k->G, k->T, k->EH, MPFR_RNDN);
    mpfr_div(k->G, k->G, k->D, MPFR_RNDN);
    r->units_hi = mpfr_get_d(k->G, MPFR_RNDN);
    r->bad_hi = r->bad_hi && r->units_hi > SANITY;
}

/* ---------------------------------------------------------------------- */
/* Points in the unit ball                                                */
/* ---------------------------------------------------------------------- */

/* p.p <= 1, exactly */
int spt_in_ball(ctx *k, const double p[3])
{
    int j;
    mpz_set_ui(k->w, 0);
    for (j = 0; j < 3; j++) {
        xu_scaled_sh(k->z, p[j], 1074);
        mpz_addmul(k->w, k->z, k->z);
    }
    mpz_set_ui(k->z, 1);
    mpz_mul_2exp(k->z, k->z, 2148);
    return mpz_cmp(k->w, k->z) <= 0;
}

/* p = v/|v| rounded, nudged toward 0 until p.p <= 1 (at most 4 times).
 * v is given as f_j 2^e_j (f_j = 0 allowed).  Returns 0 if skipped. */
int spt_unit_point(ctx *k, const double f[3], const int e[3], double sign,
                   double p[3])
{
    int j, E = INT_MIN, tries;
    double n2 = 0, n;
    for (j = 0; j < 3; j++)
        if (f[j] != 0 && e[j] > E) E = e[j];
    if (E == INT_MIN) { p[0] = sign; p[1] = p[2] = 0; return 1; }
    for (j = 0; j < 3; j++) {
        p[j] = f[j] != 0 ? ldexp(f[j], e[j] - E) : 0.0; /* |p_j| < 1 */
        n2 += p[j] * p[j];
    }
    n = sqrt(n2);
    for (j = 0; j < 3; j++) p[j] = sign * (p[j] / n);
    for (tries = 0; tries < 4; tries++) {
        if (spt_in_ball(k, p)) return 1;
        for (j = 0; j < 3; j++) p[j] = nextafter(p[j], 0.0);
    }
    return 0;
}

/* exact y = t + sum_j m_j p_j (sphere), scaled by 2^PT_SHIFT, in k->y */
void spt_sphere_image(ctx *k, const cbx_affine *a, int i, const double p[3])
{
    int j;
    xu_scaled_sh(k->y, a->m[i][3], PT_SHIFT);
    for (j = 0; j < 3; j++) {
        xu_scaled_mul(&k->x, k->z, a->m[i][j], p[j]); /* 2^2148 */
        mpz_mul_2exp(k->z, k->z, PT_SHIFT - 2148);
        mpz_add(k->y, k->y, k->z);
    }
}

/* exact y = c + sum_j rot_ij radii_j p_j, scaled by 2^PT_SHIFT */
void spt_ell_image(ctx *k, const double c[3], const double radii[3],
                   const double rot[3][3], int i, const double p[3])
{
    int j;
    xu_scaled_sh(k->y, c[i], PT_SHIFT);
    for (j = 0; j < 3; j++) {
        long e = xu_split_d(k->z, rot[i][j]);
        e += xu_split_d(k->w, radii[j]);
        mpz_mul(k->z, k->z, k->w);
        e += xu_split_d(k->w, p[j]);
        mpz_mul(k->z, k->z, k->w);
        mpz_mul_2exp(k->z, k->z, (mp_bitcnt_t)(e + (long)PT_SHIFT)); /* e >= -3222 */
        mpz_add(k->y, k->y, k->z);
    }
}
