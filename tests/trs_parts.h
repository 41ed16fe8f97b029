/*
 * trs_parts.h: the parts of test_trs (tests/test_trs.c, the driver: motion
 * with rotation against the exact motion in MPFR; its cases and checks are
 * described there), shared by its files:
 *   tests/trs_exact.c    the exact motion (MPFR at PREC bits) and the
 *                        checks made with it: corner samples, the misses
 *                        of a box, a ball's extreme points, the extremes
 *                        over [s0, s1];
 *   tests/trs_gen.c      sin, cos, acos correctly rounded, and the random
 *                        keyframe pairs;
 *   tests/trs_special.c  the checks' tally, the predicates on output boxes,
 *                        and the special cases.
 * Every name with linkage starts with trt_ (one archive, every test links
 * it: build/libtestutil.a).
 */
#ifndef TRS_PARTS_H
#define TRS_PARTS_H

#include <mpfr.h>

#include "certbox.h"
#include "exact_util.h"

#define PREC 160
#define MAX_LOGS 10

/* ---------------------------------------------------------------------- */
/* The checks' tally, boxes, special cases (tests/trs_special.c)          */
/* ---------------------------------------------------------------------- */

/* checks made, failed, and failures printed (at most MAX_LOGS) */
extern long trt_n_check, trt_n_fail, trt_n_logs;
/* Count one check of pair `pair` (-1: a special case); print a failure. */
void trt_check(int ok, const char *what, long pair);
/* 1 when every end of *b is finite (|end| <= 1e308) */
int trt_box_finite(const cbx_box *b);

/* ---------------------------------------------------------------------- */
/* The exact motion (tests/trs_exact.c)                                   */
/* ---------------------------------------------------------------------- */

typedef struct exact {
    xu_slerp sl;                      /* the keys' quaternions and angle */
    mpfr_t q[4], t1, t2, R[3][3], T[3], SC[3][2];
} exact;

void trt_ex_init(exact *e);
void trt_ex_clear(exact *e);
/* Normalised keyframe quaternions, q1 on the shorter arc (sign = +1 / -1
 * forces the arc: used for the ties): exact_util's slerp oracle. */
void trt_ex_keys(exact *e, const cbx_trs *k0, const cbx_trs *k1, int nlerp, int sign);
/* The motion at time s: R, T and the scaled box ends. */
void trt_ex_at(exact *e, const cbx_trs *k0, const cbx_trs *k1, const mpfr_t s, const cbx_box *in);
/* Coordinate i of corner c's image (trt_ex_at done for the time). */
void trt_ex_coord(exact *e, mpfr_t out, int c, int i);
/* 1 when every corner's exact image at time sd lies in *out. */
int trt_sample_in(exact *e, const cbx_trs *k0, const cbx_trs *k1, double sd, const cbx_box *in,
                  const cbx_box *out);
/* The largest distance by which a corner's exact image at time sd lies
 * outside *box (negative: all inside), rounded to a double. */
double trt_sample_miss(exact *e, const cbx_trs *k0, const cbx_trs *k1, double sd, const cbx_box *in,
                       const cbx_box *box);
/* 1 when each axis's two extreme points of the ball |x - c| <= |r| at
 * time sd lie in *box. */
int trt_ball_in(exact *e, const cbx_trs *k0, const cbx_trs *k1, double sd, const double c[3], double r,
                const cbx_box *box);
/* best[i][0] = -(the smallest), best[i][1] = the largest coordinate i of
 * the image over [s0, s1] that was found (samples, then golden section). */
void trt_extremes(exact *e, mpfr_t best[3][2], const cbx_trs *k0, const cbx_trs *k1, double s0,
                  double s1, const cbx_box *in);
/* the special cases (exact samples of the ties) */
void trt_specials(exact *e);

/* ---------------------------------------------------------------------- */
/* Generators (tests/trs_gen.c)                                           */
/* ---------------------------------------------------------------------- */

/* f (mpfr_sin, mpfr_cos, mpfr_acos) of x correctly rounded to double */
double trt_cr_fn(int (*f)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t), double x);
/* A random keyframe pair and box; returns the angle category's index
 * (0 .. 7: 0, 1e-9, 1e-4, 45, 90, 179.9, 180 degrees, random); *big: the
 * 1e12 translations. */
int trt_gen_pair(xu_rng *r, cbx_trs *k0, cbx_trs *k1, cbx_box *b, int *big);

#endif /* TRS_PARTS_H */
