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

/* The box clipped at the near plane W = wn, round to nearest: X / W at the
 * corners with W >= wn and at the edges' crossings of W = wn (the vertices
 * of the clipped box; what a renderer that clips would compute). */
static inline void ref_pnear(const cbx_proj *p, const cbx_box *in, double wn, cbx_box *out)
{
    double x[8][3], w[8], lo[3], hi[3];
    int c, i, j;
    for (i = 0; i < 3; i++) {
        lo[i] = HUGE_VAL;
        hi[i] = -HUGE_VAL;
    }
    for (c = 0; c < 8; c++) {
        for (j = 0; j < 3; j++)
            x[c][j] = (c >> j) & 1 ? in->hi[j] : in->lo[j];
        w[c] = p->m[3][0] * x[c][0] + p->m[3][1] * x[c][1] + p->m[3][2] * x[c][2] + p->m[3][3];
        if (w[c] >= wn)
            for (i = 0; i < 3; i++) {
                double y = (p->m[i][0] * x[c][0] + p->m[i][1] * x[c][1] + p->m[i][2] * x[c][2] + p->m[i][3]) / w[c];
                lo[i] = ref_min(lo[i], y);
                hi[i] = ref_max(hi[i], y);
            }
    }
    for (c = 0; c < 8; c++)
        for (j = 0; j < 3; j++) {
            int d = c | (1 << j);
            if (d != c && (w[c] >= wn) != (w[d] >= wn)) {
                double u = (wn - w[c]) / (w[d] - w[c]), y[3];
                int k;
                for (k = 0; k < 3; k++)
                    y[k] = x[c][k] + u * (x[d][k] - x[c][k]);
                for (i = 0; i < 3; i++) {
                    double v = (p->m[i][0] * y[0] + p->m[i][1] * y[1] + p->m[i][2] * y[2] + p->m[i][3]) / wn;
                    lo[i] = ref_min(lo[i], v);
                    hi[i] = ref_max(hi[i], v);
                }
            }
        }
    for (i = 0; i < 3; i++) {
        out->lo[i] = lo[i];
        out->hi[i] = hi[i];
    }
}

/* The projected ball in closed form, round to nearest: the roots of
 * (A - t B)^2 = r^2 |a - t b|^2 per axis (Mara and McGuire 2013). */
static inline void ref_psphere(const cbx_proj *p, const double c[3], double r, cbx_box *out)
{
    const double *b = p->m[3];
    double B = b[0] * c[0] + b[1] * c[1] + b[2] * c[2] + b[3];
    double r2 = r * r;
    double al = B * B - r2 * (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    int i;
    for (i = 0; i < 3; i++) {
        const double *a = p->m[i];
        double A = a[0] * c[0] + a[1] * c[1] + a[2] * c[2] + a[3];
        double be = A * B - r2 * (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
        double ga = A * A - r2 * (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        double de = be * be - al * ga;
        double sq = sqrt(de > 0 ? de : 0);
        out->lo[i] = (be - sq) / al;
        out->hi[i] = (be + sq) / al;
    }
}

/* The projected ball through its bounding box: 8 corners divided by w. */
static inline void ref_psphere_box8(const cbx_proj *p, const double c[3], double r, cbx_box *out)
{
    cbx_box b;
    int i;
    for (i = 0; i < 3; i++) {
        b.lo[i] = c[i] - r;
        b.hi[i] = c[i] + r;
    }
    ref_proj8(p, &b, out);
}

/* The projected ellipsoid c + rot diag(s) q, |q| <= 1, in closed form in
 * round-to-nearest: the ball's formula on the rows M^T a, M^T b (M = rot
 * diag(s)), radius 1 (unsound). */
static inline void ref_pell(const cbx_proj *p, const double c[3], const double s[3], const double rot[3][3],
                            cbx_box *out)
{
    double q[4][4];
    const double z[3] = {0, 0, 0};
    cbx_proj f;
    int i, j;
    for (i = 0; i < 4; i++) {
        const double *a = p->m[i];
        for (j = 0; j < 3; j++)
            q[i][j] = s[j] * (rot[0][j] * a[0] + rot[1][j] * a[1] + rot[2][j] * a[2]);
        q[i][3] = a[0] * c[0] + a[1] * c[1] + a[2] * c[2] + a[3];
    }
    memcpy(f.m, q, sizeof q);
    ref_psphere(&f, z, 1.0, out);
}

/* The projected ellipsoid through its oriented box c + M [-1, 1]^3: its 8
 * corners, each rounded to nearest, divided by w (what an engine does with
 * an OBB; unsound, and looser). */
static inline void ref_pell_obb8(const cbx_proj *p, const double c[3], const double s[3],
                                 const double rot[3][3], cbx_box *out)
{
    int k, i, j;
    for (i = 0; i < 3; i++) {
        out->lo[i] = HUGE_VAL;
        out->hi[i] = -HUGE_VAL;
    }
    for (k = 0; k < 8; k++) {
        double x[3], w;
        for (i = 0; i < 3; i++) {
            x[i] = c[i];
            for (j = 0; j < 3; j++)
                x[i] += rot[i][j] * (((k >> j) & 1) ? s[j] : -s[j]);
        }
        w = p->m[3][0] * x[0] + p->m[3][1] * x[1] + p->m[3][2] * x[2] + p->m[3][3];
        for (i = 0; i < 3; i++) {
            double y = (p->m[i][0] * x[0] + p->m[i][1] * x[1] + p->m[i][2] * x[2] + p->m[i][3]) / w;
            out->lo[i] = ref_min(out->lo[i], y);
            out->hi[i] = ref_max(out->hi[i], y);
        }
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

/* Motion with rotation as the renderers bound it (unsound): the map of a
 * translation / rotation / scale keyframe pair at time s, rounded to
 * nearest (q1 negated when q0.q1 < 0, both normalised; slerp with acos and
 * sin as pbrt's AnimatedTransform::Interpolate, or nlerp when nl != 0);
 * ref_trs_samples: the box of the 8 corners at the times ts[] (s = 0 and 1:
 * the union of the endpoint boxes; t = k / 128, k < 128: Cycles' object
 * motion, never t = 1).  REF_SIN / REF_ACOS may be defined before this
 * header (tests/test_trs.c: correctly rounded, the same bits on ARM). */
#ifndef REF_SIN
#define REF_SIN(x) sin(x)
#define REF_ACOS(x) acos(x)
#endif
static inline void ref_trs_map(const cbx_trs *k0, const cbx_trs *k1, double s, int nl, cbx_affine *m)
{
    double a[4], b[4], q[4], n0 = 0, n1 = 0, n = 0, d = 0, th, w0, w1, x, y, z, w;
    double R[3][3];
    int i, j;
    for (i = 0; i < 4; i++) {
        n0 += k0->q[i] * k0->q[i];
        n1 += k1->q[i] * k1->q[i];
    }
    n0 = sqrt(n0);
    n1 = sqrt(n1);
    for (i = 0; i < 4; i++) {
        a[i] = k0->q[i] / n0;
        b[i] = k1->q[i] / n1;
        d += a[i] * b[i];
    }
    if (d < 0) {
        for (i = 0; i < 4; i++) b[i] = -b[i];
        d = -d;
    }
    th = REF_ACOS(d > 1 ? 1 : d);
    if (nl || th < 1e-9) {
        w0 = 1 - s;
        w1 = s;
    } else {
        w0 = REF_SIN((1 - s) * th) / REF_SIN(th);
        w1 = REF_SIN(s * th) / REF_SIN(th);
    }
    for (i = 0; i < 4; i++) {
        q[i] = w0 * a[i] + w1 * b[i];
        n += q[i] * q[i];
    }
    n = sqrt(n);
    x = q[0] / n; y = q[1] / n; z = q[2] / n; w = q[3] / n;
    R[0][0] = 1 - 2 * (y * y + z * z); R[0][1] = 2 * (x * y - z * w); R[0][2] = 2 * (x * z + y * w);
    R[1][0] = 2 * (x * y + z * w); R[1][1] = 1 - 2 * (x * x + z * z); R[1][2] = 2 * (y * z - x * w);
    R[2][0] = 2 * (x * z - y * w); R[2][1] = 2 * (y * z + x * w); R[2][2] = 1 - 2 * (x * x + y * y);
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) m->m[i][j] = R[i][j] * ((1 - s) * k0->s[j] + s * k1->s[j]);
        m->m[i][3] = (1 - s) * k0->t[i] + s * k1->t[i];
    }
}

static inline void ref_trs_union(cbx_box *acc, const cbx_box *b, int first)
{
    int i;
    for (i = 0; i < 3; i++) {
        acc->lo[i] = first ? b->lo[i] : ref_min(acc->lo[i], b->lo[i]);
        acc->hi[i] = first ? b->hi[i] : ref_max(acc->hi[i], b->hi[i]);
    }
}

static inline void ref_trs_samples(const cbx_trs *k0, const cbx_trs *k1, int nl, const double *ts, int nt,
                                   const cbx_box *in, cbx_box *out)
{
    int k;
    for (k = 0; k < nt; k++) {
        cbx_affine m;
        cbx_box b;
        ref_trs_map(k0, k1, ts[k], nl, &m);
        ref_naive8(&m, in, &b);
        ref_trs_union(out, &b, k == 0);
    }
}

#endif /* BENCH_REF_H */
