/*
 * Sections 1, 2 and 2b of tests/test_float.c (tests/float_parts.h):
 * cbx_transform_boxf (its hard cases and the check of one case),
 * cbx_transform_boxesf, and the prepared maps (cbx_preparef,
 * cbx_transform_box_prepf, cbx_transform_boxes_prepf).
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "float_parts.h"

/* ---- 1. cbx_transform_boxf -------------------------------------------- */

fstat flt_st_box = { "cbx_transform_boxf", 0, 0, 0, 0, 0, 0 };
fstat flt_st_inpl = { "  in place (out == in)", 0, 0, 0, 0, 0, 0 };

/* The whole check of one case; returns 1 on failure. */
int flt_run_box(xu_exact *x, xu_stats *all, const cbx_affine *ad, const cbx_box *bd,
                int corners, const char *what)
{
    cbx_affinef a, a0;
    cbx_boxf b, b0, o, ip;
    cbx_affine af;
    cbx_box od, bf;
    cbx_status s, s2;
    xu_verdict v;
    int k, bad;
    flt_to_af(ad, &a);
    flt_to_bf(bd, &b);
    a0 = a;
    b0 = b;
    flt_from_af(&a, &af);  /* the oracle judges the floats the library got */
    flt_from_bf(&b, &bf);
    ad = &af;
    bd = &bf;
    flt_nan_bf(&o);
    s = cbx_transform_boxf(&a, &b, &o);
    flt_from_bf(&o, &od);
    xu_check_result(x, ad, bd, &od, s, corners, &v);
    for (k = 0; k < XU_NFLAGS; k++) flt_st_box.checks += v.applied[k];
    flt_st_box.checks++;
    if (memcmp(&a, &a0, sizeof a) || memcmp(&b, &b0, sizeof b)) {
        v.failed = 1;
        snprintf(v.why, sizeof v.why, "an input changed");
    }
    flt_st_box.cases++;
    bad = v.failed;
    if (bad) {
        flt_st_box.failed++;
        flt_fs_fail(&flt_st_box, what, v.why);
    }
    for (k = 0; k < 3; k++) {
        if (v.ax[k].checked && !v.ax[k].tiny) {
            flt_fs_excess(&flt_st_box, v.ax[k].ex_lo);
            flt_fs_excess(&flt_st_box, v.ax[k].ex_hi);
        }
    }
    xu_stats_add(all, &v, ad, bd);
    /* in place: the same bits */
    ip = b;
    s2 = cbx_transform_boxf(&a, &ip, &ip);
    flt_st_inpl.cases++;
    flt_st_inpl.checks++;
    if (s2 != s || memcmp(&ip, &o, sizeof o)) {
        flt_st_inpl.failed++;
        flt_fs_fail(&flt_st_inpl, what, "differs from the separate output");
        bad = 1;
    }
    return bad;
}


/* binary32 hard cases; the expected outcome of each is computed by the
 * oracle from the rules, and the comment says what it is. */
const box_case flt_box_hard[] = {
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
#define N_BOX_HARD ((int)(sizeof flt_box_hard / sizeof flt_box_hard[0]))
const int flt_n_box_hard = N_BOX_HARD;

/* ---- 2. cbx_transform_boxesf ------------------------------------------ */

fstat flt_st_batch = { "cbx_transform_boxesf", 0, 0, 0, 0, 0, 0 };

static int sev(cbx_status s)
{
    return s == CBX_EINVAL ? 3 : s == CBX_ERANGE ? 2 : s == CBX_EMPTY ? 1 : 0;
}

void flt_run_batch(xu_rng *r, int n)
{
    cbx_affine ad, ignore;
    cbx_box bd;
    cbx_affinef a;
    cbx_boxf in[102], out[102], one;
    cbx_status s, worst = CBX_OK;
    int k, bad = 0;
    xu_gen_case(r, &ad, &bd);
    flt_to_af(&ad, &a);
    for (k = 0; k < n; k++) {
        xu_gen_case(r, &ignore, &bd);
        flt_to_bf(&bd, &in[k]);
    }
    for (k = 0; k < n + 2; k++) memset(&out[k], 0x5a, sizeof out[k]); /* guards */
    s = cbx_transform_boxesf(&a, in, out, (size_t)n);
    for (k = 0; k < n; k++) {
        cbx_status sk = cbx_transform_boxf(&a, &in[k], &one);
        if (sev(sk) > sev(worst)) worst = sk;
        flt_st_batch.checks++;
        if (memcmp(&one, &out[k], sizeof one)) bad = 1;
    }
    for (k = n; k < n + 2; k++) {
        unsigned char g[sizeof out[0]];
        memset(g, 0x5a, sizeof g);
        flt_st_batch.checks++;
        if (memcmp(g, &out[k], sizeof g)) bad = 1;
    }
    flt_st_batch.checks++;
    if (s != worst) bad = 1;
    flt_st_batch.cases++;
    if (bad) {
        flt_st_batch.failed++;
        flt_fs_fail(&flt_st_batch, "batch", "differs from the single calls or wrote past out[n-1]");
    }
}

/* ---- 2b. prepared maps ------------------------------------------------ */

fstat flt_st_prep = { "cbx_preparef", 0, 0, 0, 0, 0, 0 };
fstat flt_st_prep1 = { "cbx_transform_box_prepf", 0, 0, 0, 0, 0, 0 };
fstat flt_st_prepn = { "cbx_transform_boxes_prepf", 0, 0, 0, 0, 0, 0 };
long flt_prep_fast, flt_prep_exact;

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
 * call counts in flt_st_prep1, a failed boxes_prepf call (bits, status,
 * guards, *p, or a box against the exact oracle) in flt_st_prepn. */
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
            flt_nan_bf(&r);
            s = cbx_transform_box_prepf(p, &in[k], &o);
            sr = cbx_transform_boxf(&p->a, &in[k], &r);
            ip = in[k];
            flt_st_prep1.cases++;
            flt_st_prep1.checks += 2;
            if (s != sr || memcmp(&o, &r, sizeof o)) {
                snprintf(why, sizeof why, "box %d, %s (fast %d, cls %s): status %s, "
                         "cbx_transform_boxf %s, boxes %s", k, pv_name[v], p->fast, cls,
                         cbx_status_name(s), cbx_status_name(sr),
                         memcmp(&o, &r, sizeof o) ? "differ" : "equal");
                flt_fs_fail(&flt_st_prep1, what, why);
                flt_st_prep1.failed++;
            } else if (cbx_transform_box_prepf(p, &ip, &ip) != s || memcmp(&ip, &o, sizeof o)) {
                snprintf(why, sizeof why, "box %d, %s: the in-place call differs", k, pv_name[v]);
                flt_fs_fail(&flt_st_prep1, what, why);
                flt_st_prep1.failed++;
            }
        }

    for (k = 0; k < n + 2; k++) memset(&out[k], 0x5a, sizeof out[k]); /* guards */
    for (k = 0; k < n; k++) flt_nan_bf(&ref[k]);
    s = cbx_transform_boxes_prepf(p, in, out, (size_t)n);
    sr = cbx_transform_boxesf(&p->a, in, ref, (size_t)n);
    flt_st_prepn.cases++;
    flt_st_prepn.checks += 4;
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
            flt_fs_fail(&flt_st_prepn, what, why);
            nbad = 1;
        }
    }
    if (v == PV_CLS || v == PV_FORGED)
        for (k = 0; k < n; k++) {
            cbx_affine ad;
            cbx_box bd, od;
            xu_verdict vd;
            flt_from_af(&p0.a, &ad);
            flt_from_bf(&in[k], &bd);
            flt_from_bf(&out[k], &od);
            flt_prep_exact++;
            xu_check_result(x, &ad, &bd, &od, sk[k], 0, &vd);
            for (j = 0; j < XU_NFLAGS; j++) flt_st_prepn.checks += vd.applied[j];
            if (vd.failed) {
                snprintf(why, sizeof why, "box %d of n = %d, %s (fast %d, cls %s): %s", k, n,
                         pv_name[v], p0.fast, cls, vd.why);
                flt_fs_fail(&flt_st_prepn, what, why);
                nbad = 1;
            }
        }
    if (nbad) flt_st_prepn.failed++;
}

/* The map ad and the n boxes bd[] (n <= 100) in binary32: cbx_preparef,
 * then every struct of prep_variant, with nforge values of xu_cls_values
 * from index f0 on; the fast flag of the cls-forged struct is cleared for
 * odd id.  Failures are counted in flt_st_prep, flt_st_prep1 and flt_st_prepn. */
void flt_run_prep(xu_exact *x, const cbx_affine *ad, const cbx_box *bd, int n, long id, int f0,
                 int nforge, const char *what)
{
    cbx_affinef a, a0;
    cbx_boxf in[100];
    cbx_preparedf p, q, z = { 0 };
    char why[160];
    int k, f;
    flt_to_af(ad, &a);
    for (k = 0; k < n; k++) flt_to_bf(&bd[k], &in[k]);
    a0 = a;
    memset(&p, 0xa5, sizeof p);
    cbx_preparef(&a, &p);
    flt_st_prep.cases++;
    flt_st_prep.checks += 3;
    if (p.fast) flt_prep_fast++;
    if (memcmp(&p.a, &a, sizeof a) || memcmp(&a0, &a, sizeof a)
        || (p.fast != 0) != map_fast_f(&a)) {
        snprintf(why, sizeof why, "map copied %s, fast %d (fast range: %d)",
                 memcmp(&p.a, &a, sizeof a) ? "NOT bit for bit" : "bit for bit", p.fast,
                 map_fast_f(&a));
        flt_fs_fail(&flt_st_prep, what, why);
        flt_st_prep.failed++;
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
void flt_prep_case(xu_exact *x, xu_rng *r, int n, long id)
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
    flt_run_prep(x, &a, b, n, id, (int)(id % XU_NCLS_VALUES), 1, what);
}
