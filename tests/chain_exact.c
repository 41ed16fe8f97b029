/*
 * chain_exact.c: part of tests/test_chain.c (chain_parts.h): the exact
 * context of a chain: the composed map P = A_{k-1} o ... o A_0 kept as
 * mpq_t, the 8 corners of the original box B_0 mapped by it against a box
 * or a cbox, the exact width of the bound of P(B_0), and one step of the
 * cbox chain checked against the exact oracle (exact_util's cbox rules).
 */
#include <stdio.h>
#include <math.h>

#include "chain_parts.h"

/* ---------------------------------------------------------------------- */
/* The exact context                                                      */
/* ---------------------------------------------------------------------- */

void cht_ctx_init(ctx *k)
{
    int i, j, s;
    xu_init(&k->x);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) {
            mpq_init(k->P[i][j]);
            mpq_init(k->N[i][j]);
        }
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            for (s = 0; s < 2; s++) mpq_init(k->prod[i][j][s]);
    mpq_inits(k->q, k->qa, k->qb, k->qlo, k->qhi, (mpq_ptr)0);
}

void cht_ctx_clear(ctx *k)
{
    int i, j, s;
    xu_clear(&k->x);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) {
            mpq_clear(k->P[i][j]);
            mpq_clear(k->N[i][j]);
        }
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            for (s = 0; s < 2; s++) mpq_clear(k->prod[i][j][s]);
    mpq_clears(k->q, k->qa, k->qb, k->qlo, k->qhi, (mpq_ptr)0);
}

/* ---------------------------------------------------------------------- */
/* Exact composition: P <- A P                                            */
/* ---------------------------------------------------------------------- */

void cht_compose(ctx *k, const cbx_affine *a)
{
    int i, j, l;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) {
            if (j == 3) mpq_set_d(k->N[i][j], a->m[i][3]);
            else mpq_set_ui(k->N[i][j], 0, 1);
            for (l = 0; l < 3; l++) {
                mpq_set_d(k->q, a->m[i][l]);
                mpq_mul(k->q, k->q, k->P[l][j]);
                mpq_add(k->N[i][j], k->N[i][j], k->q);
            }
        }
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) mpq_swap(k->P[i][j], k->N[i][j]);
}

void cht_set_identity(ctx *k)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) mpq_set_ui(k->P[i][j], i == j, 1);
}

static size_t bits_q(const mpq_t q)
{
    size_t a = mpz_sizeinbase(mpq_numref(q), 2), b = mpz_sizeinbase(mpq_denref(q), 2);
    return a > b ? a : b;
}

size_t cht_max_bits(ctx *k)
{
    size_t m = 0, b;
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++)
            if ((b = bits_q(k->P[i][j])) > m) m = b;
    return m;
}

/* prod[i][j][0/1] = P_ij * lo_j / hi_j of the original box B_0 */
void cht_fill_prod(ctx *k, const cbx_box *b0)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            mpq_set_d(k->q, b0->lo[j]);
            mpq_mul(k->prod[i][j][0], k->P[i][j], k->q);
            mpq_set_d(k->q, b0->hi[j]);
            mpq_mul(k->prod[i][j][1], k->P[i][j], k->q);
        }
}

/* The 8 corners of B_0 mapped exactly by P against [qlo, qhi] on axis i
 * (call fill_prod first; an infinite end, lo_inf / hi_inf, contains
 * everything).  Returns the number of failed inequalities. */
static int corners_outside(ctx *k, int i, int lo_inf, int hi_inf)
{
    unsigned c;
    int j, bad = 0;
    for (c = 0; c < 8; c++) {
        mpq_set(k->q, k->P[i][3]);
        for (j = 0; j < 3; j++) mpq_add(k->q, k->q, k->prod[i][j][(c >> j) & 1u]);
        if (!lo_inf && mpq_cmp(k->qlo, k->q) > 0) bad++;
        if (!hi_inf && mpq_cmp(k->q, k->qhi) > 0) bad++;
    }
    return bad;
}

/* P(B_0) inside the box b?  Returns the number of failures. */
int cht_composed_box_failures(ctx *k, const cbx_box *b)
{
    int i, bad = 0;
    for (i = 0; i < 3; i++) {
        int lo_inf = isinf(b->lo[i]) && b->lo[i] < 0, hi_inf = isinf(b->hi[i]) && b->hi[i] > 0;
        if ((!lo_inf && !isfinite(b->lo[i])) || (!hi_inf && !isfinite(b->hi[i]))) {
            bad++; /* NaN, lo = +inf or hi = -inf: nothing is inside */
            continue;
        }
        if (!lo_inf) mpq_set_d(k->qlo, b->lo[i]);
        if (!hi_inf) mpq_set_d(k->qhi, b->hi[i]);
        bad += corners_outside(k, i, lo_inf, hi_inf);
    }
    return bad;
}

/* P(B_0) inside the real box [c - h, c + h] (h = +inf: the whole line)? */
int cht_composed_cbox_failures(ctx *k, const cbx_cbox *cb)
{
    int i, bad = 0;
    for (i = 0; i < 3; i++) {
        if (isinf(cb->h[i]) && cb->h[i] > 0 && !isnan(cb->c[i])) continue;
        if (!isfinite(cb->c[i]) || !isfinite(cb->h[i])) {
            bad++;
            continue;
        }
        mpq_set_d(k->qa, cb->c[i]);
        mpq_set_d(k->qb, cb->h[i]);
        mpq_sub(k->qlo, k->qa, k->qb);
        mpq_add(k->qhi, k->qa, k->qb);
        bad += corners_outside(k, i, 0, 0);
    }
    return bad;
}

/* Exact width of the bound of P(B_0) on axis i: sum_j |P_ij| (hi_j - lo_j). */
double cht_exact_width(ctx *k, const cbx_box *b0, int i)
{
    int j;
    mpq_set_ui(k->qa, 0, 1);
    for (j = 0; j < 3; j++) {
        mpq_set_d(k->q, b0->hi[j]);
        mpq_set_d(k->qb, b0->lo[j]);
        mpq_sub(k->q, k->q, k->qb);
        mpq_abs(k->qb, k->P[i][j]);
        mpq_mul(k->q, k->q, k->qb);
        mpq_add(k->qa, k->qa, k->q);
    }
    return mpq_get_d(k->qa);
}

/* ---------------------------------------------------------------------- */
/* One step of the cbox chain, checked                                    */
/* ---------------------------------------------------------------------- */

int cht_cbox_step(ctx *k, const cbx_affine *a, const cbx_cbox *in, cbx_cbox *out,
                  char *why, size_t nwhy)
{
    cbx_status got, want;
    int i, j, mask = 0;
    unsigned c;
    for (i = 0; i < 3; i++) out->c[i] = out->h[i] = NAN;
    got = cbx_transform_cbox(a, in, out);
    want = xu_cbox_expected_status(a, in);
    if (want == CBX_OK || want == CBX_ERANGE) mask = xu_cbox_loss_mask(a, in);
    if (got != want) {
        snprintf(why, nwhy, "status %s, expected %s", cbx_status_name(got), cbx_status_name(want));
        return 1;
    }
    for (i = 0; i < 3; i++)
        if (isnan(out->c[i]) || isnan(out->h[i])) {
            snprintf(why, nwhy, "NaN left in out axis %d", i);
            return 1;
        }
    if (want != CBX_OK && want != CBX_ERANGE) {
        snprintf(why, nwhy, "unexpected status %s in a chain", cbx_status_name(want));
        return 1;
    }
    for (i = 0; i < 3; i++) {
        cbx_cbox d;  /* the box row i is checked on: zero columns dropped */
        if (mask & (1 << i)) {
            if (!(out->c[i] == 0 && isinf(out->h[i]) && out->h[i] > 0)) {
                snprintf(why, nwhy, "axis %d lost (W) but not c = 0, h = +inf", i);
                return 1;
            }
            continue;
        }
        /* kind A: the same box; kind D: c_j = h_j = 0 where m_ij == 0 */
        xu_cbox_dropped(a, in, i, &d);
        if (!isfinite(out->c[i]) || !isfinite(out->h[i])) {
            snprintf(why, nwhy, "axis %d (A or D) but not finite", i);
            return 1;
        }
        mpq_set_d(k->qa, out->c[i]);
        mpq_set_d(k->qb, out->h[i]);
        mpq_sub(k->qlo, k->qa, k->qb);
        mpq_add(k->qhi, k->qa, k->qb);
        for (c = 0; c < 8; c++) {
            mpq_set_d(k->q, a->m[i][3]);
            for (j = 0; j < 3; j++) {
                mpq_set_d(k->qa, d.c[j]);
                mpq_set_d(k->qb, d.h[j]);
                if ((c >> j) & 1u) mpq_add(k->qa, k->qa, k->qb);
                else mpq_sub(k->qa, k->qa, k->qb);
                mpq_set_d(k->qb, a->m[i][j]);
                mpq_mul(k->qa, k->qa, k->qb);
                mpq_add(k->q, k->q, k->qa);
            }
            if (mpq_cmp(k->qlo, k->q) > 0 || mpq_cmp(k->q, k->qhi) > 0) {
                snprintf(why, nwhy, "axis %d: corner %u's exact image outside [c - h, c + h]", i, c);
                return 1;
            }
        }
    }
    return 0;
}
