/*
 * The center form and the conversions of test_plane (tests/plane_parts.h):
 * cbx_transform_cbox2(f) against exact_util's cbox rules and the 4 corners
 * in mpq, and cbx_box2_to_cbox2 / cbx_cbox2_to_box2 (and their binary32
 * twins) against the proven gap in mpq, each against the 3D function's
 * bits on the embedding.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "plane_parts.h"

/* ---- the center form --------------------------------------------------- */

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
            if (oc[i] != 0 || !(got == CBX_EINVAL ? plt_is_pinf(oh[i]) : plt_is_ninf(oh[i])))
                snprintf(why, sizeof why, "axis %d: not the special output of %s", i, cbx_status_name(got));
            continue;
        }
        kind = xu_cbox_axis_kind(&a3, &b3, i);
        if (kind == XU_CAX_LOST) {
            if (oc[i] != 0 || !plt_is_pinf(oh[i]))
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
        plt_fail(fam, what, why);
    }
}

long plt_cboxes(int f32, long n, uint64_t seed, long *passed)
{
    ctally t;
    xu_rng r;
    long c;
    int i;
    char what[64];
    memset(&t, 0, sizeof t);
    for (c = 0; c < plt_n_hard; c++) {
        double m[2][3], cc[2], hh[2];
        int j;
        for (i = 0; i < 2; i++) {
            for (j = 0; j < 3; j++) m[i][j] = xu_round_fmt(plt_hard[c].m[i][j]);
            cc[i] = xu_round_fmt(plt_hard[c].lo[i]);
            hh[i] = xu_round_fmt(plt_hard[c].hi[i] - plt_hard[c].lo[i]);
        }
        run_cbox(&t, f32, (const double(*)[3])m, cc, hh, plt_hard[c].name);
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
        empty |= dir ? v[i] < 0 : (v[i] < u[i] || plt_is_pinf(u[i]) || plt_is_ninf(v[i]));
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
            int ok = dir ? (nan ? plt_is_ninf(p[i]) && plt_is_pinf(q[i]) : plt_is_pinf(p[i]) && plt_is_ninf(q[i]))
                         : (p[i] == 0 && (nan ? plt_is_pinf(q[i]) : plt_is_ninf(q[i])));
            if (!ok) snprintf(why, sizeof why, "axis %d: not the special output of %s", i, cbx_status_name(got));
            continue;
        }
        if (!in) {
            if (dir ? !(plt_is_ninf(p[i]) && plt_is_pinf(q[i])) : !(p[i] == 0 && plt_is_pinf(q[i])))
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
        plt_fail(fam, what, why);
    }
}

long plt_convs(int f32, long n, uint64_t seed, long *passed)
{
    ctally tb, tc;
    xu_rng r;
    long c;
    int i, k;
    char what[64];
    memset(&tb, 0, sizeof tb);
    memset(&tc, 0, sizeof tc);
    for (k = 0; k < plt_n_hard; k++) {
        double u[2], v[2], h[2];
        for (i = 0; i < 2; i++) {
            u[i] = xu_round_fmt(plt_hard[k].lo[i]);
            v[i] = xu_round_fmt(plt_hard[k].hi[i]);
            h[i] = xu_round_fmt(plt_hard[k].hi[i] - plt_hard[k].lo[i]);
        }
        run_conv(&tb, f32, 0, u, v, plt_hard[k].name);
        run_conv(&tc, f32, 1, u, h, plt_hard[k].name);
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

