/*
 * scene_exact.c: part of tests/test_scene.c (scene_parts.h): the exact
 * maps (mpq): a node's operations, a motion node's interpolation and a
 * keyframes node's slerp (MPFR at 300 bits, as a rational), composed; and
 * the tightness ratios the driver collects.
 */
#include <gmp.h>
#include <mpfr.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_parts.h"

void sct_qm_init(qmap *q)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            mpq_init(q->m[i][j]);
}
void sct_qm_clear(qmap *q)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            mpq_clear(q->m[i][j]);
}
void sct_qm_ident(qmap *q)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            mpq_set_si(q->m[i][j], i == j, 1);
}
/* q = (1 - s) a0 + s a1, exactly (s = 0: a0) */
void sct_qm_from(qmap *q, const cbx_affine *a0, const cbx_affine *a1, const mpq_t s)
{
    mpq_t x, y, one_s;
    mpq_inits(x, y, one_s, NULL);
    mpq_set_ui(one_s, 1, 1);
    mpq_sub(one_s, one_s, s);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) {
            mpq_set_d(x, a0->m[i][j]);
            mpq_mul(q->m[i][j], x, one_s);
            if (a1) {
                mpq_set_d(y, a1->m[i][j]);
                mpq_mul(y, y, s);
                mpq_add(q->m[i][j], q->m[i][j], y);
            }
        }
    mpq_clears(x, y, one_s, NULL);
}
/* r = a o b (apply b first); r may not alias a or b */
void sct_qm_compose(qmap *r, const qmap *a, const qmap *b)
{
    mpq_t t;
    mpq_init(t);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) {
            mpq_set_ui(r->m[i][j], 0, 1);
            for (int k = 0; k < 3; k++) {
                mpq_mul(t, a->m[i][k], b->m[k][j]);
                mpq_add(r->m[i][j], r->m[i][j], t);
            }
            if (j == 3)
                mpq_add(r->m[i][j], r->m[i][j], a->m[i][3]);
        }
    mpq_clear(t);
}



void sct_add_ratio(stats *st, double r)
{
    if (st->ratios_n == st->ratios_cap) {
        st->ratios_cap = st->ratios_cap ? 2 * st->ratios_cap : 256;
        st->ratios = realloc(st->ratios, (size_t)st->ratios_cap * sizeof *st->ratios);
        if (!st->ratios) { fprintf(stderr, "out of memory\n"); exit(2); }
    }
    st->ratios[st->ratios_n++] = r;
}

/* A keyframes node's map at time tm: T(tm) + R(tm) diag(S(tm)), T and S
 * exact; R from slerp (or nlerp) of the normalised quaternions, q1 negated
 * when the exact q0.q1 < 0, evaluated with MPFR at 300 bits and taken as
 * the rational of that value (within 2^-290 of the real rotation: far
 * below any rounding the tool's bound must cover). */
void sct_trs_map(const cbx_trs *k0, const cbx_trs *k1, int nlerp, const mpq_t tm, qmap *out)
{
    mpfr_t q[4], d, t, x;
    mpq_t one_m, sq, tq;
    xu_slerp sl;
    int i, j;
    mpfr_inits2(300, d, t, x, (mpfr_ptr)0);
    for (i = 0; i < 4; i++) mpfr_init2(q[i], 300);
    mpq_inits(one_m, sq, tq, NULL);
    xu_slerp_init(&sl, 300);
    xu_slerp_keys(&sl, k0->q, k1->q, nlerp, 0);
    mpfr_set_q(t, tm, MPFR_RNDN);
    xu_slerp_at(&sl, t, q);
    xu_slerp_clear(&sl);
    /* R (unit quaternion (x, y, z, w)), then the columns scaled by S */
    {
        static const int sq_a[3][2] = {{1, 2}, {0, 2}, {0, 1}};
        /* off-diagonal: 2 (q_u q_v + sign q_w q_z) */
        static const int off[3][3][4] = {
            {{0, 0, 0, 0}, {0, 1, 2, -1}, {0, 2, 1, 1}},
            {{0, 1, 2, 1}, {0, 0, 0, 0}, {1, 2, 0, -1}},
            {{0, 2, 1, -1}, {1, 2, 0, 1}, {0, 0, 0, 0}}};
        mpq_set_ui(one_m, 1, 1);
        mpq_sub(one_m, one_m, tm);
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) {
                if (i == j) {
                    mpfr_sqr(x, q[sq_a[i][0]], MPFR_RNDN);
                    mpfr_fma(x, q[sq_a[i][1]], q[sq_a[i][1]], x, MPFR_RNDN);
                    mpfr_mul_2ui(x, x, 1, MPFR_RNDN);
                    mpfr_ui_sub(x, 1, x, MPFR_RNDN);
                } else {
                    const int *o = off[i][j];
                    mpfr_mul(x, q[o[0]], q[o[1]], MPFR_RNDN);
                    mpfr_mul(d, q[o[2]], q[3], MPFR_RNDN);
                    if (o[3] > 0) mpfr_add(x, x, d, MPFR_RNDN);
                    else mpfr_sub(x, x, d, MPFR_RNDN);
                    mpfr_mul_2ui(x, x, 1, MPFR_RNDN);
                }
                mpfr_get_q(out->m[i][j], x);
                /* times S_j(tm) = (1 - tm) s0 + tm s1 */
                mpq_set_d(sq, k0->s[j]);
                mpq_mul(sq, sq, one_m);
                mpq_set_d(tq, k1->s[j]);
                mpq_mul(tq, tq, tm);
                mpq_add(sq, sq, tq);
                mpq_mul(out->m[i][j], out->m[i][j], sq);
            }
            mpq_set_d(sq, k0->t[i]);
            mpq_mul(sq, sq, one_m);
            mpq_set_d(tq, k1->t[i]);
            mpq_mul(tq, tq, tm);
            mpq_add(out->m[i][3], sq, tq);
        }
    }
    mpq_clears(one_m, sq, tq, NULL);
    for (i = 0; i < 4; i++) mpfr_clear(q[i]);
    mpfr_clears(d, t, x, (mpfr_ptr)0);
}
