/*
 * test_float [N] [seed]: the binary32 (float) family against exact rational
 * arithmetic.  The oracle is exact_util in its binary32 format
 * (xu_set_format(&xu_binary32): u = 2^-24, eta = 2^-149, domain bound
 * 2^122, classes (2^k, 2^(122-k)), proven tightness 12 u S + 2^-140): the
 * same code that checks the binary64 family in test_exact, so both
 * families are held to the same rules.  Every float is held exactly in a
 * double for the oracle; every generated value is checked to be a float.
 *
 *  1. cbx_transform_boxf: a table of binary32 hard cases (class corners,
 *     2^122, FLT_MAX, subnormals, half-spaces, cancellation), then N random
 *     cases drawn by xu_gen_case (the generator of test_exact, binary32
 *     values): status, every field written, EINVAL/EMPTY outputs, each
 *     end's kind (full row, vertex, unbounded, lost, whole line), exact
 *     containment, the proven bound 12 u S + 2^-140 (exactly), the 8 corners
 *     with mpq on every 50th case, inputs unchanged, and the in-place call
 *     (out == in) bit for bit.
 *  2. cbx_transform_boxesf: N/100 batches (sizes 0, 1, 2, 7, 100) under one
 *     map, every out[k] bit for bit against the single call, the most
 *     severe status, nothing written past out[n-1].
 *  2b. Prepared maps: N/100 + 20 batches (sizes 0, 1, 2, 7, 100; maps of
 *     xu_gen_case, a quarter with entries at the fast range's edge 2^61,
 *     2^122 or the next float), and every row of the special-value table
 *     (6) as a batch of one box.  cbx_preparef into a struct of garbage:
 *     the map copied bit for bit, the fast flag set iff every linear entry
 *     is at most 2^61 and every translation at most 2^122 in magnitude.
 *     The structs: cbx_preparef's; zero-initialised (= { 0 }) with the map
 *     set by hand; cls forged (a value of xu_cls_values, fast kept or
 *     cleared); fast and cls forged (fast = 1 whatever the map).
 *     cbx_transform_box_prepf (not on the fast-forged struct: it trusts the
 *     flag) bit for bit and status against cbx_transform_boxf, and in
 *     place; cbx_transform_boxes_prepf bit for bit and status against
 *     cbx_transform_boxesf, nothing written past out[n-1], *p unchanged;
 *     the boxes of the forged structs against the exact oracle.
 *  3. cbx_transform_cboxf: N/2 random cases (zero columns against infinite
 *     or huge centers and half-widths included): status and each axis's
 *     kind (full, dropped, lost), exact containment of [c-h, c+h] of the
 *     image of the input box, the proven bound 12 u S + 2^-140, in place.
 *  4. cbx_box_to_cboxf, cbx_cbox_to_boxf: N/2 cases each: status, kinds,
 *     exact containment of the input's real box.
 *  5. cbx_sphere_boxf, cbx_ellipsoid_boxf: N/2 cases each: status, kinds,
 *     exact containment of t -+ sqrt(sum m_ij^2) (equivalent to containing
 *     every point of the ball), the ellipsoid's rows as exact products, and
 *     the proven tightness 80 u (|t| + sqrt s) + 2^-139 of each end, exactly.
 *  6. A special-value table: every function x every input position x 32
 *     binary32 values (NaN, +-inf, +-0, subnormals, FLT_MAX, the domain
 *     limits 2^30, 2^61, 2^122, 2^123 and the next float beyond each) on an
 *     ordinary base input, through the same checks.
 * Tightness is measured in units of u S + eta (u = 2^-24, eta = 2^-149).
 * The last line is "N passed, M failed" (read by CI).
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "certbox.h"
#include "exact_util.h"

#define MAX_LOGS 20

/* ---- one counter per function ------------------------------------------ */

typedef struct fstat {
    const char *name;
    long cases, failed, checks;
    long axes;                  /* finite, proven axes/ends measured      */
    double max_ex, sum_ex;      /* excess, units of u S + eta             */
} fstat;

static long logs;

static void fs_fail(fstat *s, const char *what, const char *why)
{
    if (logs++ < MAX_LOGS) printf("  FAIL %s: %s: %s\n", s->name, what, why);
}

static void fs_excess(fstat *s, double e)
{
    s->axes++;
    s->sum_ex += e;
    if (e > s->max_ex) s->max_ex = e;
}

static void fs_print(const fstat *s)
{
    printf("  %-25s %8ld cases, %9ld exact checks, %ld failed", s->name, s->cases, s->checks,
           s->failed);
    if (s->axes)
        printf("; excess over %ld ends: max %.2f mean %.2f", s->axes, s->max_ex,
               s->sum_ex / (double)s->axes);
    printf("\n");
}

/* ---- float <-> double (exact both ways on float values) --------------- */

static long not_float; /* generated values that are not floats (a bug here) */

static float F(double d)
{
    volatile float f = (float)d; /* see xu_round_fmt */
    if (!((double)f == d) && !(d != d)) not_float++;
    return f;
}

static void to_af(const cbx_affine *d, cbx_affinef *f)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) f->m[i][j] = F(d->m[i][j]);
}

static void to_bf(const cbx_box *d, cbx_boxf *f)
{
    int j;
    for (j = 0; j < 3; j++) { f->lo[j] = F(d->lo[j]); f->hi[j] = F(d->hi[j]); }
}

static void to_cf(const cbx_cbox *d, cbx_cboxf *f)
{
    int j;
    for (j = 0; j < 3; j++) { f->c[j] = F(d->c[j]); f->h[j] = F(d->h[j]); }
}

static void from_af(const cbx_affinef *f, cbx_affine *d)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) d->m[i][j] = f->m[i][j];
}

static void from_bf(const cbx_boxf *f, cbx_box *d)
{
    int j;
    for (j = 0; j < 3; j++) { d->lo[j] = f->lo[j]; d->hi[j] = f->hi[j]; }
}

static void from_cf(const cbx_cboxf *f, cbx_cbox *d)
{
    int j;
    for (j = 0; j < 3; j++) { d->c[j] = f->c[j]; d->h[j] = f->h[j]; }
}

static void nan_bf(cbx_boxf *o)
{
    int j;
    for (j = 0; j < 3; j++) o->lo[j] = o->hi[j] = NAN;
}

static void nan_cf(cbx_cboxf *o)
{
    int j;
    for (j = 0; j < 3; j++) o->c[j] = o->h[j] = NAN;
}

static int is_pinf(double d) { return d > 0 && isinf(d); }
static int is_ninf(double d) { return d < 0 && isinf(d); }

/* ---- 1. cbx_transform_boxf -------------------------------------------- */

static fstat st_box = { "cbx_transform_boxf", 0, 0, 0, 0, 0, 0 };
static fstat st_inpl = { "  in place (out == in)", 0, 0, 0, 0, 0, 0 };

/* The whole check of one case; returns 1 on failure. */
static int run_box(xu_exact *x, xu_stats *all, const cbx_affine *ad, const cbx_box *bd,
                   int corners, const char *what)
{
    cbx_affinef a, a0;
    cbx_boxf b, b0, o, ip;
    cbx_affine af;
    cbx_box od, bf;
    cbx_status s, s2;
    xu_verdict v;
    int k, bad;
    to_af(ad, &a);
    to_bf(bd, &b);
    a0 = a;
    b0 = b;
    from_af(&a, &af);  /* the oracle judges the floats the library got */
    from_bf(&b, &bf);
    ad = &af;
    bd = &bf;
    nan_bf(&o);
    s = cbx_transform_boxf(&a, &b, &o);
    from_bf(&o, &od);
    xu_check_result(x, ad, bd, &od, s, corners, &v);
    for (k = 0; k < XU_NFLAGS; k++) st_box.checks += v.applied[k];
    st_box.checks++;
    if (memcmp(&a, &a0, sizeof a) || memcmp(&b, &b0, sizeof b)) {
        v.failed = 1;
        snprintf(v.why, sizeof v.why, "an input changed");
    }
    st_box.cases++;
    bad = v.failed;
    if (bad) {
        st_box.failed++;
        fs_fail(&st_box, what, v.why);
    }
    for (k = 0; k < 3; k++) {
        if (v.ax[k].checked && !v.ax[k].tiny) {
            fs_excess(&st_box, v.ax[k].ex_lo);
            fs_excess(&st_box, v.ax[k].ex_hi);
        }
    }
    xu_stats_add(all, &v, ad, bd);
    /* in place: the same bits */
    ip = b;
    s2 = cbx_transform_boxf(&a, &ip, &ip);
    st_inpl.cases++;
    st_inpl.checks++;
    if (s2 != s || memcmp(&ip, &o, sizeof o)) {
        st_inpl.failed++;
        fs_fail(&st_inpl, what, "differs from the separate output");
        bad = 1;
    }
    return bad;
}

#define ROW(a, b, c, t) { a, b, c, t }
#define MAT(r0, r1, r2) { { r0, r1, r2 } }
#define BOX(l0, h0, l1, h1, l2, h2) { { l0, l1, l2 }, { h0, h1, h2 } }
#define INF HUGE_VAL
#define P61U 0x1.000002p61   /* the next float above 2^61  */
#define P122U 0x1.000002p122 /* the next float above 2^122 */

typedef struct box_case { const char *name; cbx_affine a; cbx_box in; } box_case;

/* binary32 hard cases; the expected outcome of each is computed by the
 * oracle from the rules, and the comment says what it is. */
static const box_case box_hard[] = {
    { "identity, unit cube (exact box)",
      MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0)), BOX(0, 1, 0, 1, 0, 1) },
    { "rotation 0.6/0.8 about z",
      MAT(ROW(0.6f, -0.8f, 0, 1), ROW(0.8f, 0.6f, 0, 2), ROW(0, 0, 1, 3)),
      BOX(-1, 1, -1, 1, -1, 1) },
    { "2^-149 everywhere (products 2^-298)",
      MAT(ROW(0x1p-149, -0x1p-149, 0x1p-149, 0x1p-149), ROW(-0x1p-149, 0x1p-149, 0, 0),
          ROW(0, 0, 0x1p-149, -0x1p-149)),
      BOX(-0x1p-149, 0x1p-149, 0x1p-149, 0x1p-149, 0, 0x1p-149) },
    { "FLT_MIN entries and coords",
      MAT(ROW(0x1p-126, 0x1p-126, 0x1p-126, 0x1p-126), ROW(1, 0, 0, 0), ROW(0, 1, 1, 0)),
      BOX(-0x1p-126, 0x1p-126, 0x1p-126, 0x1p-126, -0x1p-126, 0) },
    { "class 61 corner: m = 2^61, coords 2^61",
      MAT(ROW(0x1p61, 0x1p61, 0x1p61, 0x1p122), ROW(-0x1p61, 0, 0, 0), ROW(0, 0, 1, 0)),
      BOX(-0x1p61, 0x1p61, -0x1p61, 0x1p61, -0x1p61, 0x1p61) },
    { "class 122: m = 2^122 with |c| <= 1",
      MAT(ROW(0x1p122, 0, 0, 0), ROW(0, -0x1p122, 0, 0x1p122), ROW(0, 0, 1, 0)),
      BOX(-1, 1, 0.5f, 1, -2, 2) },
    { "class 0: m = 1 with coords 2^122; sums reach 2^124",
      MAT(ROW(1, 1, 1, 0x1p122), ROW(1, -1, 0, 0), ROW(0, 0, -1, -0x1p122)),
      BOX(-0x1p122, 0x1p122, -0x1p122, 0x1p122, 0x1p121, 0x1p122) },
    { "m = 2^61 + ulp (row 0 lost: no class holds it)",
      MAT(ROW(P61U, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0)),
      BOX(-0x1p61, 0x1p61, -1, 1, -1, 1) },
    { "t = 2^122 + ulp (row 1 lost)",
      MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, P122U), ROW(0, 0, 1, 0)), BOX(-1, 1, -1, 1, -1, 1) },
    { "t = FLT_MAX (row 2 lost)",
      MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, FLT_MAX)), BOX(-1, 1, -1, 1, -1, 1) },
    { "FLT_MAX coordinate with a zero coefficient (vertex rule)",
      MAT(ROW(0, 1, 0, 0), ROW(1, 0, 0, 0), ROW(0, 0, 1, 0)), BOX(-1, FLT_MAX, -1, 1, -1, 1) },
    { "cancellation: t = -(m.c) at a corner",
      MAT(ROW(0.1f, 0.2f, 0.3f, -0.6f), ROW(3, -7, 0.5f, 2), ROW(1e-3f, 1e3f, -1, 0)),
      BOX(1, 1, 1, 1, 1, 1) },
    { "half-spaces: lo = -inf and hi = +inf ends",
      MAT(ROW(1, 0, 0, 0), ROW(0, -1, 0, 0), ROW(0, 0, 0, 5)), BOX(-INF, 1, 2, INF, -INF, INF) },
    { "whole space in, zero map",
      MAT(ROW(0, 0, 0, 1), ROW(0, -0.0f, 0, 2), ROW(0, 0, 0, -0x1p122)),
      BOX(-INF, INF, -INF, INF, -INF, INF) },
    { "infinite map entry (row 0 whole line)",
      MAT(ROW(INF, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0)), BOX(-1, 1, -1, 1, -1, 1) },
    { "NaN in the map",
      MAT(ROW(1, 0, 0, 0), ROW(0, NAN, 0, 0), ROW(0, 0, 1, 0)), BOX(-1, 1, -1, 1, -1, 1) },
    { "empty: hi < lo on axis 2",
      MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0)), BOX(-1, 1, -1, 1, 1, -1) },
    { "empty: lo = +inf",
      MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0)), BOX(INF, INF, -1, 1, -1, 1) },
    { "signed zeros: box [+0, -0] is not empty",
      MAT(ROW(-0.0f, 1, 0, -0.0f), ROW(1, -0.0f, 0, 0), ROW(0, 0, -1, 0)),
      BOX(0.0f, -0.0f, -0.0f, 0.0f, -1, 1) },
    { "decimal rotation 1e-3 rad, box up to 1e18",
      MAT(ROW(0.9999995f, -0.001f, 0, 1e18f), ROW(0.001f, 0.9999995f, 0, -1e18f),
          ROW(0, 0, 1, 0)), BOX(-1e18f, 1e18f, 3e17f, 1e18f, -1, 1) },
};
#define N_BOX_HARD ((int)(sizeof box_hard / sizeof box_hard[0]))

/* ---- 2. cbx_transform_boxesf ------------------------------------------ */

static fstat st_batch = { "cbx_transform_boxesf", 0, 0, 0, 0, 0, 0 };

static int sev(cbx_status s)
{
    return s == CBX_EINVAL ? 3 : s == CBX_ERANGE ? 2 : s == CBX_EMPTY ? 1 : 0;
}

static void run_batch(xu_rng *r, int n)
{
    cbx_affine ad, ignore;
    cbx_box bd;
    cbx_affinef a;
    cbx_boxf in[102], out[102], one;
    cbx_status s, worst = CBX_OK;
    int k, bad = 0;
    xu_gen_case(r, &ad, &bd);
    to_af(&ad, &a);
    for (k = 0; k < n; k++) {
        xu_gen_case(r, &ignore, &bd);
        to_bf(&bd, &in[k]);
    }
    for (k = 0; k < n + 2; k++) memset(&out[k], 0x5a, sizeof out[k]); /* guards */
    s = cbx_transform_boxesf(&a, in, out, (size_t)n);
    for (k = 0; k < n; k++) {
        cbx_status sk = cbx_transform_boxf(&a, &in[k], &one);
        if (sev(sk) > sev(worst)) worst = sk;
        st_batch.checks++;
        if (memcmp(&one, &out[k], sizeof one)) bad = 1;
    }
    for (k = n; k < n + 2; k++) {
        unsigned char g[sizeof out[0]];
        memset(g, 0x5a, sizeof g);
        st_batch.checks++;
        if (memcmp(g, &out[k], sizeof g)) bad = 1;
    }
    st_batch.checks++;
    if (s != worst) bad = 1;
    st_batch.cases++;
    if (bad) {
        st_batch.failed++;
        fs_fail(&st_batch, "batch", "differs from the single calls or wrote past out[n-1]");
    }
}

/* ---- 2b. prepared maps ------------------------------------------------ */

static fstat st_prep = { "cbx_preparef", 0, 0, 0, 0, 0, 0 };
static fstat st_prep1 = { "cbx_transform_box_prepf", 0, 0, 0, 0, 0, 0 };
static fstat st_prepn = { "cbx_transform_boxes_prepf", 0, 0, 0, 0, 0, 0 };
static long prep_fast, prep_exact;

/* the structs handed over: cbx_preparef's, zero-initialised, cls forged,
 * fast and cls forged */
enum { PV_PREP, PV_ZERO, PV_CLS, PV_FORGED, NPV };
static const char *const pv_name[NPV] = { "cbx_preparef", "zero-init", "cls forged",
                                          "fast+cls forged" };

/* The binary32 fast range: |m| <= 2^61, |t| <= 2^122 (false on NaN). */
static int map_fast_f(const cbx_affinef *a)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++)
            if (!(fabs((double)a->m[i][j]) <= (j < 3 ? 0x1p61 : 0x1p122))) return 0;
    return 1;
}

/* One struct *p (kind v) on the boxes in[0 .. n-1]: a failed box_prepf
 * call counts in st_prep1, a failed boxes_prepf call (bits, status,
 * guards, *p, or a box against the exact oracle) in st_prepn. */
static void prep_variant(xu_exact *x, const cbx_preparedf *p, int v, const cbx_boxf *in, int n,
                        const char *what)
{
    cbx_preparedf p0 = *p;
    cbx_boxf out[102], ref[102];
    cbx_status s, sr, sk[100];
    char why[400], nb[16];
    const char *cls = xu_cls_str(p->cls, nb);
    int k, j, nbad = 0; /* the boxes_prepf call failed */

    for (k = 0; k < n; k++) { /* the single calls: the reference statuses */
        cbx_boxf o;
        sk[k] = cbx_transform_boxf(&p->a, &in[k], &o);
    }
    if (v != PV_FORGED)
        for (k = 0; k < n; k++) {
            cbx_boxf o, r, ip;
            memset(&o, 0x3c, sizeof o);
            nan_bf(&r);
            s = cbx_transform_box_prepf(p, &in[k], &o);
            sr = cbx_transform_boxf(&p->a, &in[k], &r);
            ip = in[k];
            st_prep1.cases++;
            st_prep1.checks += 2;
            if (s != sr || memcmp(&o, &r, sizeof o)) {
                snprintf(why, sizeof why, "box %d, %s (fast %d, cls %s): status %s, "
                         "cbx_transform_boxf %s, boxes %s", k, pv_name[v], p->fast, cls,
                         cbx_status_name(s), cbx_status_name(sr),
                         memcmp(&o, &r, sizeof o) ? "differ" : "equal");
                fs_fail(&st_prep1, what, why);
                st_prep1.failed++;
            } else if (cbx_transform_box_prepf(p, &ip, &ip) != s || memcmp(&ip, &o, sizeof o)) {
                snprintf(why, sizeof why, "box %d, %s: the in-place call differs", k, pv_name[v]);
                fs_fail(&st_prep1, what, why);
                st_prep1.failed++;
            }
        }

    for (k = 0; k < n + 2; k++) memset(&out[k], 0x5a, sizeof out[k]); /* guards */
    for (k = 0; k < n; k++) nan_bf(&ref[k]);
    s = cbx_transform_boxes_prepf(p, in, out, (size_t)n);
    sr = cbx_transform_boxesf(&p->a, in, ref, (size_t)n);
    st_prepn.cases++;
    st_prepn.checks += 4;
    {
        unsigned char g[2 * sizeof out[0]];
        memset(g, 0x5a, sizeof g);
        if (s != sr || (n && memcmp(out, ref, (size_t)n * sizeof out[0]))
            || memcmp(g, &out[n], sizeof g) || memcmp(&p0, p, sizeof p0)) {
            snprintf(why, sizeof why, "n = %d, %s (fast %d, cls %s): status %s, "
                     "cbx_transform_boxesf %s; boxes %s, guards %s, *p %s", n, pv_name[v],
                     p0.fast, cls, cbx_status_name(s), cbx_status_name(sr),
                     n && memcmp(out, ref, (size_t)n * sizeof out[0]) ? "differ" : "equal",
                     memcmp(g, &out[n], sizeof g) ? "WRITTEN" : "intact",
                     memcmp(&p0, p, sizeof p0) ? "CHANGED" : "unchanged");
            fs_fail(&st_prepn, what, why);
            nbad = 1;
        }
    }
    if (v == PV_CLS || v == PV_FORGED)
        for (k = 0; k < n; k++) {
            cbx_affine ad;
            cbx_box bd, od;
            xu_verdict vd;
            from_af(&p0.a, &ad);
            from_bf(&in[k], &bd);
            from_bf(&out[k], &od);
            prep_exact++;
            xu_check_result(x, &ad, &bd, &od, sk[k], 0, &vd);
            for (j = 0; j < XU_NFLAGS; j++) st_prepn.checks += vd.applied[j];
            if (vd.failed) {
                snprintf(why, sizeof why, "box %d of n = %d, %s (fast %d, cls %s): %s", k, n,
                         pv_name[v], p0.fast, cls, vd.why);
                fs_fail(&st_prepn, what, why);
                nbad = 1;
            }
        }
    if (nbad) st_prepn.failed++;
}

/* The map ad and the n boxes bd[] (n <= 100) in binary32: cbx_preparef,
 * then every struct of prep_variant, with nforge values of xu_cls_values
 * from index f0 on; the fast flag of the cls-forged struct is cleared for
 * odd id.  Failures are counted in st_prep, st_prep1 and st_prepn. */
static void run_prep(xu_exact *x, const cbx_affine *ad, const cbx_box *bd, int n, long id, int f0,
                    int nforge, const char *what)
{
    cbx_affinef a, a0;
    cbx_boxf in[100];
    cbx_preparedf p, q, z = { 0 };
    char why[160];
    int k, f;
    to_af(ad, &a);
    for (k = 0; k < n; k++) to_bf(&bd[k], &in[k]);
    a0 = a;
    memset(&p, 0xa5, sizeof p);
    cbx_preparef(&a, &p);
    st_prep.cases++;
    st_prep.checks += 3;
    if (p.fast) prep_fast++;
    if (memcmp(&p.a, &a, sizeof a) || memcmp(&a0, &a, sizeof a)
        || (p.fast != 0) != map_fast_f(&a)) {
        snprintf(why, sizeof why, "map copied %s, fast %d (fast range: %d)",
                 memcmp(&p.a, &a, sizeof a) ? "NOT bit for bit" : "bit for bit", p.fast,
                 map_fast_f(&a));
        fs_fail(&st_prep, what, why);
        st_prep.failed++;
    }
    z.a = a;
    prep_variant(x, &p, PV_PREP, in, n, what);
    prep_variant(x, &z, PV_ZERO, in, n, what);
    for (f = 0; f < nforge; f++) {
        q = p;
        q.cls = xu_cls_values[(f0 + f) % XU_NCLS_VALUES];
        if (id % 2) q.fast = 0;
        prep_variant(x, &q, PV_CLS, in, n, what);
        q.fast = 1;
        prep_variant(x, &q, PV_FORGED, in, n, what);
    }
}

/* A map of xu_gen_case, a quarter of them with an entry at the edge of the
 * fast range (2^61, 2^122) or the next float beyond, then n boxes. */
static void prep_case(xu_exact *x, xu_rng *r, int n, long id)
{
    static const double edge[4] = { 0x1p61, 0x1.000002p61, 0x1p122, 0x1.000002p122 };
    cbx_affine a, ignore;
    cbx_box b[100];
    char what[48];
    int k;
    xu_gen_case(r, &a, &b[0]);
    if (xu_rng_int(r, 0, 3) == 0) {
        int i = xu_rng_int(r, 0, 2), j = xu_rng_int(r, 0, 3), e = xu_rng_int(r, 0, 1);
        double sg = xu_rng_sign(r);
        a.m[i][j] = sg * edge[(j == 3) * 2 + e];
    }
    for (k = 0; k < n; k++) xu_gen_case(r, &ignore, &b[k]);
    snprintf(what, sizeof what, "random prepared batch %ld", id);
    run_prep(x, &a, b, n, id, (int)(id % XU_NCLS_VALUES), 1, what);
}

/* ---- 3. cbx_transform_cboxf ------------------------------------------- */

static fstat st_cbox = { "cbx_transform_cboxf", 0, 0, 0, 0, 0, 0 };

/* (oc - oh) and (oc + oh) against the exact ends of the image of the
 * (dropped) input box on axis i; adds the excess (axes with u S >=
 * 2^XU_TINY eta, as test_exact reports them); 0 on failure. */
static int cbox_axis_ok(xu_exact *x, const cbx_affine *a, const cbx_cbox *d, int i,
                        double oc, double oh, char *why, size_t nwhy)
{
    mpz_t C, H, S, z, lo, hi, gap;
    int j, ok = 1, tiny;
    mpz_inits(C, H, S, z, lo, hi, gap, NULL);
    xu_scaled_d(x, C, a->m[i][3]);
    mpz_abs(S, C);
    mpz_set_ui(H, 0);
    for (j = 0; j < 3; j++) {
        xu_scaled_mul(x, z, a->m[i][j], d->c[j]);
        mpz_add(C, C, z);
        mpz_abs(z, z);
        mpz_add(S, S, z);
        xu_scaled_mul(x, z, a->m[i][j], d->h[j]);
        mpz_abs(z, z);
        mpz_add(H, H, z);
        mpz_add(S, S, z);
    }
    /* exact image [C - H, C + H]; output [oc - oh, oc + oh] */
    xu_scaled_d(x, lo, oc);
    xu_scaled_d(x, z, oh);
    mpz_add(hi, lo, z);
    mpz_sub(lo, lo, z);
    mpz_sub(gap, C, H);
    mpz_sub(gap, gap, lo); /* >= 0: contained below */
    tiny = mpz_sizeinbase(S, 2) <= (size_t)(XU_SHIFT - 149 + 24 + XU_TINY);
    if (mpz_sgn(gap) < 0) { ok = 0; snprintf(why, nwhy, "axis %d: lower end not contained", i); }
    else if (!tiny) fs_excess(&st_cbox, xu_units(x, gap, S));
    /* the proven bound: gap <= 12 u S + 2^-140 (scaled: gap 2^24 <= 12 S + 2^(SHIFT-116)) */
    mpz_mul_2exp(z, gap, 24);
    mpz_mul_ui(gap, S, 12);
    mpz_set_ui(C, 1);
    mpz_mul_2exp(C, C, XU_SHIFT - 140 + 24);
    mpz_add(gap, gap, C);
    if (ok && mpz_cmp(z, gap) > 0) { ok = 0; snprintf(why, nwhy, "axis %d: lower end beyond 12uS+2^-140", i); }
    /* upper */
    xu_scaled_d(x, C, a->m[i][3]);
    for (j = 0; j < 3; j++) {
        xu_scaled_mul(x, z, a->m[i][j], d->c[j]);
        mpz_add(C, C, z);
    }
    mpz_add(gap, C, H);
    mpz_sub(gap, hi, gap);
    if (mpz_sgn(gap) < 0) { ok = 0; snprintf(why, nwhy, "axis %d: upper end not contained", i); }
    else if (!tiny) fs_excess(&st_cbox, xu_units(x, gap, S));
    mpz_mul_2exp(z, gap, 24);
    mpz_mul_ui(gap, S, 12);
    mpz_set_ui(C, 1);
    mpz_mul_2exp(C, C, XU_SHIFT - 140 + 24);
    mpz_add(gap, gap, C);
    if (ok && mpz_cmp(z, gap) > 0) { ok = 0; snprintf(why, nwhy, "axis %d: upper end beyond 12uS+2^-140", i); }
    mpz_clears(C, H, S, z, lo, hi, gap, NULL);
    return ok;
}

static void run_cbox(xu_exact *x, const cbx_affine *ad, const cbx_cbox *cd, const char *what)
{
    cbx_affinef a;
    cbx_cboxf c, o, ip;
    cbx_cbox od;
    cbx_status s, s2, want = xu_cbox_expected_status(ad, cd);
    char why[160] = "";
    int i, bad = 0;
    to_af(ad, &a);
    to_cf(cd, &c);
    nan_cf(&o);
    s = cbx_transform_cboxf(&a, &c, &o);
    from_cf(&o, &od);
    st_cbox.cases++;
    st_cbox.checks += 2;
    if (s != want) { bad = 1; snprintf(why, sizeof why, "status %d, expected %d", s, want); }
    for (i = 0; i < 3 && !bad; i++) {
        st_cbox.checks++;
        if (od.c[i] != od.c[i] || od.h[i] != od.h[i]) {
            bad = 1;
            snprintf(why, sizeof why, "axis %d left unset", i);
        } else if (want == CBX_EINVAL || want == CBX_EMPTY) {
            if (!(od.c[i] == 0 && (want == CBX_EINVAL ? is_pinf(od.h[i]) : is_ninf(od.h[i])))) {
                bad = 1;
                snprintf(why, sizeof why, "axis %d: special output wrong", i);
            }
        } else {
            int k = xu_cbox_axis_kind(ad, cd, i);
            if (k == XU_CAX_LOST) {
                if (!(od.c[i] == 0 && is_pinf(od.h[i]))) {
                    bad = 1;
                    snprintf(why, sizeof why, "axis %d: lost axis not (0, +inf)", i);
                }
            } else {
                cbx_cbox d;
                xu_cbox_dropped(ad, cd, i, &d);
                if (!isfinite(od.c[i]) || !isfinite(od.h[i])) {
                    bad = 1;
                    snprintf(why, sizeof why, "axis %d: proven axis not finite", i);
                } else if (!cbox_axis_ok(x, ad, k == XU_CAX_FULL ? cd : &d, i, od.c[i], od.h[i],
                                         why, sizeof why)) {
                    bad = 1;
                }
                st_cbox.checks += 4;
            }
        }
    }
    ip = c;
    s2 = cbx_transform_cboxf(&a, &ip, &ip);
    st_cbox.checks++;
    if (s2 != s || memcmp(&ip, &o, sizeof o)) {
        bad = 1;
        snprintf(why, sizeof why, "in-place call differs");
    }
    if (bad) {
        st_cbox.failed++;
        fs_fail(&st_cbox, what, why);
    }
}

/* A cbox case: the map and the centers of a random box case, half-widths
 * within the same class, zero columns against infinite or huge entries,
 * some NaN and negative half-widths. */
static void gen_cbox(xu_rng *r, cbx_affine *a, cbx_cbox *c)
{
    cbx_box b;
    int j, p = xu_rng_int(r, 0, 99);
    xu_gen_case(r, a, &b);
    for (j = 0; j < 3; j++) {
        double lo = b.lo[j], hi = b.hi[j];
        c->c[j] = isfinite(lo) ? lo : (isfinite(hi) ? hi : 0.0);
        c->h[j] = fabs(xu_round_fmt(isfinite(hi) && isfinite(lo) ? hi - lo : c->c[j]));
        if (!isfinite(c->h[j])) c->h[j] = FLT_MAX;
    }
    if (p < 10) { /* zero column against an unusable center or half-width */
        int i = xu_rng_int(r, 0, 2);
        j = xu_rng_int(r, 0, 2);
        a->m[0][j] = a->m[1][j] = 0.0;
        a->m[i][j] = xu_rng_sign(r) * 0.0;
        if (xu_rng_int(r, 0, 1)) c->c[j] = xu_rng_sign(r) * HUGE_VAL;
        else c->h[j] = xu_rng_int(r, 0, 1) ? HUGE_VAL : FLT_MAX;
    } else if (p < 13) {
        double m = xu_gen_mag(r, -149, 10);
        c->h[xu_rng_int(r, 0, 2)] = m > 0 ? -m : -0x1p-149; /* empty */
    } else if (p < 15) {
        c->c[xu_rng_int(r, 0, 2)] = NAN;
    } else if (p < 18) {
        c->h[xu_rng_int(r, 0, 2)] = HUGE_VAL;
    }
}

/* ---- 4. conversions ---------------------------------------------------- */

static fstat st_b2c = { "cbx_box_to_cboxf", 0, 0, 0, 0, 0, 0 };
static fstat st_c2b = { "cbx_cbox_to_boxf", 0, 0, 0, 0, 0, 0 };

static int conv_in(double x) { return fabs(x) <= 0x1p123; }

static void run_b2c(xu_exact *x, const cbx_box *bd, const char *what)
{
    cbx_boxf b;
    cbx_cboxf o;
    cbx_cbox od;
    cbx_status s, want;
    char why[120] = "";
    int j, nan = 0, empty = 0, out = 0, bad = 0;
    to_bf(bd, &b);
    for (j = 0; j < 3; j++) {
        if (bd->lo[j] != bd->lo[j] || bd->hi[j] != bd->hi[j]) nan = 1;
        if (bd->hi[j] < bd->lo[j] || is_pinf(bd->lo[j]) || is_ninf(bd->hi[j])) empty = 1;
        if (!conv_in(bd->lo[j]) || !conv_in(bd->hi[j])) out = 1;
    }
    want = nan ? CBX_EINVAL : empty ? CBX_EMPTY : out ? CBX_ERANGE : CBX_OK;
    nan_cf(&o);
    s = cbx_box_to_cboxf(&b, &o);
    from_cf(&o, &od);
    st_b2c.cases++;
    st_b2c.checks++;
    if (s != want) { bad = 1; snprintf(why, sizeof why, "status %d, expected %d", s, want); }
    for (j = 0; j < 3 && !bad; j++) {
        st_b2c.checks++;
        if (od.c[j] != od.c[j] || od.h[j] != od.h[j]) { bad = 1; snprintf(why, sizeof why, "axis %d unset", j); }
        else if (want == CBX_EINVAL || want == CBX_EMPTY) {
            if (!(od.c[j] == 0 && (want == CBX_EINVAL ? is_pinf(od.h[j]) : is_ninf(od.h[j]))))
                { bad = 1; snprintf(why, sizeof why, "axis %d special output", j); }
        } else if (!conv_in(bd->lo[j]) || !conv_in(bd->hi[j])) {
            if (!(od.c[j] == 0 && is_pinf(od.h[j]))) { bad = 1; snprintf(why, sizeof why, "axis %d not whole", j); }
        } else {
            mpz_t lo, hi, c, h;
            mpz_inits(lo, hi, c, h, NULL);
            xu_scaled_d(x, lo, bd->lo[j]);
            xu_scaled_d(x, hi, bd->hi[j]);
            xu_scaled_d(x, c, od.c[j]);
            xu_scaled_d(x, h, od.h[j]);
            st_b2c.checks += 2;
            if (!isfinite(od.c[j]) || !isfinite(od.h[j])) { bad = 1; snprintf(why, sizeof why, "axis %d not finite", j); }
            else {
                mpz_sub(c, c, h); /* c - h <= lo */
                if (mpz_cmp(c, lo) > 0) { bad = 1; snprintf(why, sizeof why, "axis %d: c-h > lo", j); }
                mpz_add(c, c, h);
                mpz_add(c, c, h); /* c + h >= hi */
                if (mpz_cmp(c, hi) < 0) { bad = 1; snprintf(why, sizeof why, "axis %d: c+h < hi", j); }
                if (!bad) { /* excess of the half-width over (hi - lo)/2, units of u|x| + eta */
                    double w = od.h[j] - (bd->hi[j] - bd->lo[j]) / 2;
                    double sc = fmax(fabs(bd->lo[j]), fabs(bd->hi[j]));
                    fs_excess(&st_b2c, w / (0x1p-24 * sc + 0x1p-149));
                }
            }
            mpz_clears(lo, hi, c, h, NULL);
        }
    }
    if (bad) { st_b2c.failed++; fs_fail(&st_b2c, what, why); }
}

static void run_c2b(xu_exact *x, const cbx_cbox *cd, const char *what)
{
    cbx_cboxf c;
    cbx_boxf o;
    cbx_box od;
    cbx_status s, want;
    char why[120] = "";
    int j, nan = 0, empty = 0, out = 0, bad = 0;
    to_cf(cd, &c);
    for (j = 0; j < 3; j++) {
        if (cd->c[j] != cd->c[j] || cd->h[j] != cd->h[j]) nan = 1;
        if (cd->h[j] < 0) empty = 1;
        if (!conv_in(cd->c[j]) || !conv_in(cd->h[j])) out = 1;
    }
    want = nan ? CBX_EINVAL : empty ? CBX_EMPTY : out ? CBX_ERANGE : CBX_OK;
    nan_bf(&o);
    s = cbx_cbox_to_boxf(&c, &o);
    from_bf(&o, &od);
    st_c2b.cases++;
    st_c2b.checks++;
    if (s != want) { bad = 1; snprintf(why, sizeof why, "status %d, expected %d", s, want); }
    for (j = 0; j < 3 && !bad; j++) {
        st_c2b.checks++;
        if (od.lo[j] != od.lo[j] || od.hi[j] != od.hi[j]) { bad = 1; snprintf(why, sizeof why, "axis %d unset", j); }
        else if (want == CBX_EINVAL) {
            if (!(is_ninf(od.lo[j]) && is_pinf(od.hi[j]))) { bad = 1; snprintf(why, sizeof why, "axis %d special", j); }
        } else if (want == CBX_EMPTY) {
            if (!(is_pinf(od.lo[j]) && is_ninf(od.hi[j]))) { bad = 1; snprintf(why, sizeof why, "axis %d special", j); }
        } else if (!conv_in(cd->c[j]) || !conv_in(cd->h[j])) {
            if (!(is_ninf(od.lo[j]) && is_pinf(od.hi[j]))) { bad = 1; snprintf(why, sizeof why, "axis %d not whole", j); }
        } else {
            mpz_t lo, hi, c, h;
            mpz_inits(lo, hi, c, h, NULL);
            xu_scaled_d(x, lo, od.lo[j]);
            xu_scaled_d(x, hi, od.hi[j]);
            xu_scaled_d(x, c, cd->c[j]);
            xu_scaled_d(x, h, cd->h[j]);
            st_c2b.checks += 2;
            if (!isfinite(od.lo[j]) || !isfinite(od.hi[j])) { bad = 1; snprintf(why, sizeof why, "axis %d not finite", j); }
            else {
                mpz_sub(c, c, h); /* lo <= c - h */
                if (mpz_cmp(lo, c) > 0) { bad = 1; snprintf(why, sizeof why, "axis %d: lo > c-h", j); }
                mpz_add(c, c, h);
                mpz_add(c, c, h); /* hi >= c + h */
                if (mpz_cmp(hi, c) < 0) { bad = 1; snprintf(why, sizeof why, "axis %d: hi < c+h", j); }
                if (!bad) {
                    double sc = fabs(cd->c[j]) + cd->h[j];
                    double w = (od.hi[j] - od.lo[j]) / 2 - cd->h[j];
                    fs_excess(&st_c2b, w / (0x1p-24 * sc + 0x1p-149));
                }
            }
            mpz_clears(lo, hi, c, h, NULL);
        }
    }
    if (bad) { st_c2b.failed++; fs_fail(&st_c2b, what, why); }
}

/* ---- 5. spheres and ellipsoids ---------------------------------------- */

static fstat st_sph = { "cbx_sphere_boxf", 0, 0, 0, 0, 0, 0 };
static fstat st_ell = { "cbx_ellipsoid_boxf", 0, 0, 0, 0, 0, 0 };

/* One axis of a ball bound: lo <= t - sqrt(s') and hi >= t + sqrt(s'),
 * s' = s / 2^(2 sh), exactly (else 0), and each end within the proven
 * 80 u (|t| + sqrt s') + 2^-139 of the exact end, exactly (else -1); the
 * excess of each end over the exact end, in units of u (|t| + sqrt s') +
 * eta (statistics). */
static int ball_axis_ok(xu_exact *x, fstat *fs, const mpz_t s, unsigned long sh, double t,
                        double lo, double hi)
{
    double r, sc, m;
    long e;
    if (!xu_sqrt_lo_ok(x, s, sh, t, lo) || !xu_sqrt_hi_ok(x, s, sh, t, hi)) return 0;
    /* the proven tightness (ball_tight, binary32): 80 u (|t| + sqrt s') + 2^-139 */
    fs->checks += 2;
    if (!xu_sqrt_gap_ok(x, s, sh, t, lo, 80, 24, 139) || !xu_sqrt_gap_ok(x, s, sh, t, hi, 80, 24, 139))
        return -1;
    m = mpz_get_d_2exp(&e, s); /* s = m 2^e, m in [0.5, 1): statistics only */
    r = mpz_sgn(s) ? ldexp(sqrt(m * ((e & 1) ? 2.0 : 1.0)), (int)((e - (e & 1)) / 2 - (long)sh)) : 0.0;
    sc = 0x1p-24 * (fabs(t) + r) + 0x1p-149;
    fs_excess(fs, ((t - r) - lo) / sc);
    fs_excess(fs, (hi - (t + r)) / sc);
    return 1;
}

static int ball_out_common(fstat *fs, const char *what, cbx_status s, cbx_status want,
                           const cbx_box *od, const int in_dom[3])
{
    char why[120] = "";
    int i, bad = 0;
    fs->checks++;
    if (s != want) { bad = 1; snprintf(why, sizeof why, "status %d, expected %d", s, want); }
    for (i = 0; i < 3 && !bad; i++) {
        fs->checks++;
        if (od->lo[i] != od->lo[i] || od->hi[i] != od->hi[i]) { bad = 1; snprintf(why, sizeof why, "axis %d unset", i); }
        else if (want == CBX_EINVAL || !in_dom[i]) {
            if (!(is_ninf(od->lo[i]) && is_pinf(od->hi[i]))) { bad = 1; snprintf(why, sizeof why, "axis %d not whole", i); }
        } else if (!isfinite(od->lo[i]) || !isfinite(od->hi[i])) {
            bad = 1;
            snprintf(why, sizeof why, "axis %d not finite", i);
        }
    }
    if (bad) fs_fail(fs, what, why);
    return bad;
}

static void run_sphere(xu_exact *x, const cbx_affine *ad, const char *what)
{
    cbx_affinef a;
    cbx_boxf o;
    cbx_box od;
    cbx_status s, want;
    int i, j, nan = 0, dom[3], bad;
    mpz_t S, z;
    to_af(ad, &a);
    for (i = 0; i < 3; i++) {
        dom[i] = 1;
        for (j = 0; j < 4; j++) {
            if (ad->m[i][j] != ad->m[i][j]) nan = 1;
            if (!(fabs(ad->m[i][j]) <= (j < 3 ? 0x1p61 : 0x1p122))) dom[i] = 0;
        }
    }
    want = nan ? CBX_EINVAL : (dom[0] && dom[1] && dom[2]) ? CBX_OK : CBX_ERANGE;
    nan_bf(&o);
    s = cbx_sphere_boxf(&a, &o);
    from_bf(&o, &od);
    st_sph.cases++;
    bad = ball_out_common(&st_sph, what, s, want, &od, dom);
    mpz_inits(S, z, NULL);
    for (i = 0; i < 3 && !bad && want != CBX_EINVAL; i++) {
        if (!dom[i]) continue;
        mpz_set_ui(S, 0);
        for (j = 0; j < 3; j++) {
            xu_scaled_sh(z, ad->m[i][j], 1074);
            mpz_addmul(S, z, z);
        }
        st_sph.checks += 2;
        int k = ball_axis_ok(x, &st_sph, S, 1074, ad->m[i][3], od.lo[i], od.hi[i]);
        if (k <= 0) {
            bad = 1;
            fs_fail(&st_sph, what, k < 0 ? "an end beyond the proven tightness bound"
                                         : "an end inside the exact image of the ball");
        }
    }
    mpz_clears(S, z, NULL);
    if (bad) st_sph.failed++;
}

static void run_ellipsoid(xu_exact *x, const double cen[3], const double rad[3],
                          const double rot[3][3], const char *what)
{
    float c[3], r[3], R[3][3];
    cbx_boxf o;
    cbx_box od;
    cbx_status s, want;
    int i, j, nan = 0, dom[3], bad;
    mpz_t S, z, w;
    for (i = 0; i < 3; i++) {
        c[i] = F(cen[i]);
        r[i] = F(rad[i]);
        for (j = 0; j < 3; j++) R[i][j] = F(rot[i][j]);
        if (cen[i] != cen[i] || rad[i] != rad[i]) nan = 1;
        for (j = 0; j < 3; j++) if (rot[i][j] != rot[i][j]) nan = 1;
    }
    for (i = 0; i < 3; i++) {
        dom[i] = fabs(cen[i]) <= 0x1p122;
        for (j = 0; j < 3; j++)
            if (!(fabs(rot[i][j]) <= 0x1p30) || !(fabs(rad[j]) <= 0x1p30)) dom[i] = 0;
    }
    want = nan ? CBX_EINVAL : (dom[0] && dom[1] && dom[2]) ? CBX_OK : CBX_ERANGE;
    nan_bf(&o);
    s = cbx_ellipsoid_boxf(c, r, (const float (*)[3])R, &o);
    from_bf(&o, &od);
    st_ell.cases++;
    bad = ball_out_common(&st_ell, what, s, want, &od, dom);
    mpz_inits(S, z, w, NULL);
    for (i = 0; i < 3 && !bad && want != CBX_EINVAL; i++) {
        if (!dom[i]) continue;
        mpz_set_ui(S, 0);
        for (j = 0; j < 3; j++) { /* m_ij = rot_ij radii_j, times 2^2148, exactly */
            xu_scaled_sh(z, rot[i][j], 1074);
            xu_scaled_sh(w, rad[j], 1074);
            mpz_mul(z, z, w);
            mpz_addmul(S, z, z);
        }
        st_ell.checks += 2;
        int k = ball_axis_ok(x, &st_ell, S, 2148, cen[i], od.lo[i], od.hi[i]);
        if (k <= 0) {
            bad = 1;
            fs_fail(&st_ell, what, k < 0 ? "an end beyond the proven tightness bound"
                                         : "an end inside the exact image of the ellipsoid");
        }
    }
    mpz_clears(S, z, w, NULL);
    if (bad) st_ell.failed++;
}

/* A random rotation in float (the quaternion's matrix, rounded). */
static void rand_rot_f(xu_rng *r, double R[3][3])
{
    int i, j;
    xu_rand_rotation(r, R);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) R[i][j] = xu_round_fmt(R[i][j]);
}

static double gen_ball_entry(xu_rng *r)
{
    int p = xu_rng_int(r, 0, 99);
    if (p < 3) return xu_rng_sign(r) * 0x1p61;
    if (p < 5) return xu_rng_sign(r) * 0x1.000002p61;          /* just out */
    if (p < 7) return xu_rng_sign(r) * HUGE_VAL;
    if (p < 15) return xu_gen_signed(r, -149, -30);             /* tiny rows */
    return xu_gen_signed(r, -40, 40);
}

/* ---- 6. the special-value table --------------------------------------- */

static const double specials[] = {
    NAN, -NAN, HUGE_VAL, -HUGE_VAL, 0.0, -0.0, 0x1p-149, -0x1p-149, 0x1p-126, -0x1p-126,
    FLT_MAX, -FLT_MAX, 1.0, -1.0,
    0x1p30, 0x1.000002p30, -0x1p30, 0x1p61, 0x1.000002p61, -0x1p61, -0x1.000002p61,
    0x1p122, 0x1.000002p122, -0x1p122, -0x1.000002p122,
    0x1p123, 0x1.000002p123, -0x1p123, -0x1.000002p123, 0x1p-30, 3e-39f, 1e38f,
};
#define N_SPECIAL ((int)(sizeof specials / sizeof specials[0]))

static long special_rows;

static void run_specials(xu_exact *x, xu_stats *all)
{
    static const cbx_affine base_a = MAT(ROW(0.5f, -2, 0.25f, 1), ROW(0, 1.5f, -1, -3),
                                         ROW(4, 0, 0.125f, 0.75f));
    static const cbx_box base_b = BOX(-1, 2, 0.5f, 3, -4, -2);
    static const double base_cen[3] = { 1, -2, 3 }, base_rad[3] = { 2, 0.5f, 1 };
    static const double base_rot[3][3] = { { 0.6f, -0.8f, 0 }, { 0.8f, 0.6f, 0 }, { 0, 0, 1 } };
    int v, p;
    char what[64];
    for (v = 0; v < N_SPECIAL; v++) {
        double s = specials[v];
        for (p = 0; p < 18; p++) { /* transform_box: 12 map entries, 6 box ends */
            cbx_affine a = base_a;
            cbx_box b = base_b;
            cbx_cbox c;
            int j;
            if (p < 12) a.m[p / 4][p % 4] = s;
            else if (p < 15) b.lo[p - 12] = s;
            else b.hi[p - 15] = s;
            snprintf(what, sizeof what, "special box pos %d value %a", p, s);
            run_box(x, all, &a, &b, 1, what);
            run_prep(x, &a, &b, 1, v * 18 + p, 0, XU_NCLS_VALUES, what);
            for (j = 0; j < 3; j++) { c.c[j] = base_b.lo[j]; c.h[j] = 1.5f; }
            if (p >= 12 && p < 15) c.c[p - 12] = s;
            else if (p >= 15) c.h[p - 15] = s;
            run_cbox(x, &a, &c, what);
            if (p >= 12) {
                run_b2c(x, &b, what);
                run_c2b(x, &c, what);
            }
            special_rows += 2 + (p >= 12) * 2;
        }
        for (p = 0; p < 12; p++) {
            cbx_affine a = base_a;
            a.m[p / 4][p % 4] = s;
            snprintf(what, sizeof what, "special sphere pos %d value %a", p, s);
            run_sphere(x, &a, what);
            special_rows++;
        }
        for (p = 0; p < 15; p++) {
            double cen[3], rad[3], rot[3][3];
            memcpy(cen, base_cen, sizeof cen);
            memcpy(rad, base_rad, sizeof rad);
            memcpy(rot, base_rot, sizeof rot);
            if (p < 3) cen[p] = s;
            else if (p < 6) rad[p - 3] = s;
            else rot[(p - 6) / 3][(p - 6) % 3] = s;
            snprintf(what, sizeof what, "special ellipsoid pos %d value %a", p, s);
            run_ellipsoid(x, cen, rad, (const double (*)[3])rot, what);
            special_rows++;
        }
    }
}

/* ---- driver ------------------------------------------------------------ */

int main(int argc, char **argv)
{
    long n = (long)xu_arg_num(argc, argv, 1, 200000, "test_float [N] [seed]");
    uint64_t seed = xu_arg_num(argc, argv, 2, 1, "test_float [N] [seed]");
    xu_exact x;
    xu_stats all;
    xu_rng r;
    long c, failed;
    int k;
    static const int sizes[] = { 0, 1, 2, 7, 100 };

    xu_set_format(&xu_binary32);
    xu_init(&x);
    xu_stats_init(&all);
    r.s = seed;
    printf("test_float: the binary32 family against exact rationals "
           "(u = 2^-24, eta = 2^-149), N = %ld, seed = %llu\n", n, (unsigned long long)seed);

    for (k = 0; k < N_BOX_HARD; k++) run_box(&x, &all, &box_hard[k].a, &box_hard[k].in, 1, box_hard[k].name);
    for (c = 0; c < n; c++) {
        cbx_affine a;
        cbx_box b;
        char what[48];
        xu_gen_case(&r, &a, &b);
        snprintf(what, sizeof what, "random box case %ld", c);
        run_box(&x, &all, &a, &b, c % 50 == 0, what);
    }
    for (c = 0; c < n / 100 + 5; c++) run_batch(&r, sizes[c % 5]);
    {   /* its own generator: the draws of the sections below stay as they were */
        xu_rng rp;
        rp.s = UINT64_C(0x9e3779b97f4a7c15) ^ seed;
        for (c = 0; c < n / 100 + 20; c++) prep_case(&x, &rp, sizes[c % 5], c);
    }
    for (c = 0; c < n / 2; c++) {
        cbx_affine a;
        cbx_cbox cb;
        cbx_box b;
        char what[48];
        gen_cbox(&r, &a, &cb);
        snprintf(what, sizeof what, "random cbox case %ld", c);
        run_cbox(&x, &a, &cb, what);
        xu_gen_case(&r, &a, &b);
        run_b2c(&x, &b, what);
        run_c2b(&x, &cb, what);
    }
    for (c = 0; c < n / 2; c++) {
        cbx_affine a;
        double cen[3], rad[3], rot[3][3];
        char what[48];
        int i, j;
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) a.m[i][j] = gen_ball_entry(&r);
            a.m[i][3] = xu_rng_int(&r, 0, 19) == 0 ? xu_rng_sign(&r) * 0x1p122
                                                   : xu_gen_signed(&r, -149, 100);
        }
        if (xu_rng_int(&r, 0, 3) == 0) { /* a rotation times a scale: the common case */
            double R[3][3], sc = xu_gen_mag(&r, -20, 20);
            rand_rot_f(&r, R);
            for (i = 0; i < 3; i++)
                for (j = 0; j < 3; j++) a.m[i][j] = xu_round_fmt(R[i][j] * sc);
        }
        snprintf(what, sizeof what, "random sphere case %ld", c);
        run_sphere(&x, &a, what);
        rand_rot_f(&r, rot);
        for (i = 0; i < 3; i++) {
            cen[i] = xu_rng_int(&r, 0, 19) == 0 ? xu_rng_sign(&r) * 0x1.000002p122
                                                : xu_gen_signed(&r, -149, 110);
            rad[i] = xu_rng_int(&r, 0, 24) == 0 ? xu_rng_sign(&r) * 0x1.000002p30
                                                : xu_gen_signed(&r, -149, 30);
        }
        if (xu_rng_int(&r, 0, 9) == 0) rot[xu_rng_int(&r, 0, 2)][xu_rng_int(&r, 0, 2)] = xu_gen_signed(&r, -149, 31);
        snprintf(what, sizeof what, "random ellipsoid case %ld", c);
        run_ellipsoid(&x, cen, rad, (const double (*)[3])rot, what);
    }
    run_specials(&x, &all);

    xu_stats_print(stdout, "cbx_transform_boxf (oracle: exact_util, binary32)", &all);
    printf("per function (binary32 family):\n");
    fs_print(&st_box);
    fs_print(&st_inpl);
    fs_print(&st_batch);
    fs_print(&st_prep);
    fs_print(&st_prep1);
    fs_print(&st_prepn);
    printf("  prepared maps: %ld prepared (%ld in the fast range); structs: cbx_preparef's, "
           "zero-initialised, cls forged, fast+cls forged (cls over the %d values of "
           "xu_cls_values); boxes of the forged structs against the exact oracle: %ld\n",
           st_prep.cases, prep_fast, XU_NCLS_VALUES, prep_exact);
    fs_print(&st_cbox);
    fs_print(&st_b2c);
    fs_print(&st_c2b);
    fs_print(&st_sph);
    fs_print(&st_ell);
    printf("  special-value rows: %ld (%d values x every input position x every function)\n",
           special_rows, N_SPECIAL);
    printf("  generated values that were not floats: %ld\n", not_float);
    failed = st_box.failed + st_inpl.failed + st_batch.failed + st_prep.failed + st_prep1.failed
             + st_prepn.failed + st_cbox.failed + st_b2c.failed + st_c2b.failed + st_sph.failed
             + st_ell.failed + (not_float != 0);
    c = st_box.cases + st_inpl.cases + st_batch.cases + st_prep.cases + st_prep1.cases
        + st_prepn.cases + st_cbox.cases + st_b2c.cases + st_c2b.cases + st_sph.cases
        + st_ell.cases;
    xu_clear(&x);
    printf("%ld passed, %ld failed\n", c - failed, failed);
    return failed != 0;
}
