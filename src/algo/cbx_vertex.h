/*
 * The vertex rule, one column at a time: the point of [l, h] (ends may be
 * infinite) where m*x is least or greatest, with the sign step m*v <= m*p
 * (>=) for every real point p of [l, h] proven by lemma functions.  Used by
 * the half-space ends of the interval transform and by the tight mode.
 */
#ifndef CBX_VERTEX_H
#define CBX_VERTEX_H

#include "certbox.h"
#include "cbx_prec.h"
#include "cbx_domain.h"

typedef struct end_result { cbx_fp v; int ok; } end_result;

/* Lemma functions (empty bodies, no code): their contracts state the sign
 * step of one column, m*v <= m*p or >= for every point p of [l, h], in the
 * form nn_prod(a, b) (0 <= a*b) with a, b >= 0 that the lemma mul_nonneg
 * covers (the provers' nonlinear arithmetic alone is not reliable on
 * m*v <= m*p); vertex_lo / vertex_hi call them. */
/*@ requires \is_finite(m) && \is_finite(l) && m > 0;
    assigns \nothing;
    ensures \forall real p; ext_in(p, l, h) ==> nn_prod(m, p - l);
*/
static inline void pos_below(cbx_fp m, cbx_fp l, cbx_fp h) { (void)m; (void)l; (void)h; }

/*@ requires \is_finite(m) && \is_finite(h) && m < 0;
    assigns \nothing;
    ensures \forall real p; ext_in(p, l, h) ==> nn_prod(-m, h - p);
*/
static inline void neg_below(cbx_fp m, cbx_fp l, cbx_fp h) { (void)m; (void)l; (void)h; }

/*@ requires \is_finite(m) && \is_finite(h) && m > 0;
    assigns \nothing;
    ensures \forall real p; ext_in(p, l, h) ==> nn_prod(m, h - p);
*/
static inline void pos_above(cbx_fp m, cbx_fp l, cbx_fp h) { (void)m; (void)l; (void)h; }

/*@ requires \is_finite(m) && \is_finite(l) && m < 0;
    assigns \nothing;
    ensures \forall real p; ext_in(p, l, h) ==> nn_prod(-m, p - l);
*/
static inline void neg_above(cbx_fp m, cbx_fp l, cbx_fp h) { (void)m; (void)l; (void)h; }

/* The vertex of [l, h] where m*x is least; ok == 0: m*x unbounded below. */
/* proof: -wp-split */
/*@ requires fin: \is_finite(m) && !\is_NaN(l) && !\is_NaN(h);
    assigns \nothing;
    ensures unb: \result.ok == 0 <==> unb_lo(m, l, h);
    ensures v: \result.ok != 0 ==> \is_finite(\result.v) && \result.v == vlo(m, l, h);
    ensures sel: \result.ok != 0 ==> sel_lo(m, \result.v, l, h);
    ensures col: \result.ok != 0 ==> \forall real p; ext_in(p, l, h) ==> m * \result.v <= m * p;
*/
static inline end_result vertex_lo(cbx_fp m, cbx_fp l, cbx_fp h)
{
    end_result r;
    if (m > CBX_C(0.0)) {
        /*@ assert sg: m > 0; */
        r.v = l;
        r.ok = cbx_is_fin(l);
        if (r.ok != 0) {
            pos_below(m, l, h);
        }
        /*@ assert r.ok != 0 ==> \forall real p; ext_in(p, l, h) ==> m*l <= m*p; */
    } else if (m < CBX_C(0.0)) {
        /*@ assert sg: m < 0; */
        r.v = h;
        r.ok = cbx_is_fin(h);
        if (r.ok != 0) {
            neg_below(m, l, h);
        }
        /*@ assert r.ok != 0 ==> \forall real p; ext_in(p, l, h) ==> m*h <= m*p; */
    } else {
        /*@ assert sg: m == 0; */
        /*@ assert z: \forall real p; m*0 == m*p; */
        r.v = CBX_C(0.0);
        r.ok = 1;
    }
    return r;
}

/* The vertex of [l, h] where m*x is greatest; ok == 0: unbounded above. */
/* proof: -wp-split */
/*@ requires fin: \is_finite(m) && !\is_NaN(l) && !\is_NaN(h);
    assigns \nothing;
    ensures unb: \result.ok == 0 <==> unb_hi(m, l, h);
    ensures v: \result.ok != 0 ==> \is_finite(\result.v) && \result.v == vhi(m, l, h);
    ensures sel: \result.ok != 0 ==> sel_hi(m, \result.v, l, h);
    ensures col: \result.ok != 0 ==> \forall real p; ext_in(p, l, h) ==> m * \result.v >= m * p;
*/
static inline end_result vertex_hi(cbx_fp m, cbx_fp l, cbx_fp h)
{
    end_result r;
    if (m > CBX_C(0.0)) {
        /*@ assert sg: m > 0; */
        r.v = h;
        r.ok = cbx_is_fin(h);
        if (r.ok != 0) {
            pos_above(m, l, h);
        }
        /*@ assert r.ok != 0 ==> \forall real p; ext_in(p, l, h) ==> m*h >= m*p; */
    } else if (m < CBX_C(0.0)) {
        /*@ assert sg: m < 0; */
        r.v = l;
        r.ok = cbx_is_fin(l);
        if (r.ok != 0) {
            neg_above(m, l, h);
        }
        /*@ assert r.ok != 0 ==> \forall real p; ext_in(p, l, h) ==> m*l >= m*p; */
    } else {
        /*@ assert sg: m == 0; */
        /*@ assert z: \forall real p; m*0 == m*p; */
        r.v = CBX_C(0.0);
        r.ok = 1;
    }
    return r;
}

#endif /* CBX_VERTEX_H */
