/*
 * trs_gen.c: the keyframe pairs of tests/test_trs.c (tests/trs_parts.h):
 * rotations of 0 to 180 degrees between the keyframes about random axes,
 * scaled and negated quaternions, scales of either sign, huge translations
 * beside tiny boxes, equal keyframes; and sin, cos, acos correctly rounded
 * (MPFR), for these and for the renderers' bounds in the driver.
 */
#include <math.h>

#include <mpfr.h>

#include "trs_parts.h"

/* sin, cos, acos correctly rounded to double (MPFR at 53 bits): the same
 * bits on every platform, so that the ARM run (make check-cross) sees the
 * same cases as this one. */
double trt_cr_fn(int (*f)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t), double x)
{
    mpfr_t t;
    double r;
    mpfr_init2(t, 53);
    mpfr_set_d(t, x, MPFR_RNDN);
    f(t, t, MPFR_RNDN);
    r = mpfr_get_d(t, MPFR_RNDN);
    mpfr_clear(t);
    return r;
}

/* ---- generators --------------------------------------------------------- */

static double uni(xu_rng *r, double a, double b) { return a + (b - a) * xu_rng_unit(r); }

static void quat_mul(const double a[4], const double b[4], double o[4])
{
    /* (x, y, z, w) Hamilton product a b */
    o[0] = a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1];
    o[1] = a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0];
    o[2] = a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3];
    o[3] = a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2];
}

static void rand_axis_quat(xu_rng *r, double deg, double q[4])
{
    double ax[3], n = 0, h = deg * 3.14159265358979323846 / 360.0;
    int i;
    do {
        n = 0;
        for (i = 0; i < 3; i++) {
            ax[i] = uni(r, -1, 1);
            n += ax[i] * ax[i];
        }
    } while (n < 0.01 || n > 1);
    n = sqrt(n);
    for (i = 0; i < 3; i++) {
        q[i] = trt_cr_fn(mpfr_sin, h) * ax[i] / n;
    }
    q[3] = trt_cr_fn(mpfr_cos, h);
}

static const double angles[] = { 0, 1e-9, 1e-4, 45, 90, 179.9, 180, -1 };

/* A keyframe pair; returns the angle category's index. */
int trt_gen_pair(xu_rng *r, cbx_trs *k0, cbx_trs *k1, cbx_box *b, int *big)
{
    int cat = xu_rng_int(r, 0, 7), i;
    double deg = angles[cat] < 0 ? uni(r, 0, 180) : angles[cat];
    double q0[4], dq[4], q1[4], sc0, sc1;
    int huge = xu_rng_int(r, 0, 19) == 0;
    *big = huge;
    rand_axis_quat(r, uni(r, 0, 360), q0);
    rand_axis_quat(r, deg, dq);
    quat_mul(q0, dq, q1);
    sc0 = ldexp(1.0, xu_rng_int(r, -20, 20)) * uni(r, 0.5, 1) * xu_rng_sign(r);
    sc1 = ldexp(1.0, xu_rng_int(r, -20, 20)) * uni(r, 0.5, 1) * xu_rng_sign(r);
    for (i = 0; i < 4; i++) {
        k0->q[i] = q0[i] * sc0;
        k1->q[i] = q1[i] * sc1;
    }
    for (i = 0; i < 3; i++) {
        double c = huge ? uni(r, -1e12, 1e12) : uni(r, -100, 100);
        double h = huge ? uni(r, 1e-6, 1e-3) : uni(r, 1e-3, 10);
        k0->t[i] = huge ? uni(r, -1e12, 1e12) : uni(r, -100, 100);
        k1->t[i] = xu_rng_int(r, 0, 3) == 0 ? k0->t[i] : k0->t[i] + uni(r, -50, 50);
        k0->s[i] = uni(r, 0.1, 10) * (xu_rng_int(r, 0, 5) == 0 ? -1 : 1);
        k1->s[i] = k0->s[i];
        b->lo[i] = c - h;
        b->hi[i] = c + h;
        (void)c;
    }
    if (xu_rng_int(r, 0, 2) == 0) { /* scales that change (and may flip) */
        for (i = 0; i < 3; i++) {
            k1->s[i] = uni(r, 0.1, 10) * (xu_rng_int(r, 0, 5) == 0 ? -1 : 1);
        }
    }
    if (xu_rng_int(r, 0, 19) == 0) { /* equal keyframes */
        *k1 = *k0;
        cat = 0;
    }
    return cat;
}
