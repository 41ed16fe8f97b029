/*
 * test_plane [N] [seed]: the 2D form (cbx_transform_box2, cbx_transform_box2f)
 * against exact rational arithmetic, in both formats.
 *
 * Each case is a 2D map and box.  Its embedding in 3D has the same two
 * rows with a zero third column, a zero third row, and the third box axis
 * [0, 0]: the 2D contract is the 3D one on that plane (specs/cbx_plane.h).
 * For every case:
 *   1. oracle: the 2D output, with the third axis of the 3D call, is judged
 *      by exact_util's oracle on the embedding (xu_check_result: the status
 *      computed exactly, the special outputs, containment of the exact
 *      image and the proven bound 12 u S + eta on every finite end, the
 *      end kinds of half-planes and out-of-domain rows; the corners in mpq
 *      on every 50th case);
 *   2. the same bits as the 3D function on the embedding (axes 0, 1 and the
 *      status): the 2D form is not a second algorithm;
 *   3. in place (out == in) gives the same bits; the inputs are unchanged.
 * Cases: a table of 2D hard cases (NaN in each of the 10 inputs, empty
 * axes, half-planes, the domain's edges, rotations, subnormals), then N
 * random cases drawn by test_exact's generator (rows 0 and 1, box axes 0
 * and 1), in binary64 and then in binary32 (values rounded to float).
 * The center form (cbx_transform_cbox2, cbx_transform_cbox2f): the status
 * against exact_util's cbox rules on the 3D embedding, the special
 * outputs, every lost axis exactly c = 0, h = +inf, every other axis
 * finite and holding the exact image of the 4 corners c_j -+ h_j (mpq,
 * zero-coefficient columns dropped as the contract says), and the same
 * bits as cbx_transform_cbox on the embedding (whose tightness test_cbox
 * checks exactly).
 * The conversions (cbx_box2_to_cbox2, cbx_cbox2_to_box2 and their binary32
 * twins): the status and special outputs from the domain, each converted
 * axis holding its input axis and within the proven 16 u (|x| + |y|) +
 * 2^-1066 (binary32: 2^-141) of it, both in mpq, and the same bits as the
 * 3D conversions on the embedding.
 * Disks and ellipses (cbx_disk_box2, cbx_ellipse_box2 and their binary32
 * twins): on every axis the status and the special outputs as computed
 * from the domain (NaN -> CBX_EINVAL and the whole plane; an axis outside
 * the domain exactly [-inf, +inf] with CBX_ERANGE); on an axis in the
 * domain, t -+ sqrt(s) (s = m_i0^2 + m_i1^2, for the ellipse with
 * m_ij = rot_ij radii_j, all exact in GMP) inside [lo, hi], and each end
 * within the proven 80 u (|t| + sqrt s) + 2^-1064 (binary32: 2^-139), both
 * decided exactly in integers; and the same bits as cbx_sphere_box /
 * cbx_ellipsoid_box on the 3D embedding.  A table of hard cases, then N
 * random disks and N random ellipses per format.
 * The last line is "P passed, F failed".
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "certbox.h"
#include "exact_util.h"

typedef struct plane_case {
    const char *name;
    double m[2][3];
    double lo[2], hi[2];
} plane_case;

#define INF HUGE_VAL
static const plane_case hard[] = {
    { "identity", { { 1, 0, 0 }, { 0, 1, 0 } }, { -1, -2 }, { 3, 4 } },
    { "rotation by 90 degrees", { { 0, -1, 5 }, { 1, 0, -5 } }, { -1, -2 }, { 3, 4 } },
    { "rotation by 30 degrees", { { 0.8660254037844387, -0.5, 0 }, { 0.5, 0.8660254037844387, 0 } },
      { -1, -1 }, { 1, 1 } },
    { "shear and mirror", { { -1, 3, 0.1 }, { 0, -1, 1e-300 } }, { 0.1, -0.3 }, { 0.7, 0.2 } },
    { "point box", { { 3, 5, 7 }, { 11, 13, 17 } }, { 0.1, 0.2 }, { 0.1, 0.2 } },
    { "subnormal entries", { { 0x1p-1074, -0x1p-1060, 0x1p-1070 }, { 1, 0x1p-1074, 0 } },
      { -0x1p-1074, 3 }, { 0x1p-1000, 4 } },
    { "-0 entries and ends", { { -0.0, 1, -0.0 }, { 1, -0.0, 0 } }, { -0.0, -0.0 }, { 0, 0 } },
    { "entries at 2^509", { { 0x1p509, -0x1p509, 0x1p1018 }, { 0x1p509, 0x1p509, -0x1p1018 } },
      { -0x1p509, -0x1p509 }, { 0x1p509, 0x1p509 } },
    { "product above the domain", { { 0x1p600, 1, 0 }, { 1, 1, 0 } }, { -0x1p500, 0 }, { 0x1p500, 1 } },
    { "half-plane x >= 2", { { 1, 1, 0 }, { -1, 2, 0 } }, { 2, 0 }, { INF, 1 } },
    { "half-plane x <= 2 times zero", { { 0, 1, 0 }, { 1, 0, 0 } }, { -INF, 0 }, { 2, 1 } },
    { "the whole plane", { { 1, 0, 0 }, { 0, 0, 1 } }, { -INF, -INF }, { INF, INF } },
    { "infinite entry", { { INF, 0, 0 }, { 1, 1, 1 } }, { 0, 0 }, { 1, 1 } },
    { "infinite translation", { { 1, 0, -INF }, { 1, 1, 1 } }, { 0, 0 }, { 1, 1 } },
    { "empty axis 0", { { 1, 0, 0 }, { 0, 1, 0 } }, { 1, 0 }, { 0, 1 } },
    { "empty axis 1 (+inf, +inf)", { { 1, 0, 0 }, { 0, 1, 0 } }, { 0, INF }, { 1, INF } },
    { "NaN m00", { { NAN, 0, 0 }, { 0, 1, 0 } }, { 0, 0 }, { 1, 1 } },
    { "NaN m01", { { 1, NAN, 0 }, { 0, 1, 0 } }, { 0, 0 }, { 1, 1 } },
    { "NaN t0", { { 1, 0, NAN }, { 0, 1, 0 } }, { 0, 0 }, { 1, 1 } },
    { "NaN m10", { { 1, 0, 0 }, { NAN, 1, 0 } }, { 0, 0 }, { 1, 1 } },
    { "NaN m11", { { 1, 0, 0 }, { 0, NAN, 0 } }, { 0, 0 }, { 1, 1 } },
    { "NaN t1", { { 1, 0, 0 }, { 0, 1, NAN } }, { 0, 0 }, { 1, 1 } },
    { "NaN lo0 with an empty axis", { { 1, 0, 0 }, { 0, 1, 0 } }, { NAN, 1 }, { 1, 0 } },
    { "NaN lo1", { { 1, 0, 0 }, { 0, 1, 0 } }, { 0, NAN }, { 1, 1 } },
    { "NaN hi0", { { 1, 0, 0 }, { 0, 1, 0 } }, { 0, 0 }, { NAN, 1 } },
    { "NaN hi1", { { 1, 0, 0 }, { 0, 1, 0 } }, { 0, 0 }, { 1, NAN } },
};
#define N_HARD ((int)(sizeof hard / sizeof hard[0]))

typedef struct tally {
    long cases, failed, checks;
    long status[4];
} tally;

static long fail_logs;

static void fail(const char *fam, const char *what, const char *why)
{
    if (fail_logs++ < 20) printf("FAIL %s %s: %s\n", fam, what, why);
}

/* The 3D embedding of a 2D case (rows 0 and 1 with a zero third column,
 * row 2 zero; box axis 2 [0, 0]). */
static void embed(const double m[2][3], const double lo[2], const double hi[2],
                  cbx_affine *a3, cbx_box *b3)
{
    int i;
    memset(a3, 0, sizeof *a3);
    for (i = 0; i < 2; i++) {
        a3->m[i][0] = m[i][0];
        a3->m[i][1] = m[i][1];
        a3->m[i][2] = 0.0;
        a3->m[i][3] = m[i][2];
        b3->lo[i] = lo[i];
        b3->hi[i] = hi[i];
    }
    b3->lo[2] = 0.0;
    b3->hi[2] = 0.0;
}

/* The excess statistics are the 2D axes' alone: the embedding's third
 * axis (a zero row, u S = 0) is judged by the oracle (its checks are
 * counted) but left out of the excess figures. */
static void drop_third(xu_verdict *v)
{
    v->ax[2].checked = 0;
    v->ax[2].end_checked[0] = v->ax[2].end_checked[1] = 0;
    v->ax[2].end_kind[0] = v->ax[2].end_kind[1] = -1;
}

/* What a case's two calls gave, beside the oracle's verdict. */
typedef struct facts {
    int bits_same;     /* status and axes 0, 1 = the 3D function's           */
    int inplace_same;  /* out == in gave the same status and bits            */
    int inputs_same;   /* the map and the box unchanged by the call          */
} facts;

/* Judge one case: the oracle on the embedding (o3: the 2D output's two axes
 * and the 3D call's third), then the facts; returns 1 on failure. */
static int judge(xu_exact *x, xu_stats *st, tally *t, const cbx_affine *a3, const cbx_box *b3,
                 const cbx_box *o3, cbx_status s, const facts *f, int corners, const char *fam,
                 const char *what)
{
    xu_verdict v;
    int k;
    xu_check_result(x, a3, b3, o3, s, corners, &v);
    for (k = 0; k < XU_NFLAGS; k++) t->checks += v.applied[k];
    t->checks += 3;
    if (!v.failed && !f->bits_same) {
        v.failed = 1;
        snprintf(v.why, sizeof v.why, "not the bits of the 3D function on the embedding");
    }
    if (!v.failed && !f->inplace_same) {
        v.failed = 1;
        snprintf(v.why, sizeof v.why, "in place differs from the separate output");
    }
    if (!v.failed && !f->inputs_same) {
        v.failed = 1;
        snprintf(v.why, sizeof v.why, "an input changed");
    }
    t->cases++;
    if (xu_status_index(s) >= 0) t->status[xu_status_index(s)]++;
    drop_third(&v);
    xu_stats_add(st, &v, a3, b3);
    if (v.failed) {
        t->failed++;
        fail(fam, what, v.why);
    }
    return v.failed;
}

/* One case in binary64; returns 1 on failure. */
static int run64(xu_exact *x, xu_stats *st, tally *t, const double m[2][3], const double lo[2],
                 const double hi[2], int corners, const char *what)
{
    cbx_affine2 a, a0;
    cbx_box2 b, b0, o, ip;
    cbx_affine a3;
    cbx_box b3, r3, o3;
    cbx_status s, s3;
    facts f;
    int i, k;
    for (i = 0; i < 2; i++) {
        for (k = 0; k < 3; k++) a.m[i][k] = m[i][k];
        b.lo[i] = lo[i];
        b.hi[i] = hi[i];
    }
    a0 = a;
    b0 = b;
    memset(&o, 0xff, sizeof o); /* NaN: every field must be written */
    s = cbx_transform_box2(&a, &b, &o);
    embed(m, lo, hi, &a3, &b3);
    s3 = cbx_transform_box(&a3, &b3, &r3);
    o3 = r3;
    for (i = 0; i < 2; i++) {
        o3.lo[i] = o.lo[i];
        o3.hi[i] = o.hi[i];
    }
    f.bits_same = s == s3 && !memcmp(o.lo, r3.lo, sizeof o.lo) && !memcmp(o.hi, r3.hi, sizeof o.hi);
    f.inputs_same = !memcmp(&a, &a0, sizeof a) && !memcmp(&b, &b0, sizeof b);
    ip = b;
    f.inplace_same = cbx_transform_box2(&a, &ip, &ip) == s && !memcmp(&ip, &o, sizeof o);
    return judge(x, st, t, &a3, &b3, &o3, s, &f, corners, "binary64", what);
}

/* One case in binary32 (m, lo, hi already floats); returns 1 on failure. */
static int run32(xu_exact *x, xu_stats *st, tally *t, const double m[2][3], const double lo[2],
                 const double hi[2], int corners, const char *what)
{
    cbx_affine2f a, a0;
    cbx_box2f b, b0, o, ip;
    cbx_affinef a3f;
    cbx_boxf b3f, r3f;
    cbx_affine a3;
    cbx_box b3, o3;
    cbx_status s, s3;
    facts f;
    int i, k;
    for (i = 0; i < 2; i++) {
        for (k = 0; k < 3; k++) a.m[i][k] = (float)m[i][k];
        b.lo[i] = (float)lo[i];
        b.hi[i] = (float)hi[i];
    }
    a0 = a;
    b0 = b;
    memset(&o, 0xff, sizeof o);
    s = cbx_transform_box2f(&a, &b, &o);
    embed(m, lo, hi, &a3, &b3);
    for (i = 0; i < 3; i++) {
        for (k = 0; k < 4; k++) a3f.m[i][k] = (float)a3.m[i][k];
        b3f.lo[i] = (float)b3.lo[i];
        b3f.hi[i] = (float)b3.hi[i];
    }
    s3 = cbx_transform_boxf(&a3f, &b3f, &r3f);
    for (i = 0; i < 3; i++) {
        o3.lo[i] = i < 2 ? (double)o.lo[i] : (double)r3f.lo[i];
        o3.hi[i] = i < 2 ? (double)o.hi[i] : (double)r3f.hi[i];
    }
    f.bits_same = s == s3 && !memcmp(o.lo, r3f.lo, sizeof o.lo) && !memcmp(o.hi, r3f.hi, sizeof o.hi);
    f.inputs_same = !memcmp(&a, &a0, sizeof a) && !memcmp(&b, &b0, sizeof b);
    ip = b;
    f.inplace_same = cbx_transform_box2f(&a, &ip, &ip) == s && !memcmp(&ip, &o, sizeof o);
    return judge(x, st, t, &a3, &b3, &o3, s, &f, corners, "binary32", what);
}

typedef int (*runner)(xu_exact *, xu_stats *, tally *, const double[2][3], const double[2],
                      const double[2], int, const char *);

/* The table, then n random cases, in the current format. */
static long family(xu_exact *x, const char *fam, runner run, long n, uint64_t seed, long *passed)
{
    xu_stats st;
    tally t;
    xu_rng r;
    long c;
    int k, i, j;
    char what[64];
    memset(&t, 0, sizeof t);
    xu_stats_init(&st);
    for (k = 0; k < N_HARD; k++) {
        double m[2][3], lo[2], hi[2];
        for (i = 0; i < 2; i++) {
            for (j = 0; j < 3; j++) m[i][j] = xu_round_fmt(hard[k].m[i][j]);
            lo[i] = xu_round_fmt(hard[k].lo[i]);
            hi[i] = xu_round_fmt(hard[k].hi[i]);
        }
        run(x, &st, &t, (const double(*)[3])m, lo, hi, 1, hard[k].name);
    }
    r.s = seed;
    for (c = 0; c < n; c++) {
        cbx_affine a;
        cbx_box b;
        double m[2][3], lo[2], hi[2];
        xu_gen_case(&r, &a, &b);
        for (i = 0; i < 2; i++) {
            m[i][0] = a.m[i][0];
            m[i][1] = a.m[i][1];
            m[i][2] = a.m[i][3];
            lo[i] = b.lo[i];
            hi[i] = b.hi[i];
        }
        snprintf(what, sizeof what, "random case %ld", c);
        run(x, &st, &t, (const double(*)[3])m, lo, hi, c % 50 == 0, what);
    }
    printf("test_plane: %s: %ld cases (%d hard, %ld random), %ld checks, %ld failed; "
           "statuses OK %ld, EMPTY %ld, EINVAL %ld, ERANGE %ld\n", fam, t.cases, N_HARD, n,
           t.checks, t.failed, t.status[0], t.status[1], t.status[2], t.status[3]);
    xu_stats_print(stdout, fam, &st);
    *passed += t.cases - t.failed;
    return t.failed;
}

/* ---- the center form --------------------------------------------------- */

static int is_pinf(double d) { return d > 0 && isinf(d); }
static int is_ninf(double d) { return d < 0 && isinf(d); }

typedef struct ctally { long cases, failed, checks, axes, status[4]; } ctally;

/* The 4 corners of axis i of the (dropped) box, exactly, inside
 * [oc - oh, oc + oh]. */
static int cbox2_corners_in(const double m[3], const cbx_cbox *d, double oc, double oh)
{
    mpq_t v, x, lo, hi, q;
    int k, j, ok = 1;
    mpq_inits(v, x, lo, hi, q, NULL);
    mpq_set_d(lo, oc);
    mpq_set_d(q, oh);
    mpq_set(hi, lo);
    mpq_sub(lo, lo, q);
    mpq_add(hi, hi, q);
    for (k = 0; k < 4 && ok; k++) {
        mpq_set_d(v, m[2]);
        for (j = 0; j < 2; j++) {
            mpq_set_d(x, d->c[j]);
            mpq_set_d(q, d->h[j]);
            if ((k >> j) & 1) mpq_add(x, x, q);
            else mpq_sub(x, x, q);
            mpq_set_d(q, m[j]);
            mpq_mul(x, x, q);
            mpq_add(v, v, x);
        }
        ok = mpq_cmp(lo, v) <= 0 && mpq_cmp(v, hi) <= 0;
    }
    mpq_clears(v, x, lo, hi, q, NULL);
    return ok;
}

/* One case: m[i] = {m_i0, m_i1, t_i}, c, h (values of the format). */
static void run_cbox(ctally *t, int f32, const double m[2][3], const double c[2], const double h[2],
                     const char *what)
{
    const char *fam = f32 ? "cbx_transform_cbox2f" : "cbx_transform_cbox2";
    cbx_affine a3;
    cbx_cbox b3;
    double oc[2], oh[2], rc[2], rh[2];
    cbx_status got, ref, ipst, want;
    int i, j, same_in, same_ip;
    char why[160];
    why[0] = 0;
    memset(&a3, 0, sizeof a3);
    memset(&b3, 0, sizeof b3);
    for (i = 0; i < 2; i++) {
        a3.m[i][0] = m[i][0]; a3.m[i][1] = m[i][1]; a3.m[i][3] = m[i][2];
        b3.c[i] = c[i]; b3.h[i] = h[i];
    }
    if (f32) {
        cbx_affine2f a, a0;
        cbx_cbox2f b, b0, o, ip;
        cbx_affinef a3f;
        cbx_cboxf b3f, r3f;
        memset(&a3f, 0, sizeof a3f);
        memset(&b3f, 0, sizeof b3f);
        for (i = 0; i < 2; i++) {
            for (j = 0; j < 3; j++) a.m[i][j] = (float)m[i][j];
            b.c[i] = (float)c[i]; b.h[i] = (float)h[i];
            a3f.m[i][0] = a.m[i][0]; a3f.m[i][1] = a.m[i][1]; a3f.m[i][3] = a.m[i][2];
            b3f.c[i] = b.c[i]; b3f.h[i] = b.h[i];
        }
        a0 = a; b0 = b;
        memset(&o, 0xff, sizeof o);
        got = cbx_transform_cbox2f(&a, &b, &o);
        ref = cbx_transform_cboxf(&a3f, &b3f, &r3f);
        same_in = !memcmp(&a, &a0, sizeof a) && !memcmp(&b, &b0, sizeof b);
        ip = b;
        ipst = cbx_transform_cbox2f(&a, &ip, &ip);
        same_ip = ipst == got && !memcmp(&ip, &o, sizeof o);
        for (i = 0; i < 2; i++) { oc[i] = o.c[i]; oh[i] = o.h[i]; rc[i] = r3f.c[i]; rh[i] = r3f.h[i]; }
    } else {
        cbx_affine2 a, a0;
        cbx_cbox2 b, b0, o, ip;
        cbx_cbox r3;
        for (i = 0; i < 2; i++) {
            for (j = 0; j < 3; j++) a.m[i][j] = m[i][j];
            b.c[i] = c[i]; b.h[i] = h[i];
        }
        a0 = a; b0 = b;
        memset(&o, 0xff, sizeof o);
        got = cbx_transform_cbox2(&a, &b, &o);
        ref = cbx_transform_cbox(&a3, &b3, &r3);
        same_in = !memcmp(&a, &a0, sizeof a) && !memcmp(&b, &b0, sizeof b);
        ip = b;
        ipst = cbx_transform_cbox2(&a, &ip, &ip);
        same_ip = ipst == got && !memcmp(&ip, &o, sizeof o);
        for (i = 0; i < 2; i++) { oc[i] = o.c[i]; oh[i] = o.h[i]; rc[i] = r3.c[i]; rh[i] = r3.h[i]; }
    }
    t->cases++;
    t->checks += 4;
    want = xu_cbox_expected_status(&a3, &b3);
    if (got != want)
        snprintf(why, sizeof why, "status %s, expected %s", cbx_status_name(got), cbx_status_name(want));
    else if (got != ref || memcmp(oc, rc, sizeof oc) || memcmp(oh, rh, sizeof oh))
        snprintf(why, sizeof why, "not the bits of cbx_transform_cbox on the 3D embedding");
    else if (!same_in)
        snprintf(why, sizeof why, "an input changed");
    else if (!same_ip)
        snprintf(why, sizeof why, "in place differs from the separate output");
    if (!why[0] && xu_status_index(got) >= 0) t->status[xu_status_index(got)]++;
    for (i = 0; i < 2 && !why[0]; i++) {
        int kind;
        cbx_cbox d;
        t->checks++;
        if (got == CBX_EINVAL || got == CBX_EMPTY) {
            if (oc[i] != 0 || !(got == CBX_EINVAL ? is_pinf(oh[i]) : is_ninf(oh[i])))
                snprintf(why, sizeof why, "axis %d: not the special output of %s", i, cbx_status_name(got));
            continue;
        }
        kind = xu_cbox_axis_kind(&a3, &b3, i);
        if (kind == XU_CAX_LOST) {
            if (oc[i] != 0 || !is_pinf(oh[i]))
                snprintf(why, sizeof why, "axis %d lost but not c = 0, h = +inf", i);
            continue;
        }
        t->axes++;
        if (!isfinite(oc[i]) || !isfinite(oh[i]) || oh[i] < 0) {
            snprintf(why, sizeof why, "axis %d: c = %g, h = %g, not finite with h >= 0", i, oc[i], oh[i]);
            continue;
        }
        xu_cbox_dropped(&a3, &b3, i, &d);
        if (!cbox2_corners_in(m[i], &d, oc[i], oh[i]))
            snprintf(why, sizeof why, "axis %d: a corner's exact image outside [c - h, c + h]", i);
    }
    if (why[0]) {
        t->failed++;
        fail(fam, what, why);
    }
}

static long cboxes(int f32, long n, uint64_t seed, long *passed)
{
    ctally t;
    xu_rng r;
    long c;
    int i;
    char what[64];
    memset(&t, 0, sizeof t);
    for (c = 0; c < N_HARD; c++) {
        double m[2][3], cc[2], hh[2];
        int j;
        for (i = 0; i < 2; i++) {
            for (j = 0; j < 3; j++) m[i][j] = xu_round_fmt(hard[c].m[i][j]);
            cc[i] = xu_round_fmt(hard[c].lo[i]);
            hh[i] = xu_round_fmt(hard[c].hi[i] - hard[c].lo[i]);
        }
        run_cbox(&t, f32, (const double(*)[3])m, cc, hh, hard[c].name);
    }
    r.s = seed;
    for (c = 0; c < n; c++) {
        cbx_affine a;
        cbx_box b;
        double m[2][3], cc[2], hh[2];
        xu_gen_case(&r, &a, &b);
        for (i = 0; i < 2; i++) {
            m[i][0] = a.m[i][0];
            m[i][1] = a.m[i][1];
            m[i][2] = a.m[i][3];
            cc[i] = b.lo[i];
            hh[i] = xu_round_fmt(b.hi[i] - b.lo[i]);
        }
        snprintf(what, sizeof what, "random cbox case %ld", c);
        run_cbox(&t, f32, (const double(*)[3])m, cc, hh, what);
    }
    printf("test_plane: %s: %ld cases, %ld finite axes with their 4 corners in mpq, %ld checks, "
           "%ld failed; statuses OK %ld, EMPTY %ld, EINVAL %ld, ERANGE %ld\n",
           f32 ? "cbx_transform_cbox2f" : "cbx_transform_cbox2", t.cases, t.axes, t.checks, t.failed,
           t.status[0], t.status[1], t.status[2], t.status[3]);
    *passed += t.cases - t.failed;
    return t.failed;
}

/* ---- the conversions ---------------------------------------------------- */

/* In mpq: [P0, P1] holds [X0, X1] and each end is within the proven gap
 * 16 u (|a| + |b|) + 2^-1066 of it (binary32: u = 2^-24, 2^-141); a, b
 * the axis' two inputs. */
static int conv_within(const mpq_t P0, const mpq_t P1, const mpq_t X0, const mpq_t X1, double a,
                       double b, int f32)
{
    mpq_t G, q;
    int ok;
    mpq_inits(G, q, NULL);
    mpq_set_d(G, fabs(a));
    mpq_set_d(q, fabs(b));
    mpq_add(G, G, q);
    mpq_set_d(q, ldexp(16.0, f32 ? -24 : -53));
    mpq_mul(G, G, q);
    mpq_set_d(q, ldexp(1.0, f32 ? -141 : -1066));
    mpq_add(G, G, q);
    ok = mpq_cmp(P0, X0) <= 0 && mpq_cmp(X1, P1) <= 0;
    mpq_sub(q, X0, P0);
    ok = ok && mpq_cmp(q, G) <= 0;
    mpq_sub(q, P1, X1);
    ok = ok && mpq_cmp(q, G) <= 0;
    mpq_clears(G, q, NULL);
    return ok;
}

static int conv_dom_ok(double x, double y, int f32)
{
    double r = f32 ? 0x1p123 : 0x1p1019;
    return fabs(x) <= r && fabs(y) <= r;
}

/* box -> cbox (dir 0) or cbox -> box (dir 1) of one input (u, v) = (lo, hi)
 * or (c, h) per axis, in the current format. */
static void run_conv(ctally *t, int f32, int dir, const double u[2], const double v[2], const char *what)
{
    const char *fam = dir ? (f32 ? "cbx_cbox2_to_box2f" : "cbx_cbox2_to_box2")
                          : (f32 ? "cbx_box2_to_cbox2f" : "cbx_box2_to_cbox2");
    double p[2], q[2], rp[2], rq[2];
    cbx_status got, ref, want;
    int i, nan = 0, empty = 0, dom = 1;
    char why[160];
    why[0] = 0;
    for (i = 0; i < 2; i++) {
        nan |= xu_is_nan(u[i]) || xu_is_nan(v[i]);
        empty |= dir ? v[i] < 0 : (v[i] < u[i] || is_pinf(u[i]) || is_ninf(v[i]));
        dom &= conv_dom_ok(u[i], v[i], f32);
    }
    want = nan ? CBX_EINVAL : empty ? CBX_EMPTY : dom ? CBX_OK : CBX_ERANGE;
    if (f32) {
        cbx_box2f b;
        cbx_cbox2f c;
        cbx_boxf b3;
        cbx_cboxf c3;
        for (i = 0; i < 3; i++) { b3.lo[i] = b3.hi[i] = 0; c3.c[i] = c3.h[i] = 0; }
        for (i = 0; i < 2; i++) {
            b.lo[i] = b3.lo[i] = c.c[i] = c3.c[i] = (float)u[i];
            b.hi[i] = b3.hi[i] = c.h[i] = c3.h[i] = (float)v[i];
        }
        if (dir) {
            cbx_box2f o;
            got = cbx_cbox2_to_box2f(&c, &o);
            ref = cbx_cbox_to_boxf(&c3, &b3);
            for (i = 0; i < 2; i++) { p[i] = o.lo[i]; q[i] = o.hi[i]; rp[i] = b3.lo[i]; rq[i] = b3.hi[i]; }
        } else {
            cbx_cbox2f o;
            got = cbx_box2_to_cbox2f(&b, &o);
            ref = cbx_box_to_cboxf(&b3, &c3);
            for (i = 0; i < 2; i++) { p[i] = o.c[i]; q[i] = o.h[i]; rp[i] = c3.c[i]; rq[i] = c3.h[i]; }
        }
    } else {
        cbx_box2 b;
        cbx_cbox2 c;
        cbx_box b3;
        cbx_cbox c3;
        for (i = 0; i < 3; i++) { b3.lo[i] = b3.hi[i] = 0; c3.c[i] = c3.h[i] = 0; }
        for (i = 0; i < 2; i++) {
            b.lo[i] = b3.lo[i] = c.c[i] = c3.c[i] = u[i];
            b.hi[i] = b3.hi[i] = c.h[i] = c3.h[i] = v[i];
        }
        if (dir) {
            cbx_box2 o;
            got = cbx_cbox2_to_box2(&c, &o);
            ref = cbx_cbox_to_box(&c3, &b3);
            for (i = 0; i < 2; i++) { p[i] = o.lo[i]; q[i] = o.hi[i]; rp[i] = b3.lo[i]; rq[i] = b3.hi[i]; }
        } else {
            cbx_cbox2 o;
            got = cbx_box2_to_cbox2(&b, &o);
            ref = cbx_box_to_cbox(&b3, &c3);
            for (i = 0; i < 2; i++) { p[i] = o.c[i]; q[i] = o.h[i]; rp[i] = c3.c[i]; rq[i] = c3.h[i]; }
        }
    }
    t->cases++;
    t->checks += 2;
    if (got != want)
        snprintf(why, sizeof why, "status %s, expected %s", cbx_status_name(got), cbx_status_name(want));
    else if (got != ref || memcmp(p, rp, sizeof p) || memcmp(q, rq, sizeof q))
        snprintf(why, sizeof why, "not the bits of the 3D conversion on the embedding");
    if (!why[0] && xu_status_index(got) >= 0) t->status[xu_status_index(got)]++;
    for (i = 0; i < 2 && !why[0]; i++) {
        int in = !nan && !empty && conv_dom_ok(u[i], v[i], f32) && isfinite(u[i]) && isfinite(v[i]);
        t->checks++;
        if (nan || empty) {
            int ok = dir ? (nan ? is_ninf(p[i]) && is_pinf(q[i]) : is_pinf(p[i]) && is_ninf(q[i]))
                         : (p[i] == 0 && (nan ? is_pinf(q[i]) : is_ninf(q[i])));
            if (!ok) snprintf(why, sizeof why, "axis %d: not the special output of %s", i, cbx_status_name(got));
            continue;
        }
        if (!in) {
            if (dir ? !(is_ninf(p[i]) && is_pinf(q[i])) : !(p[i] == 0 && is_pinf(q[i])))
                snprintf(why, sizeof why, "axis %d outside the domain but not the whole line", i);
            continue;
        }
        t->axes++;
        if (!isfinite(p[i]) || !isfinite(q[i])) {
            snprintf(why, sizeof why, "axis %d in the domain but not finite", i);
            continue;
        }
        {
            /* dir 1: [lo, hi] = [p, q] holds [c - h, c + h]; dir 0:
             * [c - h, c + h] (c = p, h = q) holds [lo, hi] = [u, v] */
            mpq_t P0, P1, X0, X1, h;
            int ok;
            mpq_inits(P0, P1, X0, X1, h, NULL);
            if (dir) {
                mpq_set_d(P0, p[i]);
                mpq_set_d(P1, q[i]);
                mpq_set_d(h, v[i]);
                mpq_set_d(X0, u[i]);
                mpq_sub(X0, X0, h);
                mpq_set_d(X1, u[i]);
                mpq_add(X1, X1, h);
            } else {
                mpq_set_d(h, q[i]);
                mpq_set_d(P0, p[i]);
                mpq_sub(P0, P0, h);
                mpq_set_d(P1, p[i]);
                mpq_add(P1, P1, h);
                mpq_set_d(X0, u[i]);
                mpq_set_d(X1, v[i]);
            }
            ok = conv_within(P0, P1, X0, X1, u[i], v[i], f32);
            mpq_clears(P0, P1, X0, X1, h, NULL);
            if (!ok) snprintf(why, sizeof why, "axis %d: the output does not hold the input within the proven gap", i);
        }
    }
    if (why[0]) {
        t->failed++;
        fail(fam, what, why);
    }
}

static long convs(int f32, long n, uint64_t seed, long *passed)
{
    ctally tb, tc;
    xu_rng r;
    long c;
    int i, k;
    char what[64];
    memset(&tb, 0, sizeof tb);
    memset(&tc, 0, sizeof tc);
    for (k = 0; k < N_HARD; k++) {
        double u[2], v[2], h[2];
        for (i = 0; i < 2; i++) {
            u[i] = xu_round_fmt(hard[k].lo[i]);
            v[i] = xu_round_fmt(hard[k].hi[i]);
            h[i] = xu_round_fmt(hard[k].hi[i] - hard[k].lo[i]);
        }
        run_conv(&tb, f32, 0, u, v, hard[k].name);
        run_conv(&tc, f32, 1, u, h, hard[k].name);
    }
    r.s = seed;
    for (c = 0; c < n; c++) {
        cbx_affine a;
        cbx_box b;
        double u[2], v[2], h[2];
        xu_gen_case(&r, &a, &b);
        for (i = 0; i < 2; i++) {
            u[i] = b.lo[i];
            v[i] = b.hi[i];
            h[i] = xu_round_fmt(fabs(b.hi[i] - b.lo[i]) * (xu_rng_int(&r, 0, 19) ? 1.0 : -1.0));
        }
        snprintf(what, sizeof what, "random conversion %ld", c);
        run_conv(&tb, f32, 0, u, v, what);
        run_conv(&tc, f32, 1, u, h, what);
    }
    printf("test_plane: %s: %ld cases, %ld in-domain axes held exactly within the proven gap, %ld checks, "
           "%ld failed; statuses OK %ld, EMPTY %ld, EINVAL %ld, ERANGE %ld\n",
           f32 ? "cbx_box2_to_cbox2f" : "cbx_box2_to_cbox2", tb.cases, tb.axes, tb.checks, tb.failed,
           tb.status[0], tb.status[1], tb.status[2], tb.status[3]);
    printf("test_plane: %s: %ld cases, %ld in-domain axes held exactly within the proven gap, %ld checks, "
           "%ld failed; statuses OK %ld, EMPTY %ld, EINVAL %ld, ERANGE %ld\n",
           f32 ? "cbx_cbox2_to_box2f" : "cbx_cbox2_to_box2", tc.cases, tc.axes, tc.checks, tc.failed,
           tc.status[0], tc.status[1], tc.status[2], tc.status[3]);
    *passed += tb.cases - tb.failed + tc.cases - tc.failed;
    return tb.failed + tc.failed;
}

/* ---- disks and ellipses ---------------------------------------------- */

typedef struct ballfmt {
    int f32;                    /* binary32 twin                          */
    double sb, rt, eb;          /* the domain's bounds (specs: sph_dom,
                                   ell_dom): 2^509, 2^1018, 2^254 (binary64) */
    unsigned long uexp, eexp;   /* u = 2^-uexp; the absolute term 2^-eexp */
} ballfmt;
static const ballfmt bf64 = { 0, 0x1p509, 0x1p1018, 0x1p254, 53, 1064 };
static const ballfmt bf32 = { 1, 0x1p61, 0x1p122, 0x1p30, 24, 139 };

#define SH_DISK 1200UL  /* m 2^sh and t 2^(sh - uexp) integers            */
#define SH_ELL2 2148UL  /* rot * radii 2^sh integers                      */

typedef struct balltally {
    long cases, failed, checks, axes;
    long status[4];
    double max_units;           /* largest end excess, units of u (|t| + sqrt s) + eta */
} balltally;


/* One in-domain axis: containment and the proven tightness of both ends,
 * exactly; 0 if both hold. */
static int ball2_axis(xu_exact *x, balltally *t, const ballfmt *F, const mpz_t s,
                      unsigned long sh, double c, double lo, double hi, char *why, size_t n)
{
    double m, r, sc, ex;
    long e;
    t->axes++;
    t->checks += 4;
    if (!isfinite(lo) || !isfinite(hi)) {
        snprintf(why, n, "in-domain axis not finite [%g, %g]", lo, hi);
        return 1;
    }
    if (!xu_sqrt_lo_ok(x, s, sh, c, lo) || !xu_sqrt_hi_ok(x, s, sh, c, hi)) {
        snprintf(why, n, "t -+ sqrt(s) not inside [%a, %a]", lo, hi);
        return 1;
    }
    if (!xu_sqrt_gap_ok(x, s, sh, c, lo, 80, F->uexp, F->eexp)
        || !xu_sqrt_gap_ok(x, s, sh, c, hi, 80, F->uexp, F->eexp)) {
        snprintf(why, n, "an end beyond the proven 80 u (|t| + sqrt s) + eta");
        return 1;
    }
    m = mpz_get_d_2exp(&e, s); /* statistics only: sqrt s' in double */
    r = mpz_sgn(s) ? ldexp(sqrt(m * ((e & 1) ? 2.0 : 1.0)), (int)((e - (e & 1)) / 2 - (long)sh)) : 0.0;
    sc = ldexp(1.0, -(int)F->uexp) * (fabs(c) + r) + ldexp(1.0, F->f32 ? -149 : -1074);
    ex = ((c - r) - lo) / sc;
    if (ex > t->max_units) t->max_units = ex;
    ex = (hi - (c + r)) / sc;
    if (ex > t->max_units) t->max_units = ex;
    return 0;
}

/* The statuses, special outputs and axes of a disk or an ellipse, given
 * each axis's s (valid where dom[i]). */
static int ball2_judge(xu_exact *x, balltally *t, const ballfmt *F, int nan, const int dom[2],
                       mpz_t s[2], unsigned long sh, const double c[2], cbx_status got,
                       const double lo[2], const double hi[2], char *why, size_t n)
{
    cbx_status want = nan ? CBX_EINVAL : (dom[0] && dom[1]) ? CBX_OK : CBX_ERANGE;
    int i;
    t->checks++;
    if (got != want) {
        snprintf(why, n, "status %s, expected %s", cbx_status_name(got), cbx_status_name(want));
        return 1;
    }
    if (xu_status_index(got) >= 0) t->status[xu_status_index(got)]++;
    for (i = 0; i < 2; i++) {
        if (nan || !dom[i]) {
            t->checks++;
            if (!is_ninf(lo[i]) || !is_pinf(hi[i])) {
                snprintf(why, n, "axis %d must be [-inf, +inf], is [%g, %g]", i, lo[i], hi[i]);
                return 1;
            }
            continue;
        }
        if (ball2_axis(x, t, F, s[i], sh, c[i], lo[i], hi[i], why, n)) return 1;
    }
    return 0;
}

/* A value for a disk or an ellipse: mostly moderate, some at the domain's
 * edges and beyond, zeros, subnormals, infinities and NaN. */
static double gen_ball_val(xu_rng *r, const ballfmt *F, double edge)
{
    int k = xu_rng_int(r, 0, 99);
    double v;
    if (k < 70) v = xu_gen_signed(r, -25, 25);
    else if (k < 78) v = xu_rng_sign(r) * edge * (xu_rng_int(r, 0, 1) ? 1.0 : 0.75);
    else if (k < 84) v = xu_rng_sign(r) * edge * 2.0;
    else if (k < 88) v = xu_rng_sign(r) * 0.0;
    else if (k < 92) v = xu_rng_sign(r) * ldexp(1.0, F->f32 ? -149 : -1074) * xu_rng_int(r, 1, 9);
    else if (k < 96) v = xu_gen_signed(r, -300, 300);
    else if (k < 98) v = xu_rng_sign(r) * HUGE_VAL;
    else v = NAN;
    return xu_round_fmt(v);
}

static void fail_ball(balltally *t, const char *fam, const char *what, const char *why)
{
    t->failed++;
    fail(fam, what, why);
}

/* One disk: m[i] = {m_i0, m_i1, t_i}. */
static void run_disk(xu_exact *x, balltally *t, const ballfmt *F, const double m[2][3], const char *what)
{
    const char *fam = F->f32 ? "cbx_disk_box2f" : "cbx_disk_box2";
    double lo[2], hi[2], c[2], rlo[3], rhi[3];
    int dom[2], nan = 0, i, j;
    cbx_status got, ref;
    char why[160];
    mpz_t s[2], z;
    t->cases++;
    for (i = 0; i < 2; i++)
        for (j = 0; j < 3; j++) nan |= xu_is_nan(m[i][j]);
    if (F->f32) {
        cbx_affine2f a, a0;
        cbx_box2f o;
        cbx_affinef a3;
        cbx_boxf r3;
        memset(&a3, 0, sizeof a3);
        for (i = 0; i < 2; i++) {
            for (j = 0; j < 3; j++) a.m[i][j] = (float)m[i][j];
            a3.m[i][0] = a.m[i][0]; a3.m[i][1] = a.m[i][1]; a3.m[i][3] = a.m[i][2];
        }
        a0 = a;
        memset(&o, 0xff, sizeof o);
        got = cbx_disk_box2f(&a, &o);
        ref = cbx_sphere_boxf(&a3, &r3);
        if (memcmp(&a, &a0, sizeof a)) { fail_ball(t, fam, what, "an input changed"); return; }
        for (i = 0; i < 2; i++) { lo[i] = o.lo[i]; hi[i] = o.hi[i]; rlo[i] = r3.lo[i]; rhi[i] = r3.hi[i]; }
    } else {
        cbx_affine2 a, a0;
        cbx_box2 o;
        cbx_affine a3;
        cbx_box r3;
        memset(&a3, 0, sizeof a3);
        for (i = 0; i < 2; i++) {
            for (j = 0; j < 3; j++) a.m[i][j] = m[i][j];
            a3.m[i][0] = a.m[i][0]; a3.m[i][1] = a.m[i][1]; a3.m[i][3] = a.m[i][2];
        }
        a0 = a;
        memset(&o, 0xff, sizeof o);
        got = cbx_disk_box2(&a, &o);
        ref = cbx_sphere_box(&a3, &r3);
        if (memcmp(&a, &a0, sizeof a)) { fail_ball(t, fam, what, "an input changed"); return; }
        for (i = 0; i < 2; i++) { lo[i] = o.lo[i]; hi[i] = o.hi[i]; rlo[i] = r3.lo[i]; rhi[i] = r3.hi[i]; }
    }
    t->checks++;
    if (got != ref || memcmp(lo, rlo, sizeof lo) || memcmp(hi, rhi, sizeof hi)) {
        fail_ball(t, fam, what, "not the bits of the sphere's box on the 3D embedding");
        return;
    }
    mpz_init(s[0]); mpz_init(s[1]); mpz_init(z);
    for (i = 0; i < 2; i++) {
        c[i] = m[i][2];
        dom[i] = !nan && isfinite(m[i][0]) && isfinite(m[i][1]) && isfinite(m[i][2])
                 && fabs(m[i][0]) <= F->sb && fabs(m[i][1]) <= F->sb && fabs(m[i][2]) <= F->rt;
        if (!dom[i]) continue;
        for (j = 0; j < 2; j++) {
            xu_scaled_sh(z, m[i][j], SH_DISK);
            mpz_addmul(s[i], z, z);
        }
    }
    if (ball2_judge(x, t, F, nan, dom, s, SH_DISK, c, got, lo, hi, why, sizeof why))
        fail_ball(t, fam, what, why);
    mpz_clear(s[0]); mpz_clear(s[1]); mpz_clear(z);
}

/* One ellipse: e[0] = center, e[1] = radii, e[2], e[3] = rot rows. */
static void run_ellipse(xu_exact *x, balltally *t, const ballfmt *F, const double e[4][2], const char *what)
{
    const char *fam = F->f32 ? "cbx_ellipse_box2f" : "cbx_ellipse_box2";
    double lo[2], hi[2], c[2], rlo[2], rhi[2];
    int dom[2], nan = 0, i, j;
    cbx_status got, ref;
    char why[160];
    mpz_t s[2], z, w;
    t->cases++;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 2; j++) nan |= xu_is_nan(e[i][j]);
    if (F->f32) {
        float cen[2], rad[2], rot[2][2], cen3[3] = { 0 }, rad3[3] = { 0 }, rot3[3][3] = { { 0 } };
        float k0[2], k1[2], k2[2][2];
        cbx_box2f o;
        cbx_boxf r3;
        for (j = 0; j < 2; j++) {
            cen3[j] = cen[j] = (float)e[0][j];
            rad3[j] = rad[j] = (float)e[1][j];
            rot3[0][j] = rot[0][j] = (float)e[2][j];
            rot3[1][j] = rot[1][j] = (float)e[3][j];
        }
        memcpy(k0, cen, sizeof k0); memcpy(k1, rad, sizeof k1); memcpy(k2, rot, sizeof k2);
        memset(&o, 0xff, sizeof o);
        got = cbx_ellipse_box2f(cen, rad, (const float(*)[2])rot, &o);
        ref = cbx_ellipsoid_boxf(cen3, rad3, (const float(*)[3])rot3, &r3);
        if (memcmp(k0, cen, sizeof k0) || memcmp(k1, rad, sizeof k1) || memcmp(k2, rot, sizeof k2)) {
            fail_ball(t, fam, what, "an input changed");
            return;
        }
        for (i = 0; i < 2; i++) { lo[i] = o.lo[i]; hi[i] = o.hi[i]; rlo[i] = r3.lo[i]; rhi[i] = r3.hi[i]; }
    } else {
        double cen[2], rad[2], rot[2][2], cen3[3] = { 0 }, rad3[3] = { 0 }, rot3[3][3] = { { 0 } };
        double k0[2], k1[2], k2[2][2];
        cbx_box2 o;
        cbx_box r3;
        for (j = 0; j < 2; j++) {
            cen3[j] = cen[j] = e[0][j];
            rad3[j] = rad[j] = e[1][j];
            rot3[0][j] = rot[0][j] = e[2][j];
            rot3[1][j] = rot[1][j] = e[3][j];
        }
        memcpy(k0, cen, sizeof k0); memcpy(k1, rad, sizeof k1); memcpy(k2, rot, sizeof k2);
        memset(&o, 0xff, sizeof o);
        got = cbx_ellipse_box2(cen, rad, (const double(*)[2])rot, &o);
        ref = cbx_ellipsoid_box(cen3, rad3, (const double(*)[3])rot3, &r3);
        if (memcmp(k0, cen, sizeof k0) || memcmp(k1, rad, sizeof k1) || memcmp(k2, rot, sizeof k2)) {
            fail_ball(t, fam, what, "an input changed");
            return;
        }
        for (i = 0; i < 2; i++) { lo[i] = o.lo[i]; hi[i] = o.hi[i]; rlo[i] = r3.lo[i]; rhi[i] = r3.hi[i]; }
    }
    t->checks++;
    if (got != ref || memcmp(lo, rlo, sizeof lo) || memcmp(hi, rhi, sizeof hi)) {
        fail_ball(t, fam, what, "not the bits of the ellipsoid's box on the 3D embedding");
        return;
    }
    mpz_init(s[0]); mpz_init(s[1]); mpz_init(z); mpz_init(w);
    for (i = 0; i < 2; i++) {
        const double *rot_i = e[2 + i];
        c[i] = e[0][i];
        dom[i] = !nan && isfinite(c[i]) && fabs(c[i]) <= F->rt;
        for (j = 0; j < 2; j++)
            dom[i] = dom[i] && isfinite(rot_i[j]) && isfinite(e[1][j])
                     && fabs(rot_i[j]) <= F->eb && fabs(e[1][j]) <= F->eb;
        if (!dom[i]) continue;
        for (j = 0; j < 2; j++) {
            xu_scaled_sh(z, rot_i[j], 1074);
            xu_scaled_sh(w, e[1][j], 1074);
            mpz_mul(z, z, w);           /* rot_ij radii_j 2^2148, exactly */
            mpz_addmul(s[i], z, z);
        }
    }
    if (ball2_judge(x, t, F, nan, dom, s, SH_ELL2, c, got, lo, hi, why, sizeof why))
        fail_ball(t, fam, what, why);
    mpz_clear(s[0]); mpz_clear(s[1]); mpz_clear(z); mpz_clear(w);
}

static const double disk_hard[][2][3] = {
    { { 1, 0, 0 }, { 0, 1, 0 } },                   /* the unit disk          */
    { { 3, 4, 0.1 }, { -5, 12, -7 } },              /* exact norms 5 and 13   */
    { { 0, 0, 1 }, { -0.0, 0, -1 } },               /* a point (zero rows)    */
    { { 0x1p509, -0x1p509, 0x1p1018 }, { 1, 1, -0x1p1018 } }, /* the domain's edges */
    { { 0x1p510, 0, 0 }, { 1, 0, 0 } },             /* just outside           */
    { { 0x1p-1074, 0x1p-1074, 0 }, { 0x1p-600, 0x1p-601, 1e-300 } }, /* tiny rows */
    { { HUGE_VAL, 0, 0 }, { 1, 1, 1 } },
    { { 1, 0, NAN }, { 1, 1, 1 } },
};
static const double ell_hard[][4][2] = {
    { { 0, 0 }, { 1, 1 }, { 1, 0 }, { 0, 1 } },                 /* unit circle   */
    { { 5, -5 }, { 3, 0.5 }, { 0.6, -0.8 }, { 0.8, 0.6 } },     /* rotated       */
    { { 0, 0 }, { -2, 0 }, { 1, 0 }, { 0, 1 } },                /* negative, zero radii */
    { { 0x1p1018, 0 }, { 0x1p254, 0x1p254 }, { 0x1p254, -0x1p254 }, { 1, 1 } }, /* edges */
    { { 0, 0 }, { 0x1p255, 1 }, { 1, 0 }, { 0, 1 } },           /* radius outside */
    { { 0, 0 }, { 1, 1 }, { NAN, 0 }, { 0, 1 } },
    { { -HUGE_VAL, 0 }, { 1, 1 }, { 1, 0 }, { 0, 1 } },
};

static long balls(xu_exact *x, const ballfmt *F, long n, uint64_t seed, long *passed)
{
    balltally td, te;
    xu_rng r;
    long c;
    int k, i, j;
    char what[64];
    memset(&td, 0, sizeof td);
    memset(&te, 0, sizeof te);
    for (k = 0; k < (int)(sizeof disk_hard / sizeof disk_hard[0]); k++) {
        double m[2][3];
        for (i = 0; i < 2; i++)
            for (j = 0; j < 3; j++) m[i][j] = xu_round_fmt(disk_hard[k][i][j]);
        snprintf(what, sizeof what, "hard disk %d", k);
        run_disk(x, &td, F, (const double(*)[3])m, what);
    }
    for (k = 0; k < (int)(sizeof ell_hard / sizeof ell_hard[0]); k++) {
        double e[4][2];
        for (i = 0; i < 4; i++)
            for (j = 0; j < 2; j++) e[i][j] = xu_round_fmt(ell_hard[k][i][j]);
        snprintf(what, sizeof what, "hard ellipse %d", k);
        run_ellipse(x, &te, F, (const double(*)[2])e, what);
    }
    r.s = seed;
    for (c = 0; c < n; c++) {
        double m[2][3], e[4][2];
        for (i = 0; i < 2; i++) {
            m[i][0] = gen_ball_val(&r, F, F->sb);
            m[i][1] = gen_ball_val(&r, F, F->sb);
            m[i][2] = gen_ball_val(&r, F, F->rt);
        }
        snprintf(what, sizeof what, "random disk %ld", c);
        run_disk(x, &td, F, (const double(*)[3])m, what);
        for (i = 0; i < 4; i++)
            for (j = 0; j < 2; j++) e[i][j] = gen_ball_val(&r, F, i == 0 ? F->rt : F->eb);
        snprintf(what, sizeof what, "random ellipse %ld", c);
        run_ellipse(x, &te, F, (const double(*)[2])e, what);
    }
    printf("test_plane: %s: %ld cases, %ld in-domain axes, %ld checks, %ld failed; statuses OK %ld, "
           "EINVAL %ld, ERANGE %ld; largest end excess %.2f units of u (|t| + sqrt s) + eta (proven: 80)\n",
           F->f32 ? "cbx_disk_box2f" : "cbx_disk_box2", td.cases, td.axes, td.checks, td.failed,
           td.status[0], td.status[2], td.status[3], td.max_units);
    printf("test_plane: %s: %ld cases, %ld in-domain axes, %ld checks, %ld failed; statuses OK %ld, "
           "EINVAL %ld, ERANGE %ld; largest end excess %.2f units of u (|t| + sqrt s) + eta (proven: 80)\n",
           F->f32 ? "cbx_ellipse_box2f" : "cbx_ellipse_box2", te.cases, te.axes, te.checks, te.failed,
           te.status[0], te.status[2], te.status[3], te.max_units);
    *passed += td.cases - td.failed + te.cases - te.failed;
    return td.failed + te.failed;
}

int main(int argc, char **argv)
{
    long n = (long)xu_arg_num(argc, argv, 1, 200000, "test_plane [N] [seed]");
    uint64_t seed = xu_arg_num(argc, argv, 2, 7, "test_plane [N] [seed]");
    xu_exact x;
    long failed = 0, passed = 0;
    xu_init(&x);
    printf("test_plane: the 2D family (boxes in both forms, conversions, disks, ellipses; both formats) against exact "
           "rationals, N = %ld, seed = %llu\n", n,
           (unsigned long long)seed);
    xu_set_format(&xu_binary64);
    failed += family(&x, "cbx_transform_box2 (binary64)", run64, n, seed, &passed);
    xu_set_format(&xu_binary32);
    failed += family(&x, "cbx_transform_box2f (binary32)", run32, n, seed + 1, &passed);
    xu_set_format(&xu_binary64);
    failed += cboxes(0, n / 2, seed + 4, &passed);
    xu_set_format(&xu_binary32);
    failed += cboxes(1, n / 2, seed + 5, &passed);
    xu_set_format(&xu_binary64);
    failed += convs(0, n / 2, seed + 6, &passed);
    xu_set_format(&xu_binary32);
    failed += convs(1, n / 2, seed + 7, &passed);
    xu_set_format(&xu_binary64);
    failed += balls(&x, &bf64, n / 2, seed + 2, &passed);
    xu_set_format(&xu_binary32);
    failed += balls(&x, &bf32, n / 2, seed + 3, &passed);
    xu_clear(&x);
    printf("%ld passed, %ld failed\n", passed, failed);
    return failed ? 1 : 0;
}
