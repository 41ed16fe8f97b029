/*
 * exact_internal: the helpers the files of the exact oracle share among
 * themselves (tests/exact_*.c); not part of the oracle's interface, which
 * is exact_util.h.  Only those files include this header.
 */
#ifndef EXACT_INTERNAL_H
#define EXACT_INTERNAL_H

#include "exact_util.h"

/* exact_domain.c: d is +inf / -inf (isinf() and a sign test: exact, and
 * independent of the library's comparisons with DBL_MAX). */
int xu_is_pinf(double d);
int xu_is_ninf(double d);

/* exact_fixed.c, the fixed-point path (values scaled by 2^XU_SHIFT): */
/* n * 2^p / den as a double (den > 0, u = 2^-p); a few ulps of error,
 * statistics only. */
double xu_ratio53(const mpz_t n, const mpz_t den);
/* x->e = (u S + eta) * 2^(XU_SHIFT + p) = S + 2^(XU_SHIFT - emin + p). */
void xu_unit_den(xu_exact *x);
/* x->d = the exact distance by which lo (hi) is outside x->L (x->H),
 * scaled; negative = not contained. */
void xu_gap_lo(xu_exact *x, double lo);
void xu_gap_hi(xu_exact *x, double hi);
/* x->d * 2^p <= 12 S + 2^(XU_SHIFT - tight_e + p): the gap is within the
 * proven 12 u S + 2^-tight_e (uses x->t and x->e). */
int xu_gap_within_proven(xu_exact *x);

#endif /* EXACT_INTERNAL_H */
