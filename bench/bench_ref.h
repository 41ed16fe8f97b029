/*
 * bench_ref.h: the reference (baseline) algorithms of bench/bench.c.
 * NOT part of the library, and NOT sound: each is the usual textbook or
 * engine code in plain binary64 round-to-nearest, with no widening, so an
 * end may fall a few ulps inside the exact image (bench/bench.c counts
 * how often).  They are static inline, as in the header-only libraries
 * they stand for; build them with the library's flags
 * (-std=c99 -ffp-contract=off -fno-fast-math) so that no FMA is formed.
 *
 *   ref_naive8       transform the 8 corners as points (y = M x + T, each
 *                    coordinate m0*x0 + m1*x1 + m2*x2 + t, left to right)
 *                    and take min / max (pbrt's Transform::operator()
 *                    (Bounds3), Embree's xfmBounds);
 *   ref_arvo_box     Arvo's interval form (Graphics Gems I, Fig. 1): start
 *                    at t and add min / max of m_j lo_j and m_j hi_j, j =
 *                    0, 1, 2 in order (cglm's glm_aabb_transform, Godot's
 *                    Transform3D::xform(AABB)); the same arithmetic as
 *                    cbx_transform_box without the domain checks and the
 *                    widening;
 *   ref_arvo_cbox    Arvo's center/half form (Fig. 2): c' = M c + T,
 *                    h' = |M| h;
 *   ref_box_to_cbox  the usual conversion c = (lo + hi) / 2,
 *                    h = (hi - lo) / 2 (rounded to nearest; not outward);
 *   ref_arvo_boxf    ref_arvo_box in binary32: the same operations in the
 *                    same order on floats, every one rounded to nearest in
 *                    binary32 (FLT_EVAL_METHOD 0: SSE on x86, no double
 *                    intermediate), the baseline of the cbx_*f rows.
 */
#ifndef BENCH_REF_H
#define BENCH_REF_H

#include <math.h>
#include "certbox.h"

static inline double ref_min(double a, double b) { return a < b ? a : b; }
static inline double ref_max(double a, double b) { return a > b ? a : b; }
static inline double ref_abs(double a) { return a < 0.0 ? -a : a; }

static inline void ref_naive8(const cbx_affine *a, const cbx_box *in, cbx_box *out)
{
    double lo[3], hi[3];
    int c, i;
    for (i = 0; i < 3; i++) {
        lo[i] = HUGE_VAL;
        hi[i] = -HUGE_VAL;
    }
    for (c = 0; c < 8; c++) {
        double x0 = (c & 1) ? in->hi[0] : in->lo[0];
        double x1 = (c & 2) ? in->hi[1] : in->lo[1];
        double x2 = (c & 4) ? in->hi[2] : in->lo[2];
        for (i = 0; i < 3; i++) {
            double y = a->m[i][0] * x0 + a->m[i][1] * x1 + a->m[i][2] * x2 + a->m[i][3];
            lo[i] = ref_min(lo[i], y);
            hi[i] = ref_max(hi[i], y);
        }
    }
    for (i = 0; i < 3; i++) {
        out->lo[i] = lo[i];
        out->hi[i] = hi[i];
    }
}

/* The box of a box under a 4x4 projective map as pbrt, three.js and
 * Mitsuba compute it: the 8 corners, each row rounded to nearest, divided
 * by w; no care for w <= 0 and no rounding direction (unsound). */
static inline void ref_proj8(const cbx_proj *p, const cbx_box *in, cbx_box *out)
{
    double lo[3], hi[3];
    int c, i;
    for (i = 0; i < 3; i++) {
        lo[i] = HUGE_VAL;
        hi[i] = -HUGE_VAL;
    }
    for (c = 0; c < 8; c++) {
        double x0 = (c & 1) ? in->hi[0] : in->lo[0];
        double x1 = (c & 2) ? in->hi[1] : in->lo[1];
        double x2 = (c & 4) ? in->hi[2] : in->lo[2];
        double w = p->m[3][0] * x0 + p->m[3][1] * x1 + p->m[3][2] * x2 + p->m[3][3];
        for (i = 0; i < 3; i++) {
            double y = (p->m[i][0] * x0 + p->m[i][1] * x1 + p->m[i][2] * x2 + p->m[i][3]) / w;
            lo[i] = ref_min(lo[i], y);
            hi[i] = ref_max(hi[i], y);
        }
    }
    for (i = 0; i < 3; i++) {
        out->lo[i] = lo[i];
        out->hi[i] = hi[i];
    }
}

static inline void ref_arvo_box(const cbx_affine *a, const cbx_box *in, cbx_box *out)
{
    double lo[3], hi[3];
    int i, j;
    for (i = 0; i < 3; i++) {
        double l = a->m[i][3], h = a->m[i][3];
        for (j = 0; j < 3; j++) {
            double p = a->m[i][j] * in->lo[j];
            double q = a->m[i][j] * in->hi[j];
            l += ref_min(p, q);
            h += ref_max(p, q);
        }
        lo[i] = l;
        hi[i] = h;
    }
    for (i = 0; i < 3; i++) {
        out->lo[i] = lo[i];
        out->hi[i] = hi[i];
    }
}

static inline void ref_arvo_cbox(const cbx_affine *a, const cbx_cbox *in, cbx_cbox *out)
{
    double c[3], h[3];
    int i;
    for (i = 0; i < 3; i++) {
        c[i] = a->m[i][3] + a->m[i][0] * in->c[0] + a->m[i][1] * in->c[1]
               + a->m[i][2] * in->c[2];
        h[i] = ref_abs(a->m[i][0]) * in->h[0] + ref_abs(a->m[i][1]) * in->h[1]
               + ref_abs(a->m[i][2]) * in->h[2];
    }
    for (i = 0; i < 3; i++) {
        out->c[i] = c[i];
        out->h[i] = h[i];
    }
}

static inline void ref_box_to_cbox(const cbx_box *in, cbx_cbox *out)
{
    int j;
    for (j = 0; j < 3; j++) {
        out->c[j] = (in->lo[j] + in->hi[j]) * 0.5;
        out->h[j] = (in->hi[j] - in->lo[j]) * 0.5;
    }
}

static inline float ref_minf(float a, float b) { return a < b ? a : b; }
static inline float ref_maxf(float a, float b) { return a > b ? a : b; }

static inline void ref_arvo_boxf(const cbx_affinef *a, const cbx_boxf *in, cbx_boxf *out)
{
    float lo[3], hi[3];
    int i, j;
    for (i = 0; i < 3; i++) {
        float l = a->m[i][3], h = a->m[i][3];
        for (j = 0; j < 3; j++) {
            float p = a->m[i][j] * in->lo[j];
            float q = a->m[i][j] * in->hi[j];
            l += ref_minf(p, q);
            h += ref_maxf(p, q);
        }
        lo[i] = l;
        hi[i] = h;
    }
    for (i = 0; i < 3; i++) {
        out->lo[i] = lo[i];
        out->hi[i] = hi[i];
    }
}

#endif /* BENCH_REF_H */
