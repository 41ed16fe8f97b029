/*
 * test_batch [N] [seed]: cbx_transform_boxes (the batch form) against
 * the class kernel cbx_transform_box_as(a, cbx_classify(a), ...) called once
 * per box (the batch classifies the map once; the class kernels have
 * cbx_transform_box's promise and are checked against it, and against the
 * exact oracle, in tests/test_classes).
 *
 * The promise (certbox.h): out[k] has cbx_transform_box's promise for
 * in[k] under *a, for k = 0 .. n-1; the result is the most severe status met,
 * CBX_EINVAL > CBX_ERANGE > CBX_EMPTY > CBX_OK, and CBX_OK for n == 0; only
 * out[0 .. n-1] is written.
 *
 * Batches: for each of N rounds (default 200), one random map and one batch
 * of each size n = 0, 1, 2, 7, 1000 and of one random size in [0, 64], the
 * boxes a random mix (the mix itself drawn per batch, so that some batches
 * are all-normal and some all-special) of: normal boxes in the domain, NaN
 * boxes, empty boxes (hi < lo, lo = +inf, hi = -inf), boxes with a huge end
 * outside the domain, half-space boxes (infinite ends), zero-width boxes.
 * The maps: ordinary, with zero / -0.0 columns, with an infinite entry
 * (CBX_ERANGE rows), with a NaN (every box CBX_EINVAL), with huge entries.
 * Then every ordered sequence of 3 boxes drawn from {normal, empty,
 * out-of-domain, NaN} (64 batches, the severity rule in every order), and
 * n = 0 with null pointers (the contract's ranges are empty).
 *
 * Checks per batch:
 *   bits     memcmp(out[k], cbx_transform_box's output for in[k]) == 0
 *            for every k (the reference out is pre-filled differently, so
 *            an unwritten field shows);
 *   status   the returned status == the most severe per-box status, and
 *            the per-box statuses agree with exact_util's expected status;
 *   guards   GUARD = 4 entries before out[0] and after out[n-1], filled
 *            with a byte pattern, are unchanged;
 *   inputs   *a and in[0 .. n-1] unchanged.
 * Last line "N passed, M failed" (batches); exit status 1 on failure.
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

#define INF HUGE_VAL
#define GUARD 4
#define MAXN 1000
#define MAX_FAIL_LOGS 20

enum { B_NORMAL, B_NAN, B_EMPTY, B_OOD, B_HALF, B_FLAT, NB };
static const char *const b_name[NB] = { "normal", "NaN", "empty", "out-of-domain",
                                        "half-space", "flat" };

enum { K_BITS, K_STATUS, K_GUARDS, K_INPUTS, NK };
static const char *const k_name[NK] = { "bits", "status", "guards", "inputs" };
static const char *const k_unit[NK] = { "boxes", "batches", "batches", "batches" };

typedef struct stats {
    long batches, failed, boxes;
    long by_n[6];                /* batches of n = 0, 1, 2, 7, 1000, other   */
    long kinds[NB];              /* boxes by kind                            */
    long status_ret[4];          /* returned statuses                        */
    long checked[NK], fail[NK];
    long logs;
} stats;

static int severity(cbx_status s)
{
    return s == CBX_EINVAL ? 3 : s == CBX_ERANGE ? 2 : s == CBX_EMPTY ? 1 : 0;
}

static double sgm(xu_rng *r, int emin, int emax) { return xu_gen_signed(r, emin, emax); }

static void gen_map(xu_rng *r, cbx_affine *a, int kind)
{
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) a->m[i][j] = sgm(r, -10, 10);
        a->m[i][3] = sgm(r, -20, 20);
    }
    switch (kind) {
    case 1: /* zero and -0.0 columns */
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++)
                if (xu_rng_int(r, 0, 2) == 0) a->m[i][j] = xu_rng_sign(r) * 0.0;
        break;
    case 2: /* an infinite entry: that row is lost for every box */
        a->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 3)] = xu_rng_sign(r) * INF;
        break;
    case 3: /* a NaN: every box CBX_EINVAL */
        a->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 3)] = NAN;
        break;
    case 4: /* huge entries */
        a->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 2)] = xu_rng_sign(r) * 1e300;
        break;
    default:
        break;
    }
}

static void gen_box(xu_rng *r, cbx_box *b, int kind)
{
    int j, q;
    for (j = 0; j < 3; j++) {
        double u = sgm(r, -30, 30), w = sgm(r, -30, 30);
        b->lo[j] = u < w ? u : w;
        b->hi[j] = u < w ? w : u;
    }
    q = xu_rng_int(r, 0, 2);
    switch (kind) {
    case B_NAN:
        if (xu_rng_int(r, 0, 1)) b->lo[q] = NAN;
        else b->hi[q] = NAN;
        break;
    case B_EMPTY:
        switch (xu_rng_int(r, 0, 2)) {
        case 0: { double t = b->lo[q]; b->lo[q] = b->hi[q] + 1.0; b->hi[q] = t; } break;
        case 1: b->lo[q] = INF; break;
        default: b->hi[q] = -INF; break;
        }
        break;
    case B_OOD:
        if (xu_rng_int(r, 0, 1)) b->hi[q] = xu_rng_int(r, 0, 1) ? DBL_MAX : 0x1p1019;
        else b->lo[q] = -DBL_MAX;
        break;
    case B_HALF:
        if (xu_rng_int(r, 0, 1)) b->lo[q] = -INF;
        else b->hi[q] = INF;
        if (xu_rng_int(r, 0, 3) == 0) { b->lo[(q + 1) % 3] = -INF; b->hi[(q + 1) % 3] = INF; }
        break;
    case B_FLAT:
        for (j = 0; j < 3; j++) b->hi[j] = b->lo[j];
        break;
    default:
        break;
    }
}

static void fill_pattern(void *p, size_t bytes, unsigned char seed)
{
    unsigned char *c = (unsigned char *)p;
    size_t i;
    for (i = 0; i < bytes; i++) c[i] = (unsigned char)(seed + 37u * (unsigned)i);
}

/* box: the box concerned, or 0 (then only the map is printed) */
static void log_fail(stats *st, const char *why, size_t n, const cbx_affine *a,
                     const cbx_box *box)
{
    int i;
    if (st->logs++ >= MAX_FAIL_LOGS) return;
    printf("FAIL batch %ld (n = %lu): %s\n", st->batches - 1, (unsigned long)n, why);
    if (box) {
        xu_print_case(stdout, a, box);
        return;
    }
    for (i = 0; i < 3; i++)
        printf("  m[%d] = {%a, %a, %a | %a}\n", i, a->m[i][0], a->m[i][1], a->m[i][2],
               a->m[i][3]);
}

/* One batch of n boxes in[0 .. n-1] (n <= MAXN). */
static void run_batch(stats *st, const cbx_affine *a, const cbx_box *in, const int *kinds,
                      size_t n)
{
    static cbx_box out[MAXN + 2 * GUARD], guard_copy[MAXN + 2 * GUARD], ref[MAXN],
        in_copy[MAXN];
    cbx_affine a_copy = *a;
    cbx_status got, want = CBX_OK;
    size_t k;
    int bad = 0, badbits = 0;
    char why[200];

    st->batches++;
    st->boxes += (long)n;
    st->by_n[n == 0 ? 0 : n == 1 ? 1 : n == 2 ? 2 : n == 7 ? 3 : n == 1000 ? 4 : 5]++;
    for (k = 0; k < n; k++) st->kinds[kinds[k]]++;
    memcpy(in_copy, in, n * sizeof *in);

    /* the reference, box by box */
    for (k = 0; k < n; k++) {
        cbx_status s;
        int j;
        for (j = 0; j < 3; j++) ref[k].lo[j] = ref[k].hi[j] = NAN;
        s = cbx_transform_box_as(a, cbx_classify(a), &in[k], &ref[k]);
        if (s != xu_expected_status(a, &in[k])) {
            snprintf(why, sizeof why, "box %lu (%s): cbx_transform_box_as returns %s, exact_util "
                     "expects %s", (unsigned long)k, b_name[kinds[k]], cbx_status_name(s),
                     cbx_status_name(xu_expected_status(a, &in[k])));
            if (!bad) log_fail(st, why, n, a, &in[k]);
            st->fail[K_STATUS]++;
            bad = 1;
        }
        if (severity(s) > severity(want)) want = s;
    }

    /* the batch, into out[GUARD .. GUARD+n-1] with guards around */
    fill_pattern(out, sizeof out, (unsigned char)(st->batches * 13u));
    memcpy(guard_copy, out, sizeof out);
    got = cbx_transform_boxes(a, in, out + GUARD, n);
    st->status_ret[xu_status_index(got) >= 0 ? xu_status_index(got) : 0]++;

    st->checked[K_STATUS]++;
    if (got != want) {
        snprintf(why, sizeof why, "returned %s, the most severe per-box status is %s",
                 cbx_status_name(got), cbx_status_name(want));
        if (!bad) log_fail(st, why, n, a, (const cbx_box *)0);
        st->fail[K_STATUS]++;
        bad = 1;
    }
    for (k = 0; k < n; k++) {
        st->checked[K_BITS]++;
        if (memcmp(&out[GUARD + k], &ref[k], sizeof ref[k])) {
            st->fail[K_BITS]++;
            if (!badbits && !bad) {
                snprintf(why, sizeof why, "out[%lu] (%s box) differs from cbx_transform_box's",
                         (unsigned long)k, b_name[kinds[k]]);
                log_fail(st, why, n, a, &in[k]);
                xu_print_box(stdout, "batch", &out[GUARD + k]);
                xu_print_box(stdout, "single", &ref[k]);
            }
            badbits = 1;
        }
    }
    bad |= badbits;
    st->checked[K_GUARDS]++;
    if (memcmp(out, guard_copy, GUARD * sizeof out[0])
        || memcmp(out + GUARD + n, guard_copy + GUARD + n, GUARD * sizeof out[0])) {
        if (!bad) log_fail(st, "memory beyond out[0 .. n-1] was written", n, a,
                           (const cbx_box *)0);
        st->fail[K_GUARDS]++;
        bad = 1;
    }
    st->checked[K_INPUTS]++;
    if (memcmp(&a_copy, a, sizeof a_copy) || memcmp(in_copy, in, n * sizeof *in)) {
        if (!bad) log_fail(st, "the call modified its inputs", n, a, (const cbx_box *)0);
        st->fail[K_INPUTS]++;
        bad = 1;
    }
    if (bad) st->failed++;
}

/* A batch of n boxes with a random mix of kinds. */
static void random_batch(xu_rng *r, stats *st, const cbx_affine *a, size_t n)
{
    static cbx_box in[MAXN];
    static int kinds[MAXN];
    int w[NB], total = 0, q;
    size_t k;
    /* the mix: weights per kind for this batch; often all normal */
    for (q = 0; q < NB; q++) {
        w[q] = xu_rng_int(r, 0, 3) == 0 ? 0 : xu_rng_int(r, 1, 10);
        total += w[q];
    }
    if (xu_rng_int(r, 0, 4) == 0 || total == 0) {
        for (q = 0; q < NB; q++) w[q] = 0;
        w[xu_rng_int(r, 0, 3) ? B_NORMAL : xu_rng_int(r, 0, NB - 1)] = 1;
        total = 1;
    }
    for (k = 0; k < n; k++) {
        int p = xu_rng_int(r, 0, total - 1);
        for (q = 0; q < NB - 1 && p >= w[q]; q++) p -= w[q];
        kinds[k] = q;
        gen_box(r, &in[k], q);
    }
    run_batch(st, a, in, kinds, n);
}

int main(int argc, char **argv)
{
    long rounds = (long)xu_arg_num(argc, argv, 1, 200, "[N] [seed]"), c;
    uint64_t seed = (uint64_t)xu_arg_num(argc, argv, 2, 1, "[N] [seed]");
    static const size_t sizes[5] = { 0, 1, 2, 7, 1000 };
    static stats st;
    xu_rng rng;
    cbx_affine a;
    int q, seq;
    clock_t t0 = clock();

    rng.s = UINT64_C(0xb7e151628aed2a6a) ^ seed;
    printf("-- test_batch: cbx_transform_boxes against cbx_transform_box per box, %ld rounds, "
           "seed %llu --\n", rounds, (unsigned long long)seed);

    for (c = 0; c < rounds; c++) {
        int mk = xu_rng_int(&rng, 0, 9);
        gen_map(&rng, &a, mk < 5 ? 0 : mk < 7 ? 1 : mk < 8 ? 2 : mk < 9 ? 4 : 3);
        for (q = 0; q < 5; q++) random_batch(&rng, &st, &a, sizes[q]);
        random_batch(&rng, &st, &a, (size_t)xu_rng_int(&rng, 0, 64));
    }

    /* every ordered triple of {normal, empty, out-of-domain, NaN} */
    gen_map(&rng, &a, 0);
    for (seq = 0; seq < 64; seq++) {
        static const int pick[4] = { B_NORMAL, B_EMPTY, B_OOD, B_NAN };
        cbx_box in[3];
        int kinds[3], j;
        for (j = 0; j < 3; j++) {
            kinds[j] = pick[(seq >> (2 * j)) & 3];
            gen_box(&rng, &in[j], kinds[j]);
        }
        run_batch(&st, &a, in, kinds, 3);
    }

    /* n == 0 with null pointers: nothing may be touched, CBX_OK */
    st.checked[K_STATUS]++;
    st.batches++;
    st.by_n[0]++;
    if (cbx_transform_boxes(&a, (const cbx_box *)0, (cbx_box *)0, 0) != CBX_OK) {
        st.fail[K_STATUS]++;
        st.failed++;
        printf("FAIL n == 0 with null in / out: status is not CBX_OK\n");
    }

    printf("  %ld batches (n = 0: %ld, 1: %ld, 2: %ld, 7: %ld, 1000: %ld, other: %ld), "
           "%ld boxes\n", st.batches, st.by_n[0], st.by_n[1], st.by_n[2], st.by_n[3], st.by_n[4],
           st.by_n[5], st.boxes);
    printf("  boxes by kind:");
    for (q = 0; q < NB; q++) printf(" %s %ld", b_name[q], st.kinds[q]);
    printf("\n  returned statuses: OK %ld, EMPTY %ld, EINVAL %ld, ERANGE %ld\n",
           st.status_ret[0], st.status_ret[1], st.status_ret[2], st.status_ret[3]);
    for (q = 0; q < NK; q++)
        printf("  check %-7s %9ld %-8s checked, %ld failed\n", k_name[q], st.checked[q],
               k_unit[q], st.fail[q]);
    printf("  CPU time %.2f s\n", (double)(clock() - t0) / CLOCKS_PER_SEC);
    printf("%ld passed, %ld failed\n", st.batches - st.failed, st.failed);
    return st.failed ? 1 : 0;
}
