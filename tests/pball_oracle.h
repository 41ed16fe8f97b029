/*
 * pball_oracle.h: the exact oracle of a ball under a projective map clipped
 * at a near plane (cbx_project_sphere_near), shared by tests/test_pball.c
 * and the fuzz harness tests/fuzz/fuzz_pball.c.  pbo_judge decides, for
 * one call:
 *   - the status is a documented one: NaN (wn included) -> CBX_EINVAL and
 *     the whole space, only then; outside the domain -> CBX_ERANGE and the
 *     whole space; CBX_EMPTY (the empty box) only when W < wn on the whole
 *     ball (W(c) + |r| |b| < wn, exactly, in rationals); CBX_ERANGE in the
 *     domain gives the whole space, and is counted and shown;
 *   - with CBX_OK: some point of the ball has W >= wn (exactly), every end
 *     is finite, on the right side of the exact end and within
 *     2^-20 (1 + |end|) of it (pb_tight); the exact end is computed in
 *     closed form in MPFR at 1200 bits, written as sums whose terms do not
 *     cancel inside the square roots, and enclosed with a margin of
 *     2^-1100 times the magnitude of its terms (far above the rounding of
 *     1200 bits, far below a double's unit); the distance is kept, in
 *     units of 2^-52 (1 + |end|);
 *   - with CBX_OK: lo W <= X <= hi W at 8 exact rational points of the
 *     ball with W >= wn (points with W < wn are drawn again, up to 64
 *     draws).
 * The exact upper end of X / W over the part W >= wn is min over s of
 * max(s, s + h(s) / wn), h(s) = X(c) - s W(c) + |r| |a - s b| (the largest
 * value of X - s W on the ball): where the near plane cuts the ball, the
 * minimiser s* of s + h(s) / wn has a closed form, and the end is
 * s* + h(s*) / wn when that is >= s*; otherwise (and where the plane
 * misses the ball) the end is the least root of h (the unclipped tangent).
 * The lower end is minus the upper end of -X.
 * Each failed check calls fail(what); s counts the rest.
 */
#ifndef PBALL_ORACLE_H
#define PBALL_ORACLE_H

#include <stdint.h>
#include <stdio.h>

#include "certbox.h"

typedef struct pbo_stats {
    long passed, failed;
    long st[4];                 /* CBX_OK, CBX_EMPTY, CBX_ERANGE, CBX_EINVAL */
    long clipped;               /* CBX_OK ends on the near plane's circle */
    long crossing;              /* CBX_OK cases whose ball crosses the camera plane W = 0 */
    long behind;                /* CBX_EMPTY for a ball in the domain */
    long points;                /* exact points checked */
    long erange;                /* CBX_ERANGE in the domain */
    long erange_void;           /* of which with nothing in front, exactly */
    long degenerate;            /* OK cases whose end the closed form cannot give (skipped) */
    xu_dists dist;              /* each end's distance to the exact end, units */
    uint64_t rng;               /* the random points' generator */
} pbo_stats;

void pbo_init(pbo_stats *s, uint64_t seed);
void pbo_judge(const double p[4][4], const double c[3], double r, double wn, cbx_status st,
               const cbx_box *out, pbo_stats *s, void (*fail)(const char *what));
void pbo_print(FILE *f, pbo_stats *s);   /* the summary lines (sorts s->dist.v) */
void pbo_free(pbo_stats *s);

#endif /* PBALL_ORACLE_H */
