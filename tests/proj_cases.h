/*
 * proj_cases.h: cameras and random cases for the projective tests
 * (tests/test_psphere.c, test_pnear.c, test_pball.c, test_pwide.c): a
 * perspective projection times a rigid view, built from given numbers only
 * (no libm function that is not correctly rounded, so that a case has the
 * same bits on every machine: make check-cross), and the random balls and
 * boxes under such cameras and under general maps.  Each generator calls
 * the generator g in a fixed order: a test that draws its cases here draws
 * the same cases as before.
 */
#ifndef PROJ_CASES_H
#define PROJ_CASES_H

#include "certbox.h"
#include "exact_util.h"

/* P = perspective (OpenGL convention, W = -z_view; focal factor F =
 * 1 / tan(fov / 2), aspect asp, planes n < f) times the view x -> Q x + T,
 * Q the rotation of the unit quaternion q = (w, x, y, z). */
void tc_camera(double P[4][4], double F, double asp, double n, double f, const double q[4], const double T[3]);
/* c = Q^T (v - T), rounded: the world point of the view point v */
void tc_to_world(const double q[4], const double T[3], const double v[3], double c[3]);
/* m 2^e, e uniform in [lo, hi] (the generator's calls in a fixed order: the
 * order of a call's arguments is unspecified in C, and make check-cross
 * compares the outputs of two compilers) */
double tc_scaled(xu_rng *g, double m, int lo, int hi);
/* A random camera into P: a random unit quaternion q and translation T
 * (|T_i| up to 2^12) for the view; focal factor 2^-7 .. 2^7 (fields of
 * view 1 to 179 degrees), near plane *n = 2^-8 .. 4, far 2^2 .. 2^20 times
 * it, aspect 0.5 to 2.5. */
void tc_random_camera(xu_rng *g, double P[4][4], double q[4], double T[3], double *n);
/* The identity camera: looking down -z (W = -z), focal factor 2, aspect 1,
 * planes 0.125 and 128. */
void tc_identity_camera(double P[4][4]);

/* ---- random cases: a map P and a ball (c, r), a box b, a near plane wn ---- */
/* test_psphere's: a random camera with a ball in front of it (mostly),
 * beside or behind, radius 2^-40 to 2 times its distance; the whole map
 * scaled by 2^(k/4), k in [-200, 200], one time in 8 */
void tc_sphere_camera(xu_rng *g, double P[4][4], double c[3], double *r);
/* test_psphere's: a general map (entries 2^-20 .. 2^20, W mostly positive
 * near the origin), a center up to 4, a radius 2^-30 .. 1 */
void tc_sphere_general(xu_rng *g, double P[4][4], double c[3], double *r);
/* test_pnear's: a random camera with a box in front of it (mostly), near
 * the camera's near plane (half of them: so that wn cuts them) or behind;
 * wn = n 2^-3 .. n 2^1; the map and wn scaled by 2^k, k in [-40, 40], one
 * time in 8 */
void tc_box_camera(xu_rng *g, double P[4][4], cbx_box *b, double *wn);
/* test_pnear's: a general map, a box of half-widths 2^-30 .. 8, wn at W's
 * value at the center times 2^-7 .. 2 (or anywhere when it is not
 * positive) */
void tc_box_general(xu_rng *g, double P[4][4], cbx_box *b, double *wn);
/* test_pball's: as tc_box_camera, with a ball */
void tc_ball_camera(xu_rng *g, double P[4][4], double c[3], double *r, double *wn);
/* test_pball's: as tc_box_general, with a ball (radius 2^-30 .. 8) */
void tc_ball_general(xu_rng *g, double P[4][4], double c[3], double *r, double *wn);

/* ---- hard cases: tables of cases set up in P, (c, r), wn, each run by run --- */
/* The runner of a hard case that the table has just set up: want is the
 * status the case must get and what the message when it does not; what
 * NULL (want CBX_OK) where the table asks for no status (the oracle judges
 * the status either way). */
typedef void (*tc_run)(const char *name, cbx_status want, const char *what);
/* b = [l0, h0] x [l1, h1] x [l2, h2] */
void tc_set_box(cbx_box *b, double l0, double h0, double l1, double h1, double l2, double h2);
/* c = (c0, c1, c2), *r = r0 */
void tc_set_ball(double c[3], double *r, double c0, double c1, double c2, double r0);
/* the k-th wide or narrow camera (k = 0 .. 7: focal factor 2^-6 .. 2^-9,
 * then 2^8 .. 2^11; aspect 1.5, planes 0.01 and 1e4) scaled by 2^(12 k - 40) */
void tc_scaled_camera(double P[4][4], int k);
/* test_psphere's (cbx_project_sphere): a sphere straight ahead, NaN, the
 * domain's edges, the camera plane, rank-deficient maps, wide and narrow
 * fields of view, ends beyond 2^99, scaled maps */
void tc_sphere_hard(double P[4][4], double c[3], double *r, tc_run run);
/* test_pball's (cbx_project_sphere_near): balls around the identity
 * camera's near plane, NaN, bad near planes, the domain's edges, an end
 * beyond 2^99, rank-deficient maps, scaled wide and narrow cameras; gap:
 * a ball nearly tangent to the near plane, its radius 0.125 + gap */
void tc_ball_hard(double P[4][4], double c[3], double *r, double *wn, double gap, tc_run run);
/* test_pnear's and test_pwide's (cbx_project_box_near): boxes around the
 * identity camera's near plane, a point, huge and tiny boxes, NaN, an empty
 * box, bad near planes, the domain's edges, ends beyond 2^99, rank-deficient
 * maps, corners on the near plane, scaled wide and narrow cameras; mid (or
 * NULL) runs the caller's own cases before the rank-deficient maps */
void tc_box_hard(double P[4][4], cbx_box *b, double *wn, void (*mid)(void), tc_run run);

/* the 3x3 identity */
void tc_identity3(double rot[3][3]);
/* the rotation of the unit quaternion (w, x, y, z), normalised and rounded */
void tc_rotation(double rot[3][3], double w, double x, double y, double z);
/* a random ellipsoid shape of size about r (test_pell, test_pwide): rot a
 * rounded rotation, or (1 in 8) a general, maybe singular matrix; radii of
 * random signs, down to 2^-6 r (1 in 8: 2^-30 r), one of them zero in 1 of
 * 8 (a disk) */
void tc_ell_shape(xu_rng *g, double r, double rad[3], double rot[3][3]);

/* The first lines of a failure report: "FAIL what (name)" and the map's
 * rows in hexadecimal (the projective tests' on_fail print the rest). */
void tc_fail_map(const char *what, const char *name, const double P[4][4]);

#endif /* PROJ_CASES_H */
