/*
 * plane_parts.h: the suites of test_plane (tests/test_plane.c, the
 * driver): the 2D hard cases and the failure log they share
 * (tests/plane_cases.c), cbx_transform_box2 / cbx_transform_box2f
 * (tests/plane_box.c), the center form and the conversions
 * (tests/plane_cbox.c), disks and ellipses (tests/plane_balls.c).  Every
 * name has the prefix plt_: these objects go into build/libtestutil.a,
 * which every test links.  Each suite prints its summary lines, adds its
 * passed cases to *passed and returns its failed ones.
 */
#ifndef PLANE_PARTS_H
#define PLANE_PARTS_H

#include <stdint.h>

#include "certbox.h"
#include "exact_util.h"

/* ---- the hard cases and the failure log (tests/plane_cases.c) ---------- */

typedef struct plane_case {
    const char *name;
    double m[2][3];
    double lo[2], hi[2];
} plane_case;

extern const plane_case plt_hard[];
extern const int plt_n_hard;

/* a FAIL line (the first 20 of the whole run) */
void plt_fail(const char *fam, const char *what, const char *why);
int plt_is_pinf(double d);
int plt_is_ninf(double d);

/* ---- cbx_transform_box2, cbx_transform_box2f (tests/plane_box.c) ------- */

typedef struct tally {
    long cases, failed, checks;
    long status[4];
} tally;

/* one case in binary64 / binary32; returns 1 on failure */
int plt_run64(xu_exact *x, xu_stats *st, tally *t, const double m[2][3], const double lo[2],
              const double hi[2], int corners, const char *what);
int plt_run32(xu_exact *x, xu_stats *st, tally *t, const double m[2][3], const double lo[2],
              const double hi[2], int corners, const char *what);
typedef int (*runner)(xu_exact *, xu_stats *, tally *, const double[2][3], const double[2],
                      const double[2], int, const char *);
/* The table, then n random cases, in the current format. */
long plt_family(xu_exact *x, const char *fam, runner run, long n, uint64_t seed, long *passed);

/* ---- the center form and the conversions (tests/plane_cbox.c) ---------- */

long plt_cboxes(int f32, long n, uint64_t seed, long *passed);
long plt_convs(int f32, long n, uint64_t seed, long *passed);

/* ---- disks and ellipses (tests/plane_balls.c) -------------------------- */

typedef struct ballfmt {
    int f32;                    /* binary32 twin                          */
    double sb, rt, eb;          /* the domain's bounds (specs: sph_dom,
                                   ell_dom): 2^509, 2^1018, 2^254 (binary64) */
    unsigned long uexp, eexp;   /* u = 2^-uexp; the absolute term 2^-eexp */
} ballfmt;
extern const ballfmt plt_bf64, plt_bf32;
long plt_balls(xu_exact *x, const ballfmt *F, long n, uint64_t seed, long *passed);

#endif /* PLANE_PARTS_H */
