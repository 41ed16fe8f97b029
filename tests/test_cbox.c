/*
 * test_cbox [N] [seed]: the centre/half-diagonal functions against exact
 * rational arithmetic (GMP).
 *
 *   cbx_transform_cbox  (a, (c, h)) -> (c', h')   Arvo's Fig. 2
 *   cbx_box_to_cbox     [lo, hi]    -> (c, h)
 *   cbx_cbox_to_box     (c, h)      -> [lo, hi]
 *
 * A cbx_cbox (c, h) means the exact real box [c - h, c + h].  For each
 * function: first a table of hand-picked hard cases (each printed), then N
 * random cases (default 300000) from a fixed-seed splitmix64 generator.
 * Every case checks: the status equals the one decided exactly from the
 * contract in certbox.h, every output field is written (NaN pre-fill),
 * EINVAL / EMPTY outputs are exactly as specified, lost (out-of-domain)
 * axes are exactly the whole line, the other axes are finite and contain the exact
 * image (exact comparison on integers scaled by 2^2148), the inputs are not
 * modified.  Tightness is measured in units of u*S + eta (u = 2^-53,
 * eta = 2^-1074, S the scale of each function, below), printed as max and
 * mean.  Check "sanity<=64": an end more than 64 units out fails on axes
 * with u*S >= 2^-1000.  Check "tiny-abs": below that scale absolute terms
 * of the widening (2^-1065, ...) dominate, and an end fails only when its
 * gap is above both 64 units and 2^-1000.  Statistics keep the axes with
 * u*S < 2^-1000 apart.
 *
 * transform_cbox also checks the 8 corners c_j -+ h_j with plain mpq_t
 * (hard cases and every CORNER_EVERY-th random case), that the corners'
 * min / max equal the fixed-point C - H / C + H, and the tightness of the
 * contract in specs/cbx_spec.h (cbox_tight): each end within
 * 12 u S + 2^-1065 of the exact end.
 *
 * transform_cbox drops zero-coefficient columns (exact_util.h, specs:
 * crow_dfull): per output axis, kind A (full row: every input finite and
 * in the domain) is the kernel as above; kind D (not full, but full once
 * every column with m_j == 0, also -0.0, takes c_j = h_j = 0 whatever c_j,
 * h_j are, +-inf included) is checked the same way on the DROPPED row: out
 * finite with h >= 0, the exact image contained (a dropped column adds
 * exactly 0), the 8 mpq corners of the dropped box inside, and each end
 * within 12 u S' + 2^-1065 of the exact end, S' = |t| + sum_j |m_j c_j'|
 * + |m_j h_j'| (checks D-finite, D-contain, D-spec-tight, D-corners,
 * D-cross-CH); kind W (still not full) must be exactly c = 0, h = +inf and
 * is a loss (check lost-axes).  CBX_OK iff no axis is W.  A table of
 * hand-picked zero-column cases (zero coefficients against c or h = +-inf,
 * out-of-domain magnitudes in a zero column, -0.0, mixes with an infinite
 * nonzero column, NaN / h < 0 in a zero column) and N/3 random zero-column
 * cases (corners on every 5th) exercise D; the axes are counted by kind.
 *
 * cbx_box_to_cbox is EMPTY when some axis has no real point: hi < lo,
 * lo = +inf or hi = -inf (xu_is_empty); a half-line or the whole line is
 * not empty but outside the domain (that axis c = 0, h = +inf).
 *
 * Round trips: box -> cbox -> box contains the original box, and
 * cbox -> box -> cbox contains the original cbox (exactly), whenever both
 * steps return CBX_OK.
 *
 * The last line is "N passed, M failed" (cases); exit status 1 on failure.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <math.h>
#include <time.h>

#include "certbox.h"
#include "exact_util.h"
#include "cbox_parts.h" /* the checks, the hard cases, the generators */

#ifndef CORNER_EVERY
#define CORNER_EVERY 50
#endif

/* ---------------------------------------------------------------------- */
/* Drivers                                                                */
/* ---------------------------------------------------------------------- */

static void tc_log(long id, const char *what, const cbx_affine *a,
                   const cbx_cbox *in, const cbx_cbox *out, const verdict *v)
{
    if (!cbt_log_head(what, id, v)) return;
    cbt_print_affine(a);
    cbt_print_cbox("in ", in);
    cbt_print_cbox("out", out);
}

/* One table of hand-picked cases; each is also checked against the
 * table's own status, lost axes and kinds. */
static void run_tc_table(ctx *k, group *g, const char *title, const tc_case *tab, int n)
{
    int h;
    printf("-- cbx_transform_cbox: %s (%d; kinds per axis: A full row, D zero columns "
           "dropped, W lost) --\n", title, n);
    for (h = 0; h < n; h++) {
        const tc_case *t = &tab[h];
        cbx_cbox out;
        verdict v;
        double mx;
        int oob;
        char kinds[4];
        cbt_tc_run(k, g, &t->a, &t->in, &out, 1, &v, &mx);
        if (cbt_tc_expected(&t->a, &t->in, &oob, kinds) != t->expect || oob != t->oob
            || strcmp(kinds, t->kinds) != 0) {
            if (!v.failed)
                snprintf(v.why, sizeof v.why, "table says %s/lost %d/%s, oracle lost %d/%s",
                         cbx_status_name(t->expect), t->oob, t->kinds, oob, kinds);
            v.failed = 1;
        }
        cbt_g_add(g, &v);
        printf("  %-52s %-10s %s  max excess %7.3f  %s\n", t->name,
               cbx_status_name(v.got), kinds, mx, v.failed ? "FAIL" : "ok");
        if (v.failed) tc_log(h, title, &t->a, &t->in, &out, &v);
    }
}

static void run_tc(ctx *k, group *gh, group *gd, group *gr, group *grd, long n,
                   uint64_t seed)
{
    long c;
    xu_rng r;
    cbt_fail_logs = 0; /* MAX_FAIL_LOGS per function */
    run_tc_table(k, gh, "hard cases", cbt_tc_hard, cbt_n_tc_hard);
    run_tc_table(k, gd, "zero columns dropped", cbt_tc_drop, cbt_n_tc_drop);
    r.s = seed;
    for (c = 0; c < n; c++) {
        cbx_affine a;
        cbx_cbox in, out;
        verdict v;
        double mx;
        cbt_gen_tc_case(&r, &a, &in);
        if (cbt_tc_run(k, gr, &a, &in, &out, c % CORNER_EVERY == 0, &v, &mx))
            tc_log(c, "transform_cbox random", &a, &in, &out, &v);
        cbt_g_add(gr, &v);
    }
    /* zero-column cases: a third of N, corners on every 5th */
    r.s = seed ^ UINT64_C(0xd00dd00dd00d);
    for (c = 0; c < n / 3; c++) {
        cbx_affine a;
        cbx_cbox in, out;
        verdict v;
        double mx;
        cbt_gen_tc_drop_case(&r, &a, &in);
        if (cbt_tc_run(k, grd, &a, &in, &out, c % 5 == 0, &v, &mx))
            tc_log(c, "transform_cbox random zero-column", &a, &in, &out, &v);
        cbt_g_add(grd, &v);
    }
}

static void b2c_log(long id, const char *what, const cbx_box *in,
                    const cbx_cbox *out, const verdict *v)
{
    if (!cbt_log_head(what, id, v)) return;
    xu_print_box(stdout, "in ", in);
    cbt_print_cbox("out", out);
}

static void c2b_log(long id, const char *what, const cbx_cbox *in,
                    const cbx_box *out, const verdict *v)
{
    if (!cbt_log_head(what, id, v)) return;
    cbt_print_cbox("in ", in);
    xu_print_box(stdout, "out", out);
}

static void run_b2c(ctx *k, group *gh, group *gr, long n, uint64_t seed)
{
    int h;
    long c;
    xu_rng r;
    cbt_fail_logs = 0; /* MAX_FAIL_LOGS per function */
    printf("-- cbx_box_to_cbox: hard cases (%d) --\n", cbt_n_b2c_hard);
    for (h = 0; h < cbt_n_b2c_hard; h++) {
        const b2c_case *t = &cbt_b2c_hard[h];
        cbx_cbox out;
        verdict v;
        double mx;
        int oob;
        cbt_b2c_run(k, gh, &t->in, &out, &v, &mx);
        if (v.got == CBX_OK && v.expected == CBX_OK) cbt_roundtrip_box(k, gh, &t->in, &out, &v);
        if (cbt_b2c_expected(&t->in, &oob) != t->expect || oob != t->oob) {
            if (!v.failed)
                snprintf(v.why, sizeof v.why, "table says %s/oob %d, oracle oob %d",
                         cbx_status_name(t->expect), t->oob, oob);
            v.failed = 1;
        }
        cbt_g_add(gh, &v);
        printf("  %-44s %-10s max excess %7.3f  %s\n", t->name,
               cbx_status_name(v.got), mx, v.failed ? "FAIL" : "ok");
        if (v.failed) b2c_log(h, "box_to_cbox hard", &t->in, &out, &v);
    }
    r.s = seed ^ UINT64_C(0xb2cb2cb2c);
    for (c = 0; c < n; c++) {
        cbx_box in;
        cbx_cbox out;
        verdict v;
        double mx;
        cbt_gen_b2c_case(&r, &in);
        cbt_b2c_run(k, gr, &in, &out, &v, &mx);
        if (v.got == CBX_OK && v.expected == CBX_OK) cbt_roundtrip_box(k, gr, &in, &out, &v);
        if (v.failed) b2c_log(c, "box_to_cbox random", &in, &out, &v);
        cbt_g_add(gr, &v);
    }
}

static void run_c2b(ctx *k, group *gh, group *gr, long n, uint64_t seed)
{
    int h;
    long c;
    xu_rng r;
    cbt_fail_logs = 0; /* MAX_FAIL_LOGS per function */
    printf("-- cbx_cbox_to_box: hard cases (%d) --\n", cbt_n_c2b_hard);
    for (h = 0; h < cbt_n_c2b_hard; h++) {
        const c2b_case *t = &cbt_c2b_hard[h];
        cbx_box out;
        verdict v;
        double mx;
        int oob;
        cbt_c2b_run(k, gh, &t->in, &out, &v, &mx);
        if (v.got == CBX_OK && v.expected == CBX_OK) cbt_roundtrip_cbox(k, gh, &t->in, &out, &v);
        if (cbt_c2b_expected(&t->in, &oob) != t->expect || oob != t->oob) {
            if (!v.failed)
                snprintf(v.why, sizeof v.why, "table says %s/oob %d, oracle oob %d",
                         cbx_status_name(t->expect), t->oob, oob);
            v.failed = 1;
        }
        cbt_g_add(gh, &v);
        printf("  %-44s %-10s max excess %7.3f  %s\n", t->name,
               cbx_status_name(v.got), mx, v.failed ? "FAIL" : "ok");
        if (v.failed) c2b_log(h, "cbox_to_box hard", &t->in, &out, &v);
    }
    r.s = seed ^ UINT64_C(0xc2bc2bc2b);
    for (c = 0; c < n; c++) {
        cbx_cbox in;
        cbx_box out;
        verdict v;
        double mx;
        cbt_gen_c2b_case(&r, &in);
        cbt_c2b_run(k, gr, &in, &out, &v, &mx);
        if (v.got == CBX_OK && v.expected == CBX_OK) cbt_roundtrip_cbox(k, gr, &in, &out, &v);
        if (v.failed) c2b_log(c, "cbox_to_box random", &in, &out, &v);
        cbt_g_add(gr, &v);
    }
}

int main(int argc, char **argv)
{
    long n = (long)xu_arg_num(argc, argv, 1, 300000ULL, "[N] [seed]");
    uint64_t seed = (uint64_t)xu_arg_num(argc, argv, 2, 0xcb0c5eed2024ULL, "[N] [seed]");
    ctx k;
    group g[8];
    long passed = 0, failed = 0;
    int i;
    clock_t t0 = clock();

    cbt_ctx_init(&k);
    cbt_g_init(&g[0], "cbx_transform_cbox, hard cases", TC_UNITS);
    cbt_g_init(&g[1], "cbx_transform_cbox, zero columns dropped (hand-picked)", TC_UNITS);
    cbt_g_init(&g[2], "cbx_transform_cbox, random cases", TC_UNITS);
    cbt_g_init(&g[3], "cbx_transform_cbox, random zero-column cases", TC_UNITS);
    cbt_g_init(&g[4], "cbx_box_to_cbox, hard cases", "u*max(|lo|,|hi|) + eta (sanity on the mean of both ends)");
    cbt_g_init(&g[5], "cbx_box_to_cbox, random cases", "u*max(|lo|,|hi|) + eta (sanity on the mean of both ends)");
    cbt_g_init(&g[6], "cbx_cbox_to_box, hard cases", "u*(|c| + h) + eta");
    cbt_g_init(&g[7], "cbx_cbox_to_box, random cases", "u*(|c| + h) + eta");

    printf("test_cbox: N = %ld random cases per function, seed 0x%llx, conversion "
           "domain 2^%d, sanity bound %g units, corners every %d-th random case\n\n",
           n, (unsigned long long)seed, CONV_EMAX, SANITY, CORNER_EVERY);
    run_tc(&k, &g[0], &g[1], &g[2], &g[3], n, seed);
    run_b2c(&k, &g[4], &g[5], n, seed);
    run_c2b(&k, &g[6], &g[7], n, seed);

    printf("\n");
    for (i = 0; i < 8; i++) {
        cbt_g_print(&g[i]);
        passed += g[i].cases - g[i].failed;
        failed += g[i].failed;
    }
    printf("spec-tight = cbox_tight of specs/cbx_spec.h: each end within "
           "12 u S + 2^-1065 of the exact end\n");
    printf("D-* = the same checks on a D axis, on the dropped row (c_j = h_j = 0 where "
           "m_j == 0): S' instead of S\n");
    printf("CPU time %.2f s\n", (double)(clock() - t0) / CLOCKS_PER_SEC);
    cbt_ctx_clear(&k);
    printf("%ld passed, %ld failed\n", passed, failed);
    return failed ? 1 : 0;
}
