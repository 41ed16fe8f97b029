/*
 * float_parts.h: the parts of tests/test_float.c (the binary32 family
 * against exact rationals): the tallies and float <-> double conversions
 * (tests/float_util.c), cbx_transform_boxf, the batches and the prepared
 * maps (tests/float_box.c), cbx_transform_cboxf and the conversions
 * (tests/float_cbox.c), the spheres and ellipsoids (tests/float_ball.c).
 * The driver, tests/test_float.c, runs them in order, with the
 * special-value table, and prints the summary.  Everything here is
 * prefixed flt_: these objects go into the archive every test links
 * (scripts/testutil.sh).
 */
#ifndef FLOAT_PARTS_H
#define FLOAT_PARTS_H

#include <math.h>

#include "certbox.h"
#include "exact_util.h"

/* one counter per function */
typedef struct fstat {
    const char *name;
    long cases, failed, checks;
    long axes;                  /* finite, proven axes/ends measured      */
    double max_ex, sum_ex;      /* excess, units of u S + eta             */
} fstat;

/* the map and box initialisers of the hard cases and the special-value table */
#define ROW(a, b, c, t) { a, b, c, t }
#define MAT(r0, r1, r2) { { r0, r1, r2 } }
#define BOX(l0, h0, l1, h1, l2, h2) { { l0, l1, l2 }, { h0, h1, h2 } }
#define INF HUGE_VAL
#define P61U 0x1.000002p61   /* the next float above 2^61  */
#define P122U 0x1.000002p122 /* the next float above 2^122 */

/* a hard case of cbx_transform_boxf */
typedef struct box_case { const char *name; cbx_affine a; cbx_box in; } box_case;

/* ---- tests/float_util.c ------------------------------------------------ */

/* a failure of s (printed, the first MAX_LOGS of the run) */
void flt_fs_fail(fstat *s, const char *what, const char *why);
/* the excess e of one end, in units of u S + eta */
void flt_fs_excess(fstat *s, double e);
void flt_fs_print(const fstat *s);
extern long flt_not_float; /* generated values that are not floats (a bug here) */
/* d as a float, counted in flt_not_float when it is not one */
float flt_F(double d);
/* double -> float (flt_F) and float -> double (exact) */
void flt_to_af(const cbx_affine *d, cbx_affinef *f);
void flt_to_bf(const cbx_box *d, cbx_boxf *f);
void flt_to_cf(const cbx_cbox *d, cbx_cboxf *f);
void flt_from_af(const cbx_affinef *f, cbx_affine *d);
void flt_from_bf(const cbx_boxf *f, cbx_box *d);
void flt_from_cf(const cbx_cboxf *f, cbx_cbox *d);
/* fill an output with NaN (to see a field left unset) */
void flt_nan_bf(cbx_boxf *o);
void flt_nan_cf(cbx_cboxf *o);
int flt_is_pinf(double d);
int flt_is_ninf(double d);

/* ---- tests/float_box.c ------------------------------------------------- */

extern fstat flt_st_box, flt_st_inpl, flt_st_batch, flt_st_prep, flt_st_prep1, flt_st_prepn;
/* prepared maps in the fast range; boxes of the forged structs checked
 * against the exact oracle */
extern long flt_prep_fast, flt_prep_exact;
extern const box_case flt_box_hard[];
extern const int flt_n_box_hard;
/* The whole check of one cbx_transform_boxf case; returns 1 on failure. */
int flt_run_box(xu_exact *x, xu_stats *all, const cbx_affine *ad, const cbx_box *bd,
            int corners, const char *what);
/* a batch of n boxes (n <= 100) under one map of r */
void flt_run_batch(xu_rng *r, int n);
/* The map ad and the n boxes bd[] (n <= 100): cbx_preparef and the
 * prepared calls, with nforge values of xu_cls_values from index f0 on. */
void flt_run_prep(xu_exact *x, const cbx_affine *ad, const cbx_box *bd, int n, long id, int f0,
              int nforge, const char *what);
/* a random prepared batch of n boxes */
void flt_prep_case(xu_exact *x, xu_rng *r, int n, long id);

/* ---- tests/float_cbox.c ------------------------------------------------ */

extern fstat flt_st_cbox, flt_st_b2c, flt_st_c2b;
void flt_run_cbox(xu_exact *x, const cbx_affine *ad, const cbx_cbox *cd, const char *what);
/* a random cbox case and its map */
void flt_gen_cbox(xu_rng *r, cbx_affine *a, cbx_cbox *c);
void flt_run_b2c(xu_exact *x, const cbx_box *bd, const char *what);
void flt_run_c2b(xu_exact *x, const cbx_cbox *cd, const char *what);

/* ---- tests/float_ball.c ------------------------------------------------ */

extern fstat flt_st_sph, flt_st_ell;
void flt_run_sphere(xu_exact *x, const cbx_affine *ad, const char *what);
void flt_run_ellipsoid(xu_exact *x, const double cen[3], const double rad[3],
                   const double rot[3][3], const char *what);
/* a random rotation in float */
void flt_rand_rot_f(xu_rng *r, double R[3][3]);
/* an entry of a random sphere map */
double flt_gen_ball_entry(xu_rng *r);

#endif /* FLOAT_PARTS_H */
