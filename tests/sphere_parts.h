/*
 * sphere_parts.h: the parts of tests/test_sphere.c (cbx_sphere_box and
 * cbx_ellipsoid_box against GMP and MPFR): the checks and their tallies
 * (tests/sphere_check.c), the exact and MPFR oracle (tests/sphere_oracle.c),
 * the hard cases and the random generators (tests/sphere_cases.c).  The
 * driver, tests/test_sphere.c, runs them in order and prints the summary.
 * Everything here is prefixed spt_: these objects go into the archive
 * every test links (scripts/testutil.sh).
 */
#ifndef SPHERE_PARTS_H
#define SPHERE_PARTS_H

#include <stdio.h>
#include <math.h>

#include <mpfr.h>

#include "certbox.h"
#include "exact_util.h"

#define SANITY 64.0
#define MAX_FAIL_LOGS 20
#define PREC0 256    /* MPFR precision of the tightness evaluation        */
#define PRECMAX 6800 /* enough for any cancellation (see spt_mp_row)      */
#define SH_SPHERE 1074UL   /* s scaled by 2^(2*1074): m_j 2^1074 integers */
#define SH_ELL 2148UL      /* a_ij = rot*radius: a 2^2148 integers        */
#define PT_SHIFT 3222UL    /* rot*radius*p: multiples of 2^-3222          */

#define INF HUGE_VAL
#define P509U 0x1.0000000000001p509
#define P254U 0x1.0000000000001p254
#define P1018U 0x1.0000000000001p1018

/* the checks of one case (see tests/test_sphere.c) */
enum {
    F_STATUS, F_UNSET, F_SPECIAL, F_OOB, F_FINITE, F_CONTAIN,
    F_SANITY,   /* > 64 units where u*(|t|+sqrt s) >= 2^-1000              */
    F_TINYABS,  /* gap > 2^-1000 where u*(|t|+sqrt s) < 2^-1000            */
    F_PROVEN,   /* gap > 80 u (|t|+sqrt s) + 2^-1064: the proven bound     */
    F_POINT, F_INPUT, NF
};

typedef struct verdict {
    cbx_status expected, got;
    int failed;
    int flag[NF], applied[NF];
    char why[200];
} verdict;

typedef struct exstat {
    long n;
    double max, sum;
} exstat;

typedef struct group {
    const char *name;
    long cases, failed, status_seen[4];
    long applied[NF], fails[NF];
    exstat units, units_tiny, units_big, ulps_nocancel;
    double ulps_max;        /* over all ends (huge where an end is ~0)    */
    long ulps_over64;
    long axes, axes_tiny, exact_ends, prec_raised, pts, pts_skipped;
    double worst;           /* largest units (non-tiny) and where         */
    char worst_case[600];
} group;

/* the exact integers and MPFR numbers of one run (tests/sphere_oracle.c) */
typedef struct ctx {
    xu_exact x;
    mpz_t s[3], z, y, w, q;
    mpfr_t S, R, T, EL, EH, G, D;
} ctx;

/* t -+ sqrt(s) in MPFR against one axis's ends (spt_mp_row) */
typedef struct rowres {
    double units_lo, units_hi, ulps_lo, ulps_hi;
    int tiny, big, exact_lo, exact_hi, cancel_lo, cancel_hi, raised, bad_lo, bad_hi;
    int over_proven;        /* an end beyond the proven bound (ball_gap)  */
} rowres;

/* one call: a sphere (the map a) or an ellipsoid */
typedef struct problem {
    int ell;                 /* 0: sphere (a), 1: ellipsoid              */
    cbx_affine a;
    double center[3], radii[3], rot[3][3];
} problem;

/* a hard case of each function, with its expected status and the mask of
 * its out-of-domain axes */
typedef struct sph_case {
    const char *name;
    cbx_affine a;
    cbx_status expect;
    int oob;
} sph_case;

typedef struct ell_case {
    const char *name;
    double center[3], radii[3], rot[3][3];
    cbx_status expect;
    int oob;
} ell_case;

/* ---- tests/sphere_check.c ---------------------------------------------- */

/* failures printed since the last reset (at most MAX_FAIL_LOGS) */
extern long spt_fail_logs;
void spt_g_init(group *g, const char *name);
/* add a case's verdict to the tallies of its group */
void spt_g_add(group *g, const verdict *v);
void spt_g_print(const group *g);
/* the status the contract gives P; *oob: the mask of out-of-domain axes */
cbx_status spt_prob_expected(const problem *P, int *oob);
/* Run one problem.  *mx: largest units over ends (non-tiny axes).  r: the
 * generator of the two random points, or NULL.  Returns 1 on failure. */
int spt_run_problem(ctx *k, group *g, const problem *P, cbx_box *out,
                    verdict *v, double *mx, xu_rng *r);
void spt_log_failure(const char *what, long id, const problem *P,
                     const cbx_box *out, const verdict *v);

/* ---- tests/sphere_oracle.c --------------------------------------------- */

void spt_ctx_init(ctx *k);
void spt_ctx_clear(ctx *k);
/* sphere: k->s[i] = sum_j (m_ij 2^1074)^2, i.e. scaled by 2^(2*1074) */
void spt_sphere_s(ctx *k, const cbx_affine *a, int i);
/* ellipsoid: k->s[i] = sum_j (rot_ij radii_j 2^2148)^2 */
void spt_ell_s(ctx *k, const double radii[3], const double rot[3][3], int i);
/* the double nearest sqrt(s / 2^(2 sh)) (for generators) */
double spt_sqrt_rn(ctx *k, const mpz_t s, unsigned long sh);
/* t -+ sqrt(s / 2^(2 sh)) in MPFR, and lo, hi measured against it */
void spt_mp_row(ctx *k, const mpz_t s, unsigned long sh, double t,
                double lo, double hi, rowres *r);
/* p.p <= 1, exactly */
int spt_in_ball(ctx *k, const double p[3]);
/* p = sign v/|v| rounded (v_j = f_j 2^e_j), nudged toward 0 until
 * p.p <= 1; 0 if skipped */
int spt_unit_point(ctx *k, const double f[3], const int e[3], double sign,
                   double p[3]);
/* exact y = t + sum_j m_j p_j (sphere), scaled by 2^PT_SHIFT, in k->y */
void spt_sphere_image(ctx *k, const cbx_affine *a, int i, const double p[3]);
/* exact y = c + sum_j rot_ij radii_j p_j, scaled by 2^PT_SHIFT, in k->y */
void spt_ell_image(ctx *k, const double c[3], const double radii[3],
                   const double rot[3][3], int i, const double p[3]);

/* ---- tests/sphere_cases.c ---------------------------------------------- */

extern const sph_case spt_sph_hard[];
extern const int spt_n_sph_hard;
extern const ell_case spt_ell_hard[];
extern const int spt_n_ell_hard;
/* random problems (k: for the exact s of each row) */
void spt_gen_sphere(xu_rng *r, ctx *k, problem *P);
void spt_gen_ellipsoid(xu_rng *r, ctx *k, problem *P);

#endif /* SPHERE_PARTS_H */
