/*
 * imat_teeth.c: the teeth of test_imat (tests/test_imat.c): the checker run
 * on doctored results (an end moved inside the exact image or beyond the
 * proven bound, a whole coordinate made finite, a status flipped, a compose
 * entry moved past the exact product) must fail; the counts are kept in
 * imt_teeth_n / imt_teeth_caught.
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <float.h>
#include <math.h>

#include "certbox.h"
#include "exact_util.h"
#include "imat_parts.h"

/* ---------------------------------------------------------------------- */
/* Teeth: doctored results must be caught                                 */
/* ---------------------------------------------------------------------- */

/* The first double above (up) or below (!up) the value v / 2^(2148 + 53),
 * i.e. strictly beyond it; v is within the double range. */
static double past(ctx *k, const mpz_t v, int up)
{
    long e;
    double d = mpz_get_d_2exp(&e, v);
    d = ldexp(d, (int)(e - 2148 - 53));
    for (;;) { /* move until strictly beyond, then back while still beyond */
        xu_scaled_sh(k->z, d, 2148 + 53);
        int c = mpz_cmp(k->z, v);
        if (up ? c > 0 : c < 0) break;
        d = nextafter(d, up ? INF : -INF);
    }
    for (;;) {
        double n = nextafter(d, up ? -INF : INF);
        xu_scaled_sh(k->z, n, 2148 + 53);
        int c = mpz_cmp(k->z, v);
        if (!(up ? c > 0 : c < 0)) break;
        d = n;
    }
    return d;
}

const char *const imt_t_name[NT] = { "end inside the image", "end beyond the bound",
                                    "whole coord finite", "status flipped", "compose product" };
long imt_teeth_n[NT], imt_teeth_caught[NT];

static void tooth(int kind, int caught)
{
    imt_teeth_n[kind]++;
    imt_teeth_caught[kind] += caught != 0;
}

/* Doctor one coordinate [lo, hi] of a fast row and a checker that sees it:
 * moved inside the exact image, or beyond the proven bound. */
static void teeth_coord(ctx *k, const row *r, double *lo, double *hi, int which)
{
    imt_row_exact(k, r);
    imt_tol53(k);
    if (which == 0) { /* first double above L / below H */
        mpz_mul_2exp(k->g, k->L, 53);
        *lo = past(k, k->g, 1);
    } else if (which == 1) {
        mpz_mul_2exp(k->g, k->H, 53);
        *hi = past(k, k->g, 0);
    } else if (which == 2) { /* first double below L - tol / above H + tol */
        mpz_mul_2exp(k->g, k->L, 53);
        mpz_sub(k->g, k->g, k->tol);
        *lo = past(k, k->g, 0);
    } else {
        mpz_mul_2exp(k->g, k->H, 53);
        mpz_add(k->g, k->g, k->tol);
        *hi = past(k, k->g, 1);
    }
}

void imt_teeth_transform(ctx *k, const cbx_imat *a, const cbx_box *in, const cbx_box *out,
                         cbx_status got)
{
    tally scratch;
    cbx_status e;
    cbx_box d;
    int i, w;
    for (i = 0; i < 3; i++) {
        row r = imt_trow(a, i, in);
        if (imt_row_fast(&r)) {
            for (w = 0; w < 4; w++) {
                int kind = w < 2 ? T_INSIDE : T_LOOSE;
                if (imt_teeth_n[kind] >= TEETH_MAX) continue;
                d = *out;
                teeth_coord(k, &r, &d.lo[i], &d.hi[i], w);
                memset(&scratch, 0, sizeof scratch);
                tooth(kind, imt_check_transform(k, &scratch, NULL, a, in, &d, got, 0, &e));
            }
        } else if (imt_teeth_n[T_WHOLE] < TEETH_MAX) {
            d = *out;
            d.lo[i] = 0.0;
            d.hi[i] = 0.0;
            memset(&scratch, 0, sizeof scratch);
            tooth(T_WHOLE, imt_check_transform(k, &scratch, NULL, a, in, &d, got, 0, &e));
        }
    }
    if (imt_teeth_n[T_STATUS] < TEETH_MAX && (got == CBX_OK || got == CBX_ERANGE)) {
        memset(&scratch, 0, sizeof scratch);
        tooth(T_STATUS, imt_check_transform(k, &scratch, NULL, a, in, out,
                                            got == CBX_OK ? CBX_ERANGE : CBX_OK, 0, &e));
    }
}

/* Point matrices a, b: the product A B is one matrix; an entry moved to
 * the first double past it must fail the product check. */
void imt_teeth_product(ctx *k, mpq_t A[3][4], mpq_t B[3][4])
{
    cbx_imat a, b, o;
    tally scratch;
    int i, j, m;
    imt_gen_rot(&k->rng, &a, 1);
    imt_gen_rot(&k->rng, &b, 1);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) {
            a.hi[i][j] = a.lo[i][j];
            b.hi[i][j] = b.lo[i][j];
        }
    cbx_imat_compose(&a, &b, &o);
    i = xu_rng_int(&k->rng, 0, 2);
    j = xu_rng_int(&k->rng, 0, 3);
    row r = imt_crow(&a, &b, i, j);
    m = xu_rng_int(&k->rng, 0, 1);
    teeth_coord(k, &r, &o.lo[i][j], &o.hi[i][j], m);
    memset(&scratch, 0, sizeof scratch);
    tooth(T_PRODUCT, imt_check_product(k, &scratch, &a, &b, &o, A, B));
}
