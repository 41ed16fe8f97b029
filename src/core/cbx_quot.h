/*
 * Quotients, for the projective bounds (src/algo/cbx_project.c) only, both
 * formats: IEEE division (trusted to be correctly rounded, as sqrt is:
 * proofs/README.md; checked at run time by cbx_ieee_check()), the range
 * check that keeps a quotient finite, and the quotient rounded outward.
 * A header of its own so that only the units that divide carry the
 * lemmas its proofs use (specs/cbx_proj_logic.h, CBX_PROJ_LEMMAS).
 */
#ifndef CBX_QUOT_H
#define CBX_QUOT_H

#include "certbox.h"
#include "cbx_prec.h"
#include "cbx_round.h"

#if defined(__FRAMAC__)
/* IEEE-754 division is correctly rounded: q = RN(a / b) (C99 Annex F,
 * F.3).  For b > 0 and |a| <= QR b (cbx_quot_ok: QR = 2^1002, binary32
 * 2^122) the quotient does not overflow, |q| <= QR (rounding is monotonic
 * and QR is a float), q has the sign of a, and |q - a/b| <= u |a/b| +
 * eta/2; the contract states the last multiplied by b (trusted; listed in
 * proofs/README.md; checked at run time by cbx_ieee_check()). */
/*@ requires fin: \is_finite(a) && \is_finite(b);
    requires rng: b >= CBX_ETA && \abs(a) <= CBX_QR * b;
    assigns \result \from a, b;
    ensures fin: \is_finite(\result);
    ensures mag: \abs(\result) <= CBX_QR;
    ensures sgn: (a >= 0 ==> \result >= 0) && (a <= 0 ==> \result <= 0);
    ensures err: \abs(\result * b - a) <= CBX_U * \abs(a) + CBX_ETA * b;
*/
cbx_fp cbx_div_rn(cbx_fp a, cbx_fp b);
#else
static inline cbx_fp cbx_div_rn(cbx_fp a, cbx_fp b) { return a / b; }
#endif

/* ---- quotients (the projective bounds) ---------------------------------
 * A quotient a / b (b > 0) is formed only when cbx_quot_ok(a, b): b is a
 * positive float and RN(|a| 2^-1000) <= b (binary32: 2^-120), so |a / b|
 * <= 2^1002 (2^122) and nothing overflows.  The statements are multiplied
 * out by b: r b <= a says r <= a / b without a division in the logic. */
/*@ requires fin: \is_finite(a) && \is_finite(b);
    assigns \nothing;
    ensures ok: \result != 0 ==> b >= CBX_ETA && \abs(a) <= CBX_QR * b;
    ensures sure: \abs(a) * (2*CBX_QS) + CBX_ETA <= b ==> \result != 0;
*/
static inline int cbx_quot_ok(cbx_fp a, cbx_fp b)
{
    cbx_fp s = cbx_mul_rn(cbx_abs(a), CBX_K(QS));
    /*@ assert se: \abs(s - \abs(a) * CBX_QS) <= CBX_U * (\abs(a) * CBX_QS) + CBX_ETA; */
    int pos = b >= CBX_K(ETA);
    int in = s <= b;
    return pos & in;
}

/* a / b rounded down (cbx_div_dn) or up (cbx_div_up): q = RN(a / b) moved
 * by RN(3 u |q|) + 8 eta, then rounded once more; below (above) a / b and
 * within 8 u |a| + 16 eta b of it, times b. */
/*@ requires fin: \is_finite(a) && \is_finite(b);
    requires rng: b >= CBX_ETA && \abs(a) <= CBX_QR * b;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures mag: -2*CBX_QR <= \result <= 2*CBX_QR;
    ensures dn: \result * b <= a;
    ensures near: a - \result * b <= CBX_U8 * \abs(a) + CBX_ETA16 * b;
    ensures sgn: a < 0 ==> \result < 0;
*/
static inline cbx_fp cbx_div_dn(cbx_fp a, cbx_fp b)
{
    cbx_fp q = cbx_div_rn(a, b);
    /*@ assert qm: abs_prod(q, b); */
    /*@ assert qm2: \abs(q) * b <= \abs(a) * (1 + CBX_U) + CBX_ETA * b
                    && \abs(q) * b >= \abs(a) * (1 - CBX_U) - CBX_ETA * b; */
    cbx_fp m = cbx_mul_rn(cbx_abs(q), CBX_K(U3));
    cbx_fp w = cbx_add_rn(m, CBX_K(ETA8));
    /*@ assert wlo: w >= CBX_U3 * \abs(q) * (1 - CBX_U2) + 5*CBX_ETA; */
    /*@ assert whi: w <= CBX_U3 * \abs(q) * (1 + CBX_U4) + 11*CBX_ETA; */
    /*@ assert wb: prod_le(CBX_U3 * \abs(q) * (1 - CBX_U2) + 5*CBX_ETA, w, b)
                   && prod_le(w, CBX_U3 * \abs(q) * (1 + CBX_U4) + 11*CBX_ETA, b); */
    cbx_fp r = cbx_sub_rn(q, w);
    /*@ assert rlo: r <= q - w + CBX_U * (\abs(q) + w) + CBX_ETA; */
    /*@ assert rhi: r >= q - w - CBX_U * (\abs(q) + w) - CBX_ETA; */
    /*@ assert rblo: prod_le(r, q - w + CBX_U * (\abs(q) + w) + CBX_ETA, b); */
    /*@ assert rbhi: prod_le(q - w - CBX_U * (\abs(q) + w) - CBX_ETA, r, b); */
    return r;
}

/*@ requires fin: \is_finite(a) && \is_finite(b);
    requires rng: b >= CBX_ETA && \abs(a) <= CBX_QR * b;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures mag: -2*CBX_QR <= \result <= 2*CBX_QR;
    ensures up: a <= \result * b;
    ensures near: \result * b - a <= CBX_U8 * \abs(a) + CBX_ETA16 * b;
    ensures sgn: a >= 0 ==> \result >= 0;
*/
static inline cbx_fp cbx_div_up(cbx_fp a, cbx_fp b)
{
    cbx_fp q = cbx_div_rn(a, b);
    /*@ assert qm: abs_prod(q, b); */
    /*@ assert qm2: \abs(q) * b <= \abs(a) * (1 + CBX_U) + CBX_ETA * b
                    && \abs(q) * b >= \abs(a) * (1 - CBX_U) - CBX_ETA * b; */
    cbx_fp m = cbx_mul_rn(cbx_abs(q), CBX_K(U3));
    cbx_fp w = cbx_add_rn(m, CBX_K(ETA8));
    /*@ assert wlo: w >= CBX_U3 * \abs(q) * (1 - CBX_U2) + 5*CBX_ETA; */
    /*@ assert whi: w <= CBX_U3 * \abs(q) * (1 + CBX_U4) + 11*CBX_ETA; */
    /*@ assert wb: prod_le(CBX_U3 * \abs(q) * (1 - CBX_U2) + 5*CBX_ETA, w, b)
                   && prod_le(w, CBX_U3 * \abs(q) * (1 + CBX_U4) + 11*CBX_ETA, b); */
    cbx_fp r = cbx_add_rn(q, w);
    /*@ assert rlo: r <= q + w + CBX_U * (\abs(q) + w) + CBX_ETA; */
    /*@ assert rhi: r >= q + w - CBX_U * (\abs(q) + w) - CBX_ETA; */
    /*@ assert rblo: prod_le(r, q + w + CBX_U * (\abs(q) + w) + CBX_ETA, b); */
    /*@ assert rbhi: prod_le(q + w - CBX_U * (\abs(q) + w) - CBX_ETA, r, b); */
    return r;
}

#endif /* CBX_QUOT_H */
