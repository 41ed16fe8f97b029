/*
 * proj_oracle.h: the exact oracle of the projective bound (cbx_project_box,
 * cbx_project_boxf), shared by tests/test_project.c and the fuzz harness
 * tests/fuzz/fuzz_project.c.  po_judge decides, in GMP rationals, every
 * clause of the contract for one call: the statuses and special outputs,
 * proj_ok => CBX_OK, CBX_EBEHIND => a corner not clear, CBX_ERANGE in the
 * range => W > 0 at every corner, and with CBX_OK
 * finite ends, W > 0 and lo W <= X <= hi W at the 8 corners and at
 * s->npoints random points of the box, and the proven tightness at some
 * corner.  Each failed check calls fail(what); s counts the rest.
 */
#ifndef PROJ_ORACLE_H
#define PROJ_ORACLE_H

#include <stdint.h>

#include "certbox.h"

typedef struct po_stats {
    long passed, failed;
    long st[4];          /* CBX_OK, CBX_EBEHIND, CBX_ERANGE, NaN or empty */
    long points;         /* random points checked */
    long naive_miss, naive_cases; /* the round-to-nearest 8-corner divide (binary64) */
    double max_frac;     /* the largest used fraction of the proven tolerance */
    int npoints;         /* random points per CBX_OK case */
    uint64_t rng;        /* their generator's state */
} po_stats;

/* P, BL, BH: the map and box as the function got them (values of the
 * format: binary32 when is32); st, olo, ohi: its status and output. */
void po_judge(const double P[4][4], const double BL[3], const double BH[3], int is32,
              cbx_status st, const double olo[3], const double ohi[3], po_stats *s,
              void (*fail)(const char *what));

#endif /* PROJ_ORACLE_H */
