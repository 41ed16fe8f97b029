/*
 * proj_cases.h: cameras for the projective tests (tests/test_psphere.c,
 * tests/test_pnear.c): a perspective projection times a rigid view, built
 * from given numbers only (no libm function that is not correctly rounded,
 * so that a case has the same bits on every machine: make check-cross).
 */
#ifndef PROJ_CASES_H
#define PROJ_CASES_H

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

#endif /* PROJ_CASES_H */
