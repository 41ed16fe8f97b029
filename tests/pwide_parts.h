/*
 * pwide_parts.h: the pieces of tests/test_pwide.c (the binary32 twins of the
 * projective bounds against binary64 and the exact oracles) that live in
 * their own files:
 *   test_pwide.c    the driver: the current case, the twins' runs and
 *                   checks, the random cases, the summary;
 *   pwide_cases.c   the hard cases.
 * pwide_cases.c is compiled once into build/libtestutil.a
 * (scripts/testutil.sh).  The exported names carry the prefix pwt_.
 */
#ifndef PWIDE_PARTS_H
#define PWIDE_PARTS_H

#include "certbox.h"
#include "exact_util.h"

/* ---- the driver (test_pwide.c) ----------------------------------------- */
/* the current case in binary64, as the generators draw it: the map, the
 * ball (center, radius), the near plane, the box; the ellipsoid's radii and
 * rot (its center pwt_C) */
extern double pwt_P[4][4], pwt_C[3], pwt_R, pwt_WN;
extern cbx_box pwt_B;
extern double pwt_E[3], pwt_Q[3][3];
/* each twin on the current case, rounded to float, against binary64 and
 * the exact oracle; the twin's status */
cbx_status pwt_run_sph(const char *name);
cbx_status pwt_run_near(const char *name);
cbx_status pwt_run_ball(const char *name);
cbx_status pwt_run_ell(const char *name);
/* a status check (counted under the current twin's "status") */
void pwt_expect(cbx_status got, cbx_status want, const char *what);

/* ---- the hard cases (pwide_cases.c) ------------------------------------- */
/* the callbacks of tests/proj_cases.c's tables: the ball's twin, the
 * clipped ball's twin, and the ball's cases as ellipsoids (pwt_ell_kind 0:
 * a ball, 1: a tilted disk) */
extern int pwt_ell_kind;
void pwt_sph_run(const char *name, cbx_status want, const char *what);
void pwt_ball_run(const char *name, cbx_status want, const char *what);
void pwt_ell_run(const char *name, cbx_status want, const char *what);
/* test_pnear's box cases, a box wholly in front of the camera, and the
 * float cases */
void pwt_near_run(const char *name, cbx_status want, const char *what);
void pwt_near_in_front(xu_rng *g);
void pwt_float_hard(void);

#endif
