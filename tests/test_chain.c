/*
 * test_chain [steps=1000] [chains=20] [seed=1]: stability of repeated
 * transforms.
 *
 * Each chain starts from a random box B_0 (centre in [-8, 8], half-widths
 * in [2^-3, 2^3), every 5th chain flat on axis 2) and applies `steps`
 * random rigid maps A_k (a random unit quaternion -> 3x3 rotation computed
 * in doubles, so only nearly orthogonal; plus a translation with entries in
 * [-1/16, 1/16]), each output feeding the next step, in two forms:
 *   box chain:   B_{k+1} = cbx_transform_box(A_k, B_k);
 *   cbox chain:  C_0 = cbx_box_to_cbox(B_0), C_{k+1} = cbx_transform_cbox(A_k, C_k).
 * The map actually applied is the one made of the doubles, taken exactly.
 *
 * Checks (every one exact, GMP):
 *   start      cbx_box_to_cbox(B_0) is CBX_OK and [c - h, c + h] holds B_0;
 *   box-step   every step of the box chain with xu_run_case (exact_util):
 *              the status equals the exact oracle's, no output field left
 *              unset (NaN pre-fill), every end as the rules of exact_util.h
 *              say (rows outside the domain: each end proven from its
 *              vertex or exactly infinite), and on in-domain (full) rows
 *              the exact image of the step's input box B_k under A_k is
 *              contained in B_{k+1} (fixed-point bounds AND all 8 corners
 *              with mpq_t) and within the proven tightness 12 u S + 2^-1065;
 *   cbox-step  every step of the cbox chain: status equals the exact oracle's
 *              (exact_util's cbox rules: full rows A, rows full once their
 *              zero-coefficient columns are dropped D, lost rows W), no NaN
 *              left, lost axes c = 0, h = +inf, and on the others the 8
 *              corners c_j -+ h_j of C_k (for D, of the dropped box: c_j =
 *              h_j = 0 where the coefficient is 0) mapped by A_k exactly
 *              (mpq_t) lie in [c' - h', c' + h'];
 *   box-comp / cbox-comp  the composed map P_k = A_{k-1} o ... o A_0 is
 *              kept exactly as mpq_t (the double matrices multiplied as
 *              rationals, every one of the `steps` steps), and at every
 *              checkpoint (steps 1, 2, 3, 5, 10, 20, 50, then every
 *              CHECK_EVERY = 100 steps, and after the last step) the 8
 *              corners of the ORIGINAL box B_0 mapped exactly by P_k lie in
 *              B_k and in [c - h, c + h] of C_k.  Nothing is skipped: the
 *              exact composition of all 1000 steps stays fast (its time and
 *              the size of its numbers are printed).  The early checkpoints
 *              are the sharp ones: later the boxes are so much wider than
 *              the exact image (the wrapping effect, below) that this check
 *              only confirms soundness, it could no longer see a wrong P.
 *   chain-fn   at every checkpoint, cbx_transform_box_chain on the maps so
 *              far (last applied first) and B_0: the same box as the box
 *              chain's B_k, bit for bit, the status the most severe of the
 *              steps', and the 8 corners of B_0 mapped by the exact
 *              composition inside it (its proven promise, checked exactly);
 *   chain-spec its special cases: no map (CBX_EINVAL, whole space), a NaN
 *              in the box or in one map of the chain (CBX_EINVAL, whole
 *              space), an empty box (CBX_EMPTY, lo +inf, hi -inf), two
 *              scalings by 2^1000 and one more map (CBX_ERANGE, the whole
 *              space), the result written in place (out == in).
 * Growth, reported per axis as max / median over the chains: the final box
 * width of the box chain divided by the width 2h of the cbox chain, and
 * divided by the width of the exact bound of P(B_0) (the naive exact
 * box, sum_j |P_ij| (hi_j - lo_j), a rational); also cbox / exact, the
 * per-step factor (box / exact)^(1 / steps), and box / exact at every
 * checkpoint.  A chain whose box leaves the proven domain (ERANGE, the
 * widths grow geometrically) is reported with the step; its widths are
 * then infinite.
 * The last line is "N passed, M failed" (checked steps and checkpoints);
 * exit status 1 on failure.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <time.h>

#include "certbox.h"
#include "exact_util.h"

#define CHECK_EVERY 100

/* Checkpoints before the first hundred steps, where the boxes are still
 * only a few times wider than the exact image (a composition error would
 * show there; later the wrapping effect hides it). */
static int early_checkpoint(long s)
{
    return s == 1 || s == 2 || s == 3 || s == 5 || s == 10 || s == 20 || s == 50;
}
#define MAX_FAIL_LOGS 20

enum { K_START, K_BOX, K_CBOX, K_BOXC, K_CBOXC, K_CHAIN, K_CHSPEC, NK };
static const char *const k_name[NK] = { "start", "box-step", "cbox-step", "box-comp", "cbox-comp",
                                        "chain-fn", "chain-spec" };
static const char *const k_unit[NK] = { "chains", "steps", "steps", "checkpts", "checkpts",
                                        "checkpts", "cases" };
static long k_checked[NK], k_failed[NK];
static long logs;

typedef struct ctx {
    xu_exact x;
    mpq_t P[3][4], N[3][4];     /* composed exact map, and the next one   */
    mpq_t q, qa, qb, qlo, qhi;
    mpq_t prod[3][3][2];        /* P_ij * lo_j / hi_j of the original box */
} ctx;

static void ctx_init(ctx *k)
{
    int i, j, s;
    xu_init(&k->x);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) {
            mpq_init(k->P[i][j]);
            mpq_init(k->N[i][j]);
        }
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            for (s = 0; s < 2; s++) mpq_init(k->prod[i][j][s]);
    mpq_inits(k->q, k->qa, k->qb, k->qlo, k->qhi, (mpq_ptr)0);
}

static void ctx_clear(ctx *k)
{
    int i, j, s;
    xu_clear(&k->x);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) {
            mpq_clear(k->P[i][j]);
            mpq_clear(k->N[i][j]);
        }
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            for (s = 0; s < 2; s++) mpq_clear(k->prod[i][j][s]);
    mpq_clears(k->q, k->qa, k->qb, k->qlo, k->qhi, (mpq_ptr)0);
}

static void report(int kind, int chain, long step, const char *why)
{
    k_failed[kind]++;
    if (logs++ < MAX_FAIL_LOGS)
        printf("FAIL: %s, chain %d step %ld: %s\n", k_name[kind], chain, step, why);
}

/* ---------------------------------------------------------------------- */
/* Random maps                                                            */
/* ---------------------------------------------------------------------- */

/* A uniformly random unit quaternion (rejection in the 4-ball), turned
 * into a rotation matrix in double arithmetic, plus a small translation. */
static void random_step(xu_rng *r, cbx_affine *a)
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

static void random_box(xu_rng *r, int chain, cbx_box *b)
{
    int j;
    for (j = 0; j < 3; j++) {
        double c = (2 * xu_rng_unit(r) - 1) * 8;
        int e = xu_rng_int(r, -3, 2); /* drawn first (argument order: see exact_util.c) */
        double h = ldexp(1 + xu_rng_unit(r), e);
        if (j == 2 && chain % 5 == 4) h = 0;
        b->lo[j] = c - h;
        b->hi[j] = c + h;
    }
}

/* ---------------------------------------------------------------------- */
/* Exact composition: P <- A P                                            */
/* ---------------------------------------------------------------------- */

static void compose(ctx *k, const cbx_affine *a)
{
    int i, j, l;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) {
            if (j == 3) mpq_set_d(k->N[i][j], a->m[i][3]);
            else mpq_set_ui(k->N[i][j], 0, 1);
            for (l = 0; l < 3; l++) {
                mpq_set_d(k->q, a->m[i][l]);
                mpq_mul(k->q, k->q, k->P[l][j]);
                mpq_add(k->N[i][j], k->N[i][j], k->q);
            }
        }
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) mpq_swap(k->P[i][j], k->N[i][j]);
}

static void set_identity(ctx *k)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) mpq_set_ui(k->P[i][j], i == j, 1);
}

static size_t bits_q(const mpq_t q)
{
    size_t a = mpz_sizeinbase(mpq_numref(q), 2), b = mpz_sizeinbase(mpq_denref(q), 2);
    return a > b ? a : b;
}

static size_t max_bits(ctx *k)
{
    size_t m = 0, b;
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++)
            if ((b = bits_q(k->P[i][j])) > m) m = b;
    return m;
}

/* prod[i][j][0/1] = P_ij * lo_j / hi_j of the original box B_0 */
static void fill_prod(ctx *k, const cbx_box *b0)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            mpq_set_d(k->q, b0->lo[j]);
            mpq_mul(k->prod[i][j][0], k->P[i][j], k->q);
            mpq_set_d(k->q, b0->hi[j]);
            mpq_mul(k->prod[i][j][1], k->P[i][j], k->q);
        }
}

/* The 8 corners of B_0 mapped exactly by P against [qlo, qhi] on axis i
 * (call fill_prod first; an infinite end, lo_inf / hi_inf, contains
 * everything).  Returns the number of failed inequalities. */
static int corners_outside(ctx *k, int i, int lo_inf, int hi_inf)
{
    unsigned c;
    int j, bad = 0;
    for (c = 0; c < 8; c++) {
        mpq_set(k->q, k->P[i][3]);
        for (j = 0; j < 3; j++) mpq_add(k->q, k->q, k->prod[i][j][(c >> j) & 1u]);
        if (!lo_inf && mpq_cmp(k->qlo, k->q) > 0) bad++;
        if (!hi_inf && mpq_cmp(k->q, k->qhi) > 0) bad++;
    }
    return bad;
}

/* P(B_0) inside the box b?  Returns the number of failures. */
static int composed_box_failures(ctx *k, const cbx_box *b)
{
    int i, bad = 0;
    for (i = 0; i < 3; i++) {
        int lo_inf = isinf(b->lo[i]) && b->lo[i] < 0, hi_inf = isinf(b->hi[i]) && b->hi[i] > 0;
        if ((!lo_inf && !isfinite(b->lo[i])) || (!hi_inf && !isfinite(b->hi[i]))) {
            bad++; /* NaN, lo = +inf or hi = -inf: nothing is inside */
            continue;
        }
        if (!lo_inf) mpq_set_d(k->qlo, b->lo[i]);
        if (!hi_inf) mpq_set_d(k->qhi, b->hi[i]);
        bad += corners_outside(k, i, lo_inf, hi_inf);
    }
    return bad;
}

/* P(B_0) inside the real box [c - h, c + h] (h = +inf: the whole line)? */
static int composed_cbox_failures(ctx *k, const cbx_cbox *cb)
{
    int i, bad = 0;
    for (i = 0; i < 3; i++) {
        if (isinf(cb->h[i]) && cb->h[i] > 0 && !isnan(cb->c[i])) continue;
        if (!isfinite(cb->c[i]) || !isfinite(cb->h[i])) {
            bad++;
            continue;
        }
        mpq_set_d(k->qa, cb->c[i]);
        mpq_set_d(k->qb, cb->h[i]);
        mpq_sub(k->qlo, k->qa, k->qb);
        mpq_add(k->qhi, k->qa, k->qb);
        bad += corners_outside(k, i, 0, 0);
    }
    return bad;
}

/* Exact width of the bound of P(B_0) on axis i: sum_j |P_ij| (hi_j - lo_j). */
static double exact_width(ctx *k, const cbx_box *b0, int i)
{
    int j;
    mpq_set_ui(k->qa, 0, 1);
    for (j = 0; j < 3; j++) {
        mpq_set_d(k->q, b0->hi[j]);
        mpq_set_d(k->qb, b0->lo[j]);
        mpq_sub(k->q, k->q, k->qb);
        mpq_abs(k->qb, k->P[i][j]);
        mpq_mul(k->q, k->q, k->qb);
        mpq_add(k->qa, k->qa, k->q);
    }
    return mpq_get_d(k->qa);
}

/* ---------------------------------------------------------------------- */
/* One step of the cbox chain, checked                                    */
/* ---------------------------------------------------------------------- */

static int cbox_step(ctx *k, const cbx_affine *a, const cbx_cbox *in, cbx_cbox *out,
                     char *why, size_t nwhy)
{
    cbx_status got, want;
    int i, j, mask = 0;
    unsigned c;
    for (i = 0; i < 3; i++) out->c[i] = out->h[i] = NAN;
    got = cbx_transform_cbox(a, in, out);
    want = xu_cbox_expected_status(a, in);
    if (want == CBX_OK || want == CBX_ERANGE) mask = xu_cbox_loss_mask(a, in);
    if (got != want) {
        snprintf(why, nwhy, "status %s, expected %s", cbx_status_name(got), cbx_status_name(want));
        return 1;
    }
    for (i = 0; i < 3; i++)
        if (isnan(out->c[i]) || isnan(out->h[i])) {
            snprintf(why, nwhy, "NaN left in out axis %d", i);
            return 1;
        }
    if (want != CBX_OK && want != CBX_ERANGE) {
        snprintf(why, nwhy, "unexpected status %s in a chain", cbx_status_name(want));
        return 1;
    }
    for (i = 0; i < 3; i++) {
        cbx_cbox d;  /* the box row i is checked on: zero columns dropped */
        if (mask & (1 << i)) {
            if (!(out->c[i] == 0 && isinf(out->h[i]) && out->h[i] > 0)) {
                snprintf(why, nwhy, "axis %d lost (W) but not c = 0, h = +inf", i);
                return 1;
            }
            continue;
        }
        /* kind A: the same box; kind D: c_j = h_j = 0 where m_ij == 0 */
        xu_cbox_dropped(a, in, i, &d);
        if (!isfinite(out->c[i]) || !isfinite(out->h[i])) {
            snprintf(why, nwhy, "axis %d (A or D) but not finite", i);
            return 1;
        }
        mpq_set_d(k->qa, out->c[i]);
        mpq_set_d(k->qb, out->h[i]);
        mpq_sub(k->qlo, k->qa, k->qb);
        mpq_add(k->qhi, k->qa, k->qb);
        for (c = 0; c < 8; c++) {
            mpq_set_d(k->q, a->m[i][3]);
            for (j = 0; j < 3; j++) {
                mpq_set_d(k->qa, d.c[j]);
                mpq_set_d(k->qb, d.h[j]);
                if ((c >> j) & 1u) mpq_add(k->qa, k->qa, k->qb);
                else mpq_sub(k->qa, k->qa, k->qb);
                mpq_set_d(k->qb, a->m[i][j]);
                mpq_mul(k->qa, k->qa, k->qb);
                mpq_add(k->q, k->q, k->qa);
            }
            if (mpq_cmp(k->qlo, k->q) > 0 || mpq_cmp(k->q, k->qhi) > 0) {
                snprintf(why, nwhy, "axis %d: corner %u's exact image outside [c - h, c + h]", i, c);
                return 1;
            }
        }
    }
    return 0;
}

/* ---------------------------------------------------------------------- */
/* Statistics                                                             */
/* ---------------------------------------------------------------------- */

/* a / b for the statistics; +inf where a width is infinite (a chain that
 * left the domain), so that no NaN reaches the sort */
static int is_whole(const cbx_box *b)
{
    int i;
    for (i = 0; i < 3; i++)
        if (!(isinf(b->lo[i]) && b->lo[i] < 0 && isinf(b->hi[i]) && b->hi[i] > 0)) return 0;
    return 1;
}

/* cbx_transform_box_chain's special cases; returns the number failed. */
static int chain_special(xu_rng *r)
{
    cbx_prepared pr[3];
    cbx_affine a;
    cbx_box b = { { -1, -2, -3 }, { 1, 2, 3 } }, o, e = b, ref;
    cbx_status st;
    int i, bad = 0;
    for (i = 0; i < 3; i++) {
        random_step(r, &a);
        cbx_prepare(&a, &pr[i]);
    }
    k_checked[K_CHSPEC]++;                       /* no map */
    if (cbx_transform_box_chain(pr, 0, &b, &o) != CBX_EINVAL || !is_whole(&o)) {
        report(K_CHSPEC, -1, 0, "n = 0 is not CBX_EINVAL with the whole space"); bad++;
    }
    k_checked[K_CHSPEC]++;                       /* NaN in the box */
    e.lo[1] = NAN;
    if (cbx_transform_box_chain(pr, 3, &e, &o) != CBX_EINVAL || !is_whole(&o)) {
        report(K_CHSPEC, -1, 0, "a NaN box is not CBX_EINVAL with the whole space"); bad++;
    }
    k_checked[K_CHSPEC]++;                       /* empty box */
    e = b; e.lo[2] = 4;
    st = cbx_transform_box_chain(pr, 3, &e, &o);
    if (st != CBX_EMPTY || !(o.lo[0] == INFINITY && o.hi[0] == -INFINITY)) {
        report(K_CHSPEC, -1, 0, "an empty box is not CBX_EMPTY with the empty box"); bad++;
    }
    k_checked[K_CHSPEC]++;                       /* NaN in the middle map */
    a = pr[1].a; a.m[1][2] = NAN;
    cbx_prepare(&a, &pr[1]);
    if (cbx_transform_box_chain(pr, 3, &b, &o) != CBX_EINVAL || !is_whole(&o)) {
        report(K_CHSPEC, -1, 0, "a NaN map is not CBX_EINVAL with the whole space"); bad++;
    }
    k_checked[K_CHSPEC]++;                       /* out of range, then one more map */
    memset(&a, 0, sizeof a);
    a.m[0][0] = a.m[1][1] = a.m[2][2] = 0x1p1000;
    cbx_prepare(&a, &pr[2]);
    cbx_prepare(&a, &pr[1]);
    st = cbx_transform_box_chain(pr, 3, &b, &o);
    if (st != CBX_ERANGE || !is_whole(&o)) {
        report(K_CHSPEC, -1, 0, "a chain out of range is not CBX_ERANGE with the whole space"); bad++;
    }
    k_checked[K_CHSPEC]++;                       /* in place, the same as apart */
    random_step(r, &a);
    cbx_prepare(&a, &pr[1]);
    st = cbx_transform_box_chain(pr, 3, &b, &ref);
    o = b;
    if (cbx_transform_box_chain(pr, 3, &o, &o) != st || memcmp(&o, &ref, sizeof o) != 0) {
        report(K_CHSPEC, -1, 0, "in place (out == in) differs from out apart"); bad++;
    }
    return bad;
}

static double ratio(double a, double b)
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
static void max_med(double *v, int n, double *mx, double *med)
{
    qsort(v, (size_t)n, sizeof *v, cmp_d);
    *mx = v[n - 1];
    *med = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

static void usage(char **argv)
{
    fprintf(stderr, "usage: %s [steps=1000] [chains=20] [seed=1]  (steps, chains >= 1)\n",
            argv[0]);
    exit(2);
}

/* argv[k] as a number >= vmin, dflt if absent; a typo is an error */
static unsigned long long arg_num(int argc, char **argv, int k, unsigned long long dflt,
                                  unsigned long long vmin)
{
    char *end;
    unsigned long long v;
    if (argc <= k) return dflt;
    v = strtoull(argv[k], &end, 0);
    if (*argv[k] == '\0' || *argv[k] == '-' || *end != '\0' || v < vmin) usage(argv);
    return v;
}

int main(int argc, char **argv)
{
    long steps = (long)arg_num(argc, argv, 1, 1000, 1);
    int chains = (int)arg_num(argc, argv, 2, 20, 1);
    uint64_t seed = (uint64_t)arg_num(argc, argv, 3, 1, 0);
    int ncp = 0, cp;
    long *cp_at;
    double *r_bc[4], *r_be[4], *r_ce[4], *r_step, *cp_be;
    double comp_sec = 0, mx, med;
    size_t bits_max = 0;
    long total = 0, failed = 0;
    int ch, i, n_left = 0;
    ctx k;
    xu_rng rng;
    clock_t t0 = clock();
    cbx_prepared *pr, *rev;

    if (argc > 4 || steps > 100000000L || chains > 1000000) usage(argv);
    for (i = 0; i < 4; i++) {
        r_bc[i] = malloc(3 * (size_t)chains * sizeof(double));
        r_be[i] = malloc(3 * (size_t)chains * sizeof(double));
        r_ce[i] = malloc(3 * (size_t)chains * sizeof(double));
    }
    r_step = malloc((size_t)chains * 3 * sizeof(double));
    cp_at = malloc(((size_t)steps / CHECK_EVERY + 16) * sizeof *cp_at);
    if (!cp_at) return 2;
    for (i = 1; i <= steps; i++)
        if (early_checkpoint(i) || i % CHECK_EVERY == 0 || i == steps) cp_at[ncp++] = i;
    cp_be = malloc((size_t)ncp * 3 * (size_t)chains * sizeof(double));
    for (i = 0; i < 4; i++)
        if (!r_bc[i] || !r_be[i] || !r_ce[i]) return 2;
    if (!r_step || !cp_be) return 2;
    pr = malloc((size_t)steps * sizeof *pr);
    rev = malloc((size_t)steps * sizeof *rev);
    if (!pr || !rev) return 2;

    ctx_init(&k);
    rng.s = seed;
    printf("-- test_chain: %d chains x %ld steps (seed %llu), random rotations +"
           " translations, box and cbox forms --\n", chains, steps, (unsigned long long)seed);

    for (ch = 0; ch < chains; ch++) {
        cbx_box b0, b, bn;
        cbx_cbox c, cn;
        cbx_affine a;
        xu_verdict v;
        char why[256];
        long s, left_box = -1, left_cbox = -1;
        int bad_chain = 0;
        double wb[3], wc[3], we[3];
        int start_ok;
        cbx_status worst = CBX_OK;

        cp = 0;
        random_box(&rng, ch, &b0);
        b = b0;
        /* start: the cbox chain begins at box_to_cbox(B_0) */
        total++;
        k_checked[K_START]++;
        start_ok = cbx_box_to_cbox(&b0, &c) == CBX_OK;
        for (i = 0; i < 3 && start_ok; i++) {
            mpq_set_d(k.qa, c.c[i]);
            mpq_set_d(k.qb, c.h[i]);
            mpq_sub(k.qlo, k.qa, k.qb);
            mpq_add(k.qhi, k.qa, k.qb);
            mpq_set_d(k.qa, b0.lo[i]);
            mpq_set_d(k.qb, b0.hi[i]);
            if (mpq_cmp(k.qlo, k.qa) > 0 || mpq_cmp(k.qb, k.qhi) > 0) start_ok = 0;
        }
        if (!start_ok) {
            report(K_START, ch, 0, "box_to_cbox(B_0) not OK or not containing B_0");
            failed++;
            bad_chain = 1;
        }
        set_identity(&k);

        for (s = 0; s < steps; s++) {
            clock_t tc;
            random_step(&rng, &a);
            /* box chain: one checked step */
            total++;
            k_checked[K_BOX]++;
            if (xu_run_case(&k.x, &a, &b, &bn, 1, &v)) {
                report(K_BOX, ch, s + 1, v.why);
                if (logs <= MAX_FAIL_LOGS) {
                    xu_print_case(stdout, &a, &b);
                    xu_print_box(stdout, "out", &bn);
                }
                failed++;
                bad_chain = 1;
            }
            if (v.got != CBX_OK && left_box < 0) left_box = s + 1;
            if (xu_severity(v.got) > xu_severity(worst)) worst = v.got;
            cbx_prepare(&a, &pr[s]);
            b = bn;
            /* cbox chain */
            total++;
            k_checked[K_CBOX]++;
            if (cbox_step(&k, &a, &c, &cn, why, sizeof why)) {
                report(K_CBOX, ch, s + 1, why);
                failed++;
                bad_chain = 1;
            }
            if (!isfinite(cn.h[0] + cn.h[1] + cn.h[2]) && left_cbox < 0) left_cbox = s + 1;
            c = cn;
            /* exact composition */
            tc = clock();
            compose(&k, &a);
            comp_sec += (double)(clock() - tc) / CLOCKS_PER_SEC;

            if (cp < ncp && cp_at[cp] == s + 1) {
                total += 2;
                k_checked[K_BOXC]++;
                k_checked[K_CBOXC]++;
                fill_prod(&k, &b0);
                if (composed_box_failures(&k, &b)) {
                    report(K_BOXC, ch, s + 1, "a corner of B_0 mapped by the exact composition"
                                              " is outside the box");
                    failed++;
                    bad_chain = 1;
                }
                if (composed_cbox_failures(&k, &c)) {
                    report(K_CBOXC, ch, s + 1, "a corner of B_0 mapped by the exact composition"
                                               " is outside [c - h, c + h]");
                    failed++;
                    bad_chain = 1;
                }
                /* the chain function on the maps so far, last applied first */
                {
                    cbx_box w;
                    cbx_status ws;
                    long j;
                    for (j = 0; j <= s; j++) rev[j] = pr[s - j];
                    ws = cbx_transform_box_chain(rev, (size_t)s + 1, &b0, &w);
                    total++;
                    k_checked[K_CHAIN]++;
                    if (ws != worst || memcmp(&w, &b, sizeof w) != 0 || composed_box_failures(&k, &w)) {
                        report(K_CHAIN, ch, s + 1, ws != worst ? "status is not the worst of the steps'"
                               : memcmp(&w, &b, sizeof w) != 0 ? "box differs from the box chain's"
                               : "a corner of B_0 mapped by the exact composition is outside it");
                        failed++;
                        bad_chain = 1;
                    }
                }
                for (i = 0; i < 3; i++)
                    cp_be[((size_t)cp * (size_t)chains + (size_t)ch) * 3 + (size_t)i] =
                        ratio(b.hi[i] - b.lo[i], exact_width(&k, &b0, i));
                cp++;
            }
        }
        {
            size_t bm = max_bits(&k);
            if (bm > bits_max) bits_max = bm;
        }
        for (i = 0; i < 3; i++) {
            wb[i] = b.hi[i] - b.lo[i];
            wc[i] = 2 * c.h[i];
            we[i] = exact_width(&k, &b0, i);
            r_bc[i][ch] = r_bc[3][3 * ch + i] = ratio(wb[i], wc[i]);
            r_be[i][ch] = r_be[3][3 * ch + i] = ratio(wb[i], we[i]);
            r_ce[i][ch] = r_ce[3][3 * ch + i] = ratio(wc[i], we[i]);
            r_step[3 * ch + i] = pow(r_be[i][ch], 1.0 / (double)steps);
        }
        if (left_box >= 0 || left_cbox >= 0) n_left++;
        printf("  chain %2d: B_0 widths %-9.3g %-9.3g %-9.3g  final box/exact %-9.3g %-9.3g %-9.3g"
               "  box/cbox-1 %-10.3g %-10.3g %-10.3g", ch, b0.hi[0] - b0.lo[0], b0.hi[1] - b0.lo[1],
               b0.hi[2] - b0.lo[2], r_be[0][ch], r_be[1][ch], r_be[2][ch], r_bc[0][ch] - 1,
               r_bc[1][ch] - 1, r_bc[2][ch] - 1);
        if (left_box >= 0) printf("  box left the domain at step %ld", left_box);
        if (left_cbox >= 0) printf("  cbox left the domain at step %ld", left_cbox);
        printf("  %s\n", bad_chain ? "FAIL" : "ok");
    }

    printf("\ngrowth after %ld steps: final width / reference width, max / median over %d chains\n",
           steps, chains);
    for (i = 0; i < 4; i++) {
        int n = i < 3 ? chains : 3 * chains;
        char ax[24];
        if (i < 3) snprintf(ax, sizeof ax, "axis %d", i);
        else snprintf(ax, sizeof ax, "all axes");
        max_med(r_bc[i], n, &mx, &med);
        printf("  %-8s box/cbox   max %.15f  median %.15f  (min %.15f)\n", ax, mx, med,
               r_bc[i][0]);
        max_med(r_be[i], n, &mx, &med);
        printf("  %-8s box/exact  max %.4g  median %.4g\n", ax, mx, med);
        max_med(r_ce[i], n, &mx, &med);
        printf("  %-8s cbox/exact max %.4g  median %.4g\n", ax, mx, med);
    }
    max_med(r_step, 3 * chains, &mx, &med);
    printf("  per-step factor (box/exact)^(1/%ld): max %.6f  median %.6f\n", steps, mx, med);
    printf("  chains that left the proven domain: %d\n", n_left);
    printf("growth by checkpoint, box/exact over chains and axes:\n");
    for (cp = 0; cp < ncp; cp++) {
        max_med(cp_be + (size_t)cp * 3 * (size_t)chains, 3 * chains, &mx, &med);
        printf("  step %5ld: max %.4g  median %.4g\n", cp_at[cp], mx, med);
    }
    printf("exact composition (mpq_t, all %ld steps): %.2f s in all, largest numerator or"
           " denominator %zu bits\n", steps, comp_sec, bits_max);
    {
        int sb = chain_special(&rng);
        total += 6;
        failed += sb;
    }
    printf("checks:\n");
    for (i = 0; i < NK; i++)
        printf("  check %-10s %8ld %-8s checked, %ld failed\n", k_name[i], k_checked[i], k_unit[i],
               k_failed[i]);
    printf("time %.2f s (CPU)\n", (double)(clock() - t0) / CLOCKS_PER_SEC);

    ctx_clear(&k);
    for (i = 0; i < 4; i++) {
        free(r_bc[i]);
        free(r_be[i]);
        free(r_ce[i]);
    }
    free(r_step);
    free(cp_be);
    free(cp_at);
    free(pr);
    free(rev);
    printf("%ld passed, %ld failed\n", total - failed, failed);
    return failed ? 1 : 0;
}
