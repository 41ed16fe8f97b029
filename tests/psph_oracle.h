/*
 * psph_oracle.h: the exact oracle of a ball under a projective map
 * (cbx_project_sphere), shared by tests/test_psphere.c and the fuzz
 * harness tests/fuzz/fuzz_psphere.c.  pso_judge decides, for one call:
 *   - the status is a documented one, and every status but CBX_OK gives
 *     the whole space; NaN -> CBX_EINVAL, only then; outside the domain
 *     -> CBX_ERANGE; a ball touching, crossing or behind the camera plane
 *     (W(c) <= |r| |b|, exactly) -> CBX_EBEHIND; CBX_EBEHIND only for a
 *     ball near the camera plane:
 *     W(c) - |r| |b| <= 2^-40 (S_W + |r| |b|) + 2^-1000 + |r| 2^-520,
 *     S_W = |b0 c0| + |b1 c1| + |b2 c2| + |b3| (the last term: the square
 *     root of the norm's absolute rounding) (exactly, in rationals);
 *   - with CBX_OK: the ball in front (exactly), every end finite, on the
 *     right side of the exact end and within 2^-20 (1 + |end|) of it
 *     (MPFR, 300 bits, directed rounding, from the exact rational
 *     coefficients), and W > 0, lo W <= X <= hi W at 8 exact rational
 *     points of the ball (6 on the sphere, 2 inside);
 *   - (counted, not asserted) the round-to-nearest closed form's misses.
 * Each failed check calls fail(what); s counts the rest.
 */
#ifndef PSPH_ORACLE_H
#define PSPH_ORACLE_H

#include <stdint.h>
#include <stdio.h>

#include "certbox.h"

typedef struct pso_stats {
    long passed, failed;
    long st[4];                 /* CBX_OK, CBX_EBEHIND, CBX_ERANGE, CBX_EINVAL */
    long points;                /* exact points checked */
    long naive_miss, naive;     /* the round-to-nearest closed form */
    long erange;                /* CBX_ERANGE in the domain */
    double erange_front;        /* the largest min W / max W among them */
    xu_dists dist;              /* each end's distance to the exact end, units */
    uint64_t rng;               /* the points' generator */
} pso_stats;

void pso_init(pso_stats *s, uint64_t seed);
void pso_judge(const double p[4][4], const double c[3], double r, cbx_status st, const cbx_box *out,
               pso_stats *s, void (*fail)(const char *what));
/* the same for an ellipsoid c + rot diag(radii) q, |q| <= 1
 * (cbx_project_ellipsoid: the ball's clauses with |M^T b| in place of
 * |r| |b|, and 1 + sum_j |radii_j| (1 + sum_i |rot_ij|) in place of |r|
 * in the allowance of CBX_EBEHIND: the square root of the norm's absolute
 * rounding is not scaled by the radii) */
void pso_judge_ell(const double p[4][4], const double c[3], const double radii[3], const double rot[3][3],
                   cbx_status st, const cbx_box *out, pso_stats *s, void (*fail)(const char *what));
void pso_print(FILE *f, pso_stats *s);
/* 1 when [lo, hi] contains the exact range of X_i / W over the ball (in
 * front of the camera), 0 when not, -1 when within 2^-300 of an end */
/* the closed form in round to nearest (Mara and McGuire; unsound) */
void pso_closed_form(const double p[4][4], const double c[3], double r, int i, double *lo, double *hi);
/* the same for an ellipsoid, on the rows M^T a, M^T b rounded to nearest */
void pso_closed_form_ell(const double p[4][4], const double c[3], const double radii[3],
                         const double rot[3][3], int i, double *lo, double *hi);
int pso_contains(const double p[4][4], const double c[3], double r, int i, double lo, double hi);   /* the summary lines (sorts s->dist.v) */
void pso_free(pso_stats *s);

#endif /* PSPH_ORACLE_H */
