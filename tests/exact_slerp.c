/* exact_slerp: the slerp (and nlerp) oracle of the rotation-motion tests
 * (test_trs, test_scene, test_gltf), in MPFR.
 * Part of the oracle declared in exact_util.h (see there for the map). */
#include "exact_util.h"

/* ---- the slerp oracle --------------------------------------------------- */
void xu_slerp_init(xu_slerp *e, mpfr_prec_t prec)
{
    for (int i = 0; i < 4; i++) mpfr_inits2(prec, e->q0[i], e->q1[i], (mpfr_ptr)0);
    mpfr_inits2(prec, e->th, e->sth, e->w0, e->w1, e->n, (mpfr_ptr)0);
    e->nlerp = e->small = e->dot_neg = 0;
}

void xu_slerp_clear(xu_slerp *e)
{
    for (int i = 0; i < 4; i++) mpfr_clears(e->q0[i], e->q1[i], (mpfr_ptr)0);
    mpfr_clears(e->th, e->sth, e->w0, e->w1, e->n, (mpfr_ptr)0);
}

void xu_slerp_keys(xu_slerp *e, const double q0[4], const double q1[4], int nlerp, int arc)
{
    mpfr_t *q[2] = { e->q0, e->q1 };
    const double *k[2] = { q0, q1 };
    for (int j = 0; j < 2; j++) {
        mpfr_set_ui(e->n, 0, MPFR_RNDN);
        for (int i = 0; i < 4; i++) {
            mpfr_set_d(q[j][i], k[j][i], MPFR_RNDN);
            mpfr_fma(e->n, q[j][i], q[j][i], e->n, MPFR_RNDN);
        }
        mpfr_sqrt(e->n, e->n, MPFR_RNDN);
        for (int i = 0; i < 4; i++) mpfr_div(q[j][i], q[j][i], e->n, MPFR_RNDN);
    }
    /* the exact sign of q0.q1: every product of two doubles and their sum
     * are exact at 2400 bits */
    mpfr_t d, t;
    mpfr_inits2(2400, d, t, (mpfr_ptr)0);
    mpfr_set_ui(d, 0, MPFR_RNDN);
    for (int i = 0; i < 4; i++) {
        mpfr_set_d(t, q0[i], MPFR_RNDN);
        mpfr_mul_d(t, t, q1[i], MPFR_RNDN);
        mpfr_add(d, d, t, MPFR_RNDN);
    }
    e->dot_neg = mpfr_sgn(d) < 0;
    mpfr_clears(d, t, (mpfr_ptr)0);
    if ((arc == 0 && e->dot_neg) || arc < 0)
        for (int i = 0; i < 4; i++) mpfr_neg(e->q1[i], e->q1[i], MPFR_RNDN);
    mpfr_set_ui(e->n, 0, MPFR_RNDN);
    for (int i = 0; i < 4; i++) mpfr_fma(e->n, e->q0[i], e->q1[i], e->n, MPFR_RNDN);
    if (mpfr_cmp_ui(e->n, 1) > 0) mpfr_set_ui(e->n, 1, MPFR_RNDN);
    mpfr_acos(e->th, e->n, MPFR_RNDN);
    mpfr_sin(e->sth, e->th, MPFR_RNDN);
    e->small = mpfr_cmp_d(e->th, 0x1p-200) < 0;
    e->nlerp = nlerp;
}

void xu_slerp_at(xu_slerp *e, mpfr_srcptr s, mpfr_t q[4])
{
    mpfr_ui_sub(e->w0, 1, s, MPFR_RNDN);
    mpfr_set(e->w1, s, MPFR_RNDN);
    if (!e->nlerp && !e->small) {
        mpfr_mul(e->w0, e->w0, e->th, MPFR_RNDN);
        mpfr_sin(e->w0, e->w0, MPFR_RNDN);
        mpfr_div(e->w0, e->w0, e->sth, MPFR_RNDN);
        mpfr_mul(e->w1, s, e->th, MPFR_RNDN);
        mpfr_sin(e->w1, e->w1, MPFR_RNDN);
        mpfr_div(e->w1, e->w1, e->sth, MPFR_RNDN);
    }
    mpfr_set_ui(e->n, 0, MPFR_RNDN);
    for (int i = 0; i < 4; i++) {
        mpfr_mul(q[i], e->q0[i], e->w0, MPFR_RNDN);
        mpfr_fma(q[i], e->q1[i], e->w1, q[i], MPFR_RNDN);
        mpfr_fma(e->n, q[i], q[i], e->n, MPFR_RNDN);
    }
    mpfr_sqrt(e->n, e->n, MPFR_RNDN);
    for (int i = 0; i < 4; i++) mpfr_div(q[i], q[i], e->n, MPFR_RNDN);
}
