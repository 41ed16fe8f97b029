/*
 * imat_parts.h: the parts of test_imat (tests/test_imat.c, the driver: the
 * interval-matrix functions of certbox.h against exact arithmetic), shared
 * by its files:
 *   tests/imat_check.c  the checks and their tallies: one coordinate's
 *                       rules and exact ends, one whole call, the product
 *                       check, printing the tallies;
 *   tests/imat_gen.c    the inputs (random interval matrices and boxes,
 *                       pushed out of range, NaN, inverted, empty) and
 *                       printing them;
 *   tests/imat_teeth.c  the teeth: doctored results the checker must catch.
 * Every name with linkage starts with imt_ (one archive, every test links
 * it: build/libtestutil.a).
 */
#ifndef IMAT_PARTS_H
#define IMAT_PARTS_H

#include <math.h>

#include "certbox.h"
#include "exact_util.h"

#define INF HUGE_VAL
#define SB 0x1p509      /* linear entries and box ends */
#define RT 0x1p1018     /* translations */
#define TEETH_MAX 60    /* doctored results per kind of tooth */

/* ---------------------------------------------------------------------- */
/* The checks and their tallies (tests/imat_check.c)                      */
/* ---------------------------------------------------------------------- */

enum { C_STATUS, C_WRITTEN, C_SPECIAL, C_WHOLE, C_FINITE, C_CONTAIN, C_TIGHT, C_CROSS,
       C_POINTS, C_PRODUCT, C_ALIAS, C_INPUT, NC };

typedef struct tally {
    long n[NC], f[NC];
    char why[300];              /* the first failure of the current case */
} tally;

/* Count one check; 1 if it failed (the first reason is kept). */
int imt_tick(tally *t, int c, int ok, const char *why, int coord);

/* Excess statistics, in units of u S + eta. */
typedef struct exstat {
    long ends, tiny;
    double max, sum, max_tiny;
} exstat;

void imt_ex_add(exstat *e, double v, int tiny);

/* One coordinate: its inputs (transform: row i of a and the box; compose:
 * row i of a and column j of b). */
typedef struct row {
    double ml[3], mh[3];        /* linear entries */
    double tl, th;              /* translation */
    double l[3], h[3];          /* box (compose: a column of b) */
} row;

row imt_trow(const cbx_imat *a, int i, const cbx_box *b);
row imt_crow(const cbx_imat *a, const cbx_imat *b, int i, int j);
/* The coordinate is in the fast range (the rules of test_imat.c's header). */
int imt_row_fast(const row *r);

typedef struct ctx {
    xu_exact x;                 /* exact_util's scratch */
    mpz_t L, H, S, p[4], g, g2, tol, z;
    mpq_t q, qa, qb, qs, qmin, qmax, qt;
    xu_rng rng;
} ctx;

/* Exact ends and scale of one fast coordinate, scaled by 2^2148:
 * k->L, k->H, k->S. */
void imt_row_exact(ctx *k, const row *r);
/* k->tol = (12 u S + 2^-1065) 2^(2148 + 53) = 12 S + 2^1136 (S scaled). */
void imt_tol53(ctx *k);
/* The checks of one cbx_transform_box_imat result (ex: excess statistics,
 * NULL: none; deep: also cross and points); returns the failures. */
int imt_check_transform(ctx *k, tally *t, exstat *ex, const cbx_imat *a, const cbx_box *in,
                        const cbx_box *out, cbx_status got, int deep, cbx_status *expected);
/* The checks of one cbx_imat_compose result. */
int imt_check_compose(ctx *k, tally *t, exstat *ex, const cbx_imat *a, const cbx_imat *b,
                      const cbx_imat *out, cbx_status got, int deep, cbx_status *expected);
/* Every entry of a has a real number (no [+inf, +inf] or [-inf, -inf]). */
int imt_has_real(const cbx_imat *a);
/* product: random real A in a, B in b; every entry of A B in out. */
int imt_check_product(ctx *k, tally *t, const cbx_imat *a, const cbx_imat *b, const cbx_imat *out,
                      mpq_t A[3][4], mpq_t B[3][4]);
void imt_print_tally(const tally *t);
void imt_print_ex(const char *what, const exstat *e);
/* The checks made in *t; their failures added to *failed. */
long imt_checks_of(const tally *t, long *failed);

/* ---------------------------------------------------------------------- */
/* Inputs (tests/imat_gen.c)                                              */
/* ---------------------------------------------------------------------- */

/* Intervals of a random rotation (or of a scaled one), each entry its
 * double widened by 0 to 2 ulps on each side: the maps of a node chain. */
void imt_gen_rot(xu_rng *r, cbx_imat *a, int with_t);
/* A random interval matrix within the fast range (every row: linear
 * entries within 2^509, translation within 2^ttop). */
void imt_gen_imat(xu_rng *r, cbx_imat *a, int ttop);
void imt_gen_box(xu_rng *r, cbx_box *b);
/* Row i's translation cancelling the linear part at the box's centre. */
void imt_cancel_t(xu_rng *r, cbx_imat *a, const cbx_box *b, int i);
/* Make one axis of b have no real point. */
void imt_make_empty(xu_rng *r, cbx_box *b);
/* Perturbations common to both functions: out of range (20%), NaN (2%),
 * inverted (2%).  Returns 1 if something was pushed out of range. */
int imt_perturb(xu_rng *r, cbx_imat *a, cbx_box *b, cbx_imat *b2);
void imt_print_imat(const char *name, const cbx_imat *a);
void imt_print_box(const char *name, const cbx_box *b);

/* ---------------------------------------------------------------------- */
/* Teeth (tests/imat_teeth.c)                                             */
/* ---------------------------------------------------------------------- */

enum { T_INSIDE, T_LOOSE, T_WHOLE, T_STATUS, T_PRODUCT, NT };
extern const char *const imt_t_name[NT];
/* doctored results made and caught, per kind */
extern long imt_teeth_n[NT], imt_teeth_caught[NT];
/* Doctor the coordinates of one cbx_transform_box_imat result. */
void imt_teeth_transform(ctx *k, const cbx_imat *a, const cbx_box *in, const cbx_box *out,
                         cbx_status got);
/* Point matrices a, b: an entry of their product moved past it. */
void imt_teeth_product(ctx *k, mpq_t A[3][4], mpq_t B[3][4]);

#endif /* IMAT_PARTS_H */
