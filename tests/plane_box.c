/*
 * The box suite of test_plane (tests/plane_parts.h): cbx_transform_box2
 * and cbx_transform_box2f on the hard cases and random cases, judged by
 * exact_util's oracle on the 3D embedding, against the 3D function's bits,
 * in place and with the inputs unchanged.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "plane_parts.h"

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
        plt_fail(fam, what, v.why);
    }
    return v.failed;
}

/* One case in binary64; returns 1 on failure. */
int plt_run64(xu_exact *x, xu_stats *st, tally *t, const double m[2][3], const double lo[2],
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
int plt_run32(xu_exact *x, xu_stats *st, tally *t, const double m[2][3], const double lo[2],
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

/* The table, then n random cases, in the current format. */
long plt_family(xu_exact *x, const char *fam, runner run, long n, uint64_t seed, long *passed)
{
    xu_stats st;
    tally t;
    xu_rng r;
    long c;
    int k, i, j;
    char what[64];
    memset(&t, 0, sizeof t);
    xu_stats_init(&st);
    for (k = 0; k < plt_n_hard; k++) {
        double m[2][3], lo[2], hi[2];
        for (i = 0; i < 2; i++) {
            for (j = 0; j < 3; j++) m[i][j] = xu_round_fmt(plt_hard[k].m[i][j]);
            lo[i] = xu_round_fmt(plt_hard[k].lo[i]);
            hi[i] = xu_round_fmt(plt_hard[k].hi[i]);
        }
        run(x, &st, &t, (const double(*)[3])m, lo, hi, 1, plt_hard[k].name);
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
           "statuses OK %ld, EMPTY %ld, EINVAL %ld, ERANGE %ld\n", fam, t.cases, plt_n_hard, n,
           t.checks, t.failed, t.status[0], t.status[1], t.status[2], t.status[3]);
    xu_stats_print(stdout, fam, &st);
    *passed += t.cases - t.failed;
    return t.failed;
}

