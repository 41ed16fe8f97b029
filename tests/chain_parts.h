/*
 * chain_parts.h: the parts of tests/test_chain.c (the stability of repeated
 * transforms, checked exactly with GMP), shared by its files:
 *   tests/chain_exact.c  the exact context: the composed map P kept as
 *                        mpq_t, the corners of B_0 mapped by it against a
 *                        box or a cbox, the exact widths, and one checked
 *                        step of the cbox chain;
 *   tests/chain_cases.c  the tallies of the checks and the failure log, the
 *                        random maps and boxes, cbx_transform_box_chain's
 *                        special cases, and the statistics.
 * The driver, tests/test_chain.c, runs the chains in order and prints the
 * summary.  Every name with linkage starts with cht_ (one archive, every
 * test links it: build/libtestutil.a).
 */
#ifndef CHAIN_PARTS_H
#define CHAIN_PARTS_H

#include <stddef.h>

#include "certbox.h"
#include "exact_util.h"

#define MAX_FAIL_LOGS 20

/* the checks (see tests/test_chain.c) */
enum { K_START, K_BOX, K_CBOX, K_BOXC, K_CBOXC, K_CHAIN, K_CHSPEC, NK };

typedef struct ctx {
    xu_exact x;
    mpq_t P[3][4], N[3][4];     /* composed exact map, and the next one   */
    mpq_t q, qa, qb, qlo, qhi;
    mpq_t prod[3][3][2];        /* P_ij * lo_j / hi_j of the original box */
} ctx;

/* ---- tests/chain_exact.c ----------------------------------------------- */

void cht_ctx_init(ctx *k);
void cht_ctx_clear(ctx *k);
/* P <- A P, exactly */
void cht_compose(ctx *k, const cbx_affine *a);
void cht_set_identity(ctx *k);
/* the largest numerator or denominator of P, in bits */
size_t cht_max_bits(ctx *k);
/* prod[i][j][0/1] = P_ij * lo_j / hi_j of the original box B_0 */
void cht_fill_prod(ctx *k, const cbx_box *b0);
/* P(B_0) inside the box b?  The number of failures (cht_fill_prod first). */
int cht_composed_box_failures(ctx *k, const cbx_box *b);
/* P(B_0) inside the real box [c - h, c + h] (h = +inf: the whole line)? */
int cht_composed_cbox_failures(ctx *k, const cbx_cbox *cb);
/* exact width of the bound of P(B_0) on axis i: sum_j |P_ij| (hi_j - lo_j) */
double cht_exact_width(ctx *k, const cbx_box *b0, int i);
/* one step of the cbox chain, checked; 1 on failure (why: the reason) */
int cht_cbox_step(ctx *k, const cbx_affine *a, const cbx_cbox *in, cbx_cbox *out,
                  char *why, size_t nwhy);

/* ---- tests/chain_cases.c ----------------------------------------------- */

extern const char *const cht_k_name[NK];
extern long cht_k_checked[NK], cht_k_failed[NK];
/* failures printed (at most MAX_FAIL_LOGS) */
extern long cht_logs;
void cht_report(int kind, int chain, long step, const char *why);
/* a random rigid map (rotation in doubles, small translation) */
void cht_random_step(xu_rng *r, cbx_affine *a);
/* the start box of a chain (every 5th flat on axis 2) */
void cht_random_box(xu_rng *r, int chain, cbx_box *b);
/* cbx_transform_box_chain's special cases; returns the number failed */
int cht_chain_special(xu_rng *r);
/* a / b, +inf instead of NaN */
double cht_ratio(double a, double b);
/* max and median of v[0..n-1] (sorted in place) */
void cht_max_med(double *v, int n, double *mx, double *med);

#endif /* CHAIN_PARTS_H */
