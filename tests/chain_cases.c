/*
 * chain_cases.c: part of tests/test_chain.c (chain_parts.h): the tallies
 * of the checks and the failure log, the random maps and boxes of the
 * chains (the draws in a fixed order: the same chains on every machine),
 * cbx_transform_box_chain's special cases, and the statistics of the
 * growth (ratios, max and median).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>

#include "chain_parts.h"

const char *const cht_k_name[NK] = { "start", "box-step", "cbox-step", "box-comp", "cbox-comp",
                                     "chain-fn", "chain-spec" };
long cht_k_checked[NK], cht_k_failed[NK];
long cht_logs;

void cht_report(int kind, int chain, long step, const char *why)
{
    cht_k_failed[kind]++;
    if (cht_logs++ < MAX_FAIL_LOGS)
        printf("FAIL: %s, chain %d step %ld: %s\n", cht_k_name[kind], chain, step, why);
}

/* ---------------------------------------------------------------------- */
/* Random maps                                                            */
/* ---------------------------------------------------------------------- */

/* A uniformly random unit quaternion (rejection in the 4-ball), turned
 * into a rotation matrix in double arithmetic, plus a small translation. */
void cht_random_step(xu_rng *r, cbx_affine *a)
{
    double w, x, y, z, n;
    int i;
    do {
        w = 2 * xu_rng_unit(r) - 1;
        x = 2 * xu_rng_unit(r) - 1;
        y = 2 * xu_rng_unit(r) - 1;
        z = 2 * xu_rng_unit(r) - 1;
        n = w * w + x * x + y * y + z * z;
    } while (n > 1 || n < 1e-4);
    n = sqrt(n);
    w /= n; x /= n; y /= n; z /= n;
    a->m[0][0] = 1 - 2 * (y * y + z * z);
    a->m[0][1] = 2 * (x * y - w * z);
    a->m[0][2] = 2 * (x * z + w * y);
    a->m[1][0] = 2 * (x * y + w * z);
    a->m[1][1] = 1 - 2 * (x * x + z * z);
    a->m[1][2] = 2 * (y * z - w * x);
    a->m[2][0] = 2 * (x * z - w * y);
    a->m[2][1] = 2 * (y * z + w * x);
    a->m[2][2] = 1 - 2 * (x * x + y * y);
    for (i = 0; i < 3; i++) a->m[i][3] = (2 * xu_rng_unit(r) - 1) * 0.0625;
}

void cht_random_box(xu_rng *r, int chain, cbx_box *b)
{
    int j;
    for (j = 0; j < 3; j++) {
        double c = (2 * xu_rng_unit(r) - 1) * 8;
        int e = xu_rng_int(r, -3, 2); /* drawn first (argument order: see exact_gen.c) */
        double h = ldexp(1 + xu_rng_unit(r), e);
        if (j == 2 && chain % 5 == 4) h = 0;
        b->lo[j] = c - h;
        b->hi[j] = c + h;
    }
}

/* ---------------------------------------------------------------------- */
/* cbx_transform_box_chain's special cases                                */
/* ---------------------------------------------------------------------- */

/* the whole space: every axis [-inf, +inf] */
static int is_whole(const cbx_box *b)
{
    int i;
    for (i = 0; i < 3; i++)
        if (!(isinf(b->lo[i]) && b->lo[i] < 0 && isinf(b->hi[i]) && b->hi[i] > 0)) return 0;
    return 1;
}

/* cbx_transform_box_chain's special cases; returns the number failed. */
int cht_chain_special(xu_rng *r)
{
    cbx_prepared pr[3];
    cbx_affine a;
    cbx_box b = { { -1, -2, -3 }, { 1, 2, 3 } }, o, e = b, ref;
    cbx_status st;
    int i, bad = 0;
    for (i = 0; i < 3; i++) {
        cht_random_step(r, &a);
        cbx_prepare(&a, &pr[i]);
    }
    cht_k_checked[K_CHSPEC]++;                       /* no map */
    if (cbx_transform_box_chain(pr, 0, &b, &o) != CBX_EINVAL || !is_whole(&o)) {
        cht_report(K_CHSPEC, -1, 0, "n = 0 is not CBX_EINVAL with the whole space"); bad++;
    }
    cht_k_checked[K_CHSPEC]++;                       /* NaN in the box */
    e.lo[1] = NAN;
    if (cbx_transform_box_chain(pr, 3, &e, &o) != CBX_EINVAL || !is_whole(&o)) {
        cht_report(K_CHSPEC, -1, 0, "a NaN box is not CBX_EINVAL with the whole space"); bad++;
    }
    cht_k_checked[K_CHSPEC]++;                       /* empty box */
    e = b; e.lo[2] = 4;
    st = cbx_transform_box_chain(pr, 3, &e, &o);
    if (st != CBX_EMPTY || !(o.lo[0] == INFINITY && o.hi[0] == -INFINITY)) {
        cht_report(K_CHSPEC, -1, 0, "an empty box is not CBX_EMPTY with the empty box"); bad++;
    }
    cht_k_checked[K_CHSPEC]++;                       /* NaN in the middle map */
    a = pr[1].a; a.m[1][2] = NAN;
    cbx_prepare(&a, &pr[1]);
    if (cbx_transform_box_chain(pr, 3, &b, &o) != CBX_EINVAL || !is_whole(&o)) {
        cht_report(K_CHSPEC, -1, 0, "a NaN map is not CBX_EINVAL with the whole space"); bad++;
    }
    cht_k_checked[K_CHSPEC]++;                       /* out of range, then one more map */
    memset(&a, 0, sizeof a);
    a.m[0][0] = a.m[1][1] = a.m[2][2] = 0x1p1000;
    cbx_prepare(&a, &pr[2]);
    cbx_prepare(&a, &pr[1]);
    st = cbx_transform_box_chain(pr, 3, &b, &o);
    if (st != CBX_ERANGE || !is_whole(&o)) {
        cht_report(K_CHSPEC, -1, 0, "a chain out of range is not CBX_ERANGE with the whole space");
        bad++;
    }
    cht_k_checked[K_CHSPEC]++;                       /* in place, the same as apart */
    cht_random_step(r, &a);
    cbx_prepare(&a, &pr[1]);
    st = cbx_transform_box_chain(pr, 3, &b, &ref);
    o = b;
    if (cbx_transform_box_chain(pr, 3, &o, &o) != st || memcmp(&o, &ref, sizeof o) != 0) {
        cht_report(K_CHSPEC, -1, 0, "in place (out == in) differs from out apart"); bad++;
    }
    return bad;
}

/* ---------------------------------------------------------------------- */
/* Statistics                                                             */
/* ---------------------------------------------------------------------- */

/* a / b for the statistics; +inf where a width is infinite (a chain that
 * left the domain), so that no NaN reaches the sort */
double cht_ratio(double a, double b)
{
    double r = a / b;
    return isnan(r) ? HUGE_VAL : r;
}

static int cmp_d(const void *p, const void *q)
{
    double a = *(const double *)p, b = *(const double *)q;
    return (a > b) - (a < b);
}

/* max and median of v[0..n-1] (sorted in place, so v[0] is then the
 * min; NaN never occurs) */
void cht_max_med(double *v, int n, double *mx, double *med)
{
    qsort(v, (size_t)n, sizeof *v, cmp_d);
    *mx = v[n - 1];
    *med = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
