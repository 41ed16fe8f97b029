/*
 * pnear_oracle.h: the exact oracle of a box under a projective map clipped
 * at a near plane (cbx_project_box_near), shared by tests/test_pnear.c and
 * the fuzz harness tests/fuzz/fuzz_pnear.c.  pno_judge decides, for one
 * call, in GMP rationals (every vertex of the clipped box is rational):
 *   - the status is a documented one: NaN -> CBX_EINVAL and the whole
 *     space; an empty box -> CBX_EMPTY and the empty box; outside the
 *     domain -> CBX_ERANGE and the whole space; CBX_EMPTY for a box in the
 *     domain only when W < wn on the whole box (at its 8 corners, exactly);
 *     CBX_ERANGE in the domain and the whole space is counted (allowed by
 *     the contract) and shown;
 *   - with CBX_OK: the part W >= wn is not empty, every end is finite, on
 *     the right side of the exact end (the largest and least X_i / W over
 *     the corners with W >= wn and the crossings of the 12 edges with
 *     W = wn) and within 2^-20 (1 + |end|) of it (pn_tight); the distance
 *     is kept, in units of 2^-52 (1 + |end|);
 *   - with CBX_OK: lo W <= X <= hi W at every vertex and at 6 random
 *     rational points of the box with W >= wn.
 * Each failed check calls fail(what); s counts the rest.
 */
#ifndef PNEAR_ORACLE_H
#define PNEAR_ORACLE_H

#include <stdint.h>
#include <stdio.h>

#include "certbox.h"

typedef struct pno_stats {
    long passed, failed;
    long st[4];                 /* CBX_OK, CBX_EMPTY, CBX_ERANGE, CBX_EINVAL */
    long clipped;               /* CBX_OK cases where the near plane cut the box */
    long behind;                /* CBX_EMPTY for a box in the domain (all behind) */
    long points;                /* exact points checked */
    long erange;                /* CBX_ERANGE in the domain */
    long erange_void;           /* of which with nothing in front, exactly */
    xu_dists dist;              /* each end's distance to the exact end, units */
    int wide;                   /* set by the caller: W's magnitude above 2^20 wn */
    double worst_wide;          /* the largest distance among those (kept apart) */
    long n_wide;
    uint64_t rng;               /* the random points' generator */
} pno_stats;

void pno_init(pno_stats *s, uint64_t seed);
void pno_judge(const double p[4][4], const cbx_box *in, double wn, cbx_status st, const cbx_box *out,
               pno_stats *s, void (*fail)(const char *what));
void pno_print(FILE *f, pno_stats *s);   /* the summary lines (sorts s->dist.v) */
void pno_free(pno_stats *s);

#endif /* PNEAR_ORACLE_H */
