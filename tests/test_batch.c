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
 *
 * Prepared maps, on every batch above (the same map and boxes): the
 * structs a caller may hand over,
 *   cbx_prepare       filled by cbx_prepare (checked: the map copied bit
 *                     for bit, cls == cbx_classify(a), fast set iff every
 *                     linear entry is at most 2^509 and every translation
 *                     at most 2^1018 in magnitude);
 *   zero-init         cbx_prepared p = { 0 }, then p.a = *a (fast 0, cls 0);
 *   cls forged        cbx_prepare's with p.cls set by hand to a value of
 *                     xu_cls_values (the five classes and ints outside the
 *                     enum), the fast flag kept or cleared;
 *   fast+cls forged   the same with p.fast = 1 whatever the map (huge,
 *                     infinite, NaN entries included);
 * the forged value cycling with the batch number.  Checks:
 *   box_prep   cbx_transform_box_prep(&p, in[k]) == cbx_transform_box_as(
 *              &p.a, p.cls, in[k]), status and bits (pre-filled
 *              differently), and in place (out == in); not for fast+cls
 *              forged (cbx_transform_box_prep trusts the fast flag);
 *   boxes_prep cbx_transform_boxes_prep(&p, in, out, n) == cbx_transform_
 *              boxes(a, in, out, n), status and bits, guards unchanged,
 *              *p unchanged, for every struct;
 *   exact      the boxes of boxes_prep on the forged structs against the
 *              exact oracle (xu_check_result: status, special outputs,
 *              containment of the exact image, proven tightness);
 *   n == 0 with null in / out: CBX_OK.
 * Special values: a base map of each class (identity, translation, scale,
 * permutation, general) and a base box, one of 19 values (NaN, +-inf,
 * +-0, 2^-1074, DBL_MIN, 2^509 and the next double, 2^1018 and the next,
 * 2^1019, DBL_MAX, ...) in one of the 18 positions, as a batch of one box
 * through every check above, with every forged cls value.
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

/* box kinds; the random batches draw the first NB_RAND */
enum { B_NORMAL, B_NAN, B_EMPTY, B_OOD, B_HALF, B_FLAT, B_EDGE, NB_RAND, B_SPECIAL = NB_RAND,
       NB };
static const char *const b_name[NB] = { "normal", "NaN", "empty", "out-of-domain",
                                        "half-space", "flat", "fast-range-edge", "special" };

enum { K_BITS, K_STATUS, K_GUARDS, K_INPUTS, NK };
static const char *const k_name[NK] = { "bits", "status", "guards", "inputs" };
static const char *const k_unit[NK] = { "boxes", "batches", "batches", "batches" };

/* the structs handed to the prepared forms (see the top comment) */
enum { V_PREP, V_ZERO, V_CLS, V_FORGED, NV };
static const char *const v_name[NV] = { "cbx_prepare", "zero-init", "cls forged",
                                        "fast+cls forged" };

typedef struct stats {
    long batches, failed, boxes;
    long by_n[6];                /* batches of n = 0, 1, 2, 7, 1000, other   */
    long kinds[NB];              /* boxes by kind                            */
    long status_ret[4];          /* returned statuses                        */
    long checked[NK], fail[NK];
    long logs;
    /* prepared maps */
    long prep_maps, prep_fast, prep_fail;     /* cbx_prepare's struct checked */
    long one[NV], one_fail[NV];               /* box_prep: boxes              */
    long inplace_fail[NV];                    /* box_prep in place: boxes     */
    long many[NV], many_boxes[NV], many_fail[NV]; /* boxes_prep: batches      */
    long exact, exact_fail;                   /* forged structs' boxes, exact */
    long special;                             /* special-value inputs         */
} stats;

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
    case 5: { /* a map of a class: identity, translation, scale, permutation */
        int c = xu_rng_int(r, CBX_CLASS_PERMUTE, CBX_CLASS_IDENTITY), col;
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) a->m[i][j] = 0.0;
            col = c == CBX_CLASS_PERMUTE ? (i + 1) % 3 : i;
            a->m[i][col] = c >= CBX_CLASS_TRANSLATE ? 1.0 : sgm(r, -10, 10);
            if (c == CBX_CLASS_IDENTITY) a->m[i][3] = 0.0;
        }
        break;
    }
    case 6: /* entries at the edge of the fast range (2^509, 2^1018) or just past it */
        for (i = 0; i < 3; i++) {
            double e = xu_rng_int(r, 0, 1) ? 0x1p509 : 0x1.0000000000001p509;
            j = xu_rng_int(r, 0, 2);
            a->m[i][j] = xu_rng_sign(r) * e;
            e = xu_rng_int(r, 0, 1) ? 0x1p1018 : 0x1.0000000000001p1018;
            a->m[i][3] = xu_rng_sign(r) * e;
        }
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
    case B_EDGE: /* an end at the edge of the fast range (2^509) or just past it */
        if (xu_rng_int(r, 0, 1)) b->hi[q] = xu_rng_int(r, 0, 1) ? 0x1p509 : 0x1.0000000000001p509;
        else b->lo[q] = xu_rng_int(r, 0, 1) ? -0x1p509 : -0x1.0000000000001p509;
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

/* ---- prepared maps ---------------------------------------------------- */

/* The fast range of certbox.h: every linear entry at most 2^509 and every
 * translation at most 2^1018 in magnitude (false on NaN). */
static int map_fast_ref(const cbx_affine *a)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++)
            if (!(fabs(a->m[i][j]) <= (j < 3 ? 0x1p509 : 0x1p1018))) return 0;
    return 1;
}

/* cbx_prepare(a, p) into a struct filled with garbage: the map copied bit
 * for bit, the class cbx_classify's, the fast flag set iff the map is in
 * the fast range, *a unchanged.  Returns 1 on failure. */
static int check_prepare(stats *st, const cbx_affine *a, cbx_prepared *p, size_t n)
{
    cbx_affine a0 = *a;
    char why[200];
    memset(p, 0xa5, sizeof *p);
    cbx_prepare(a, p);
    st->prep_maps++;
    if (p->fast) st->prep_fast++;
    if (memcmp(&p->a, a, sizeof *a) || memcmp(&a0, a, sizeof a0) || p->cls != (int)cbx_classify(a)
        || (p->fast != 0) != map_fast_ref(a)) {
        st->prep_fail++;
        snprintf(why, sizeof why, "cbx_prepare: map copied %s, cls %d (cbx_classify %d), fast %d "
                 "(fast range: %d)", memcmp(&p->a, a, sizeof *a) ? "NOT bit for bit" : "bit for bit",
                 p->cls, (int)cbx_classify(a), p->fast, map_fast_ref(a));
        log_fail(st, why, n, a, (const cbx_box *)0);
        return 1;
    }
    return 0;
}

/* One struct *p (kind v) on a batch whose cbx_transform_boxes output is
 * bout (status bgot) and whose per-box statuses are refst[]: box_prep box
 * by box against cbx_transform_box_as(&p->a, p->cls, ...) and in place
 * (not for V_FORGED: box_prep trusts the fast flag), boxes_prep against
 * bout with guards, *p unchanged, and for a forged struct every box of
 * boxes_prep against the exact oracle.  Returns 1 on failure. */
static int prep_variant(stats *st, xu_exact *x, const cbx_prepared *p, int v, const cbx_box *in,
                        const int *kinds, size_t n, const cbx_box *bout, cbx_status bgot,
                        const cbx_status *refst)
{
    static cbx_box pout[MAXN + 2 * GUARD], guard_copy[MAXN + 2 * GUARD];
    cbx_prepared p0 = *p;
    cbx_status s;
    size_t k;
    int bad = 0, j;
    char why[480], nb[16];
    const char *cls = xu_cls_str(p->cls, nb);

    if (v != V_FORGED)
        for (k = 0; k < n; k++) {
            cbx_box o, r, ip;
            cbx_status sr, si;
            fill_pattern(&o, sizeof o, 0x3c);
            for (j = 0; j < 3; j++) r.lo[j] = r.hi[j] = NAN;
            s = cbx_transform_box_prep(p, &in[k], &o);
            sr = cbx_transform_box_as(&p->a, (cbx_class)p->cls, &in[k], &r);
            st->one[v]++;
            if (s != sr || memcmp(&o, &r, sizeof o)) {
                st->one_fail[v]++;
                snprintf(why, sizeof why, "box %lu (%s): cbx_transform_box_prep (%s, fast %d, cls "
                         "%s) returns %s, cbx_transform_box_as %s, boxes %s", (unsigned long)k,
                         b_name[kinds[k]], v_name[v], p->fast, cls, cbx_status_name(s),
                         cbx_status_name(sr), memcmp(&o, &r, sizeof o) ? "differ" : "equal");
                if (!bad) {
                    log_fail(st, why, n, &p->a, &in[k]);
                    xu_print_box(stdout, "prep", &o);
                    xu_print_box(stdout, "as", &r);
                }
                bad = 1;
            }
            ip = in[k];
            si = cbx_transform_box_prep(p, &ip, &ip);
            if (si != s || memcmp(&ip, &o, sizeof o)) {
                st->inplace_fail[v]++;
                snprintf(why, sizeof why, "box %lu (%s): cbx_transform_box_prep (%s) in place "
                         "(out == in) differs", (unsigned long)k, b_name[kinds[k]], v_name[v]);
                if (!bad) log_fail(st, why, n, &p->a, &in[k]);
                bad = 1;
            }
        }

    fill_pattern(pout, sizeof pout, (unsigned char)(st->batches * 7u + (unsigned)v));
    memcpy(guard_copy, pout, sizeof pout);
    s = cbx_transform_boxes_prep(p, in, pout + GUARD, n);
    st->many[v]++;
    st->many_boxes[v] += (long)n;
    if (s != bgot || (n && memcmp(pout + GUARD, bout, n * sizeof *bout))
        || memcmp(pout, guard_copy, GUARD * sizeof pout[0])
        || memcmp(pout + GUARD + n, guard_copy + GUARD + n, GUARD * sizeof pout[0])
        || memcmp(&p0, p, sizeof p0)) {
        st->many_fail[v]++;
        snprintf(why, sizeof why, "cbx_transform_boxes_prep (%s, fast %d, cls %s) returns %s, "
                 "cbx_transform_boxes %s; boxes %s, guards %s, *p %s", v_name[v], p0.fast, cls,
                 cbx_status_name(s), cbx_status_name(bgot),
                 n && memcmp(pout + GUARD, bout, n * sizeof *bout) ? "differ" : "equal",
                 memcmp(pout, guard_copy, GUARD * sizeof pout[0])
                 || memcmp(pout + GUARD + n, guard_copy + GUARD + n, GUARD * sizeof pout[0])
                 ? "WRITTEN" : "intact", memcmp(&p0, p, sizeof p0) ? "CHANGED" : "unchanged");
        if (!bad) log_fail(st, why, n, &p0.a, (const cbx_box *)0);
        bad = 1;
    }

    if (v == V_CLS || v == V_FORGED)
        for (k = 0; k < n; k++) {
            xu_verdict vd;
            st->exact++;
            if (xu_check_result(x, &p0.a, &in[k], &pout[GUARD + k], refst[k], 0, &vd)) {
                st->exact_fail++;
                snprintf(why, sizeof why, "box %lu (%s) of cbx_transform_boxes_prep (%s, fast %d, "
                         "cls %s): %s", (unsigned long)k, b_name[kinds[k]], v_name[v], p0.fast,
                         cls, vd.why);
                if (!bad) {
                    log_fail(st, why, n, &p0.a, &in[k]);
                    xu_print_box(stdout, "out", &pout[GUARD + k]);
                }
                bad = 1;
            }
        }
    return bad;
}

/* The prepared forms on one batch (see prep_variant): cbx_prepare's struct,
 * a zero-initialised one, and for each of nforge values of xu_cls_values
 * from index f0 on, the class forged (fast kept or cleared, alternating
 * every XU_NCLS_VALUES batches) and fast and class forged. */
static int run_prepared(stats *st, xu_exact *x, const cbx_affine *a, const cbx_box *in,
                        const int *kinds, size_t n, const cbx_box *bout, cbx_status bgot,
                        const cbx_status *refst, int f0, int nforge)
{
    cbx_prepared p, q, z = { 0 };
    int f, bad = check_prepare(st, a, &p, n);
    z.a = *a;
    bad |= prep_variant(st, x, &p, V_PREP, in, kinds, n, bout, bgot, refst);
    bad |= prep_variant(st, x, &z, V_ZERO, in, kinds, n, bout, bgot, refst);
    for (f = 0; f < nforge; f++) {
        q = p;
        q.cls = xu_cls_values[(f0 + f) % XU_NCLS_VALUES];
        if ((st->batches / XU_NCLS_VALUES) % 2) q.fast = 0;
        bad |= prep_variant(st, x, &q, V_CLS, in, kinds, n, bout, bgot, refst);
        q.fast = 1;
        bad |= prep_variant(st, x, &q, V_FORGED, in, kinds, n, bout, bgot, refst);
    }
    return bad;
}

/* One batch of n boxes in[0 .. n-1] (n <= MAXN). */
static void run_batch(stats *st, xu_exact *x, const cbx_affine *a, const cbx_box *in,
                      const int *kinds, size_t n, int f0, int nforge)
{
    static cbx_box out[MAXN + 2 * GUARD], guard_copy[MAXN + 2 * GUARD], ref[MAXN],
        in_copy[MAXN];
    static cbx_status refst[MAXN];
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
        s = refst[k] = cbx_transform_box_as(a, cbx_classify(a), &in[k], &ref[k]);
        if (s != xu_expected_status(a, &in[k])) {
            snprintf(why, sizeof why, "box %lu (%s): cbx_transform_box_as returns %s, exact_util "
                     "expects %s", (unsigned long)k, b_name[kinds[k]], cbx_status_name(s),
                     cbx_status_name(xu_expected_status(a, &in[k])));
            if (!bad) log_fail(st, why, n, a, &in[k]);
            st->fail[K_STATUS]++;
            bad = 1;
        }
        if (xu_severity(s) > xu_severity(want)) want = s;
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
    bad |= run_prepared(st, x, a, in, kinds, n, out + GUARD, got, refst, f0, nforge);
    if (bad) st->failed++;
}

/* A batch of n boxes with a random mix of kinds. */
static void random_batch(xu_rng *r, stats *st, xu_exact *x, const cbx_affine *a, size_t n)
{
    static cbx_box in[MAXN];
    static int kinds[MAXN];
    int w[NB_RAND], total = 0, q;
    size_t k;
    /* the mix: weights per kind for this batch; often all normal */
    for (q = 0; q < NB_RAND; q++) {
        w[q] = xu_rng_int(r, 0, 3) == 0 ? 0 : xu_rng_int(r, 1, 10);
        total += w[q];
    }
    if (xu_rng_int(r, 0, 4) == 0 || total == 0) {
        for (q = 0; q < NB_RAND; q++) w[q] = 0;
        w[xu_rng_int(r, 0, 3) ? B_NORMAL : xu_rng_int(r, 0, NB_RAND - 1)] = 1;
        total = 1;
    }
    for (k = 0; k < n; k++) {
        int p = xu_rng_int(r, 0, total - 1);
        for (q = 0; q < NB_RAND - 1 && p >= w[q]; q++) p -= w[q];
        kinds[k] = q;
        gen_box(r, &in[k], q);
    }
    run_batch(st, x, a, in, kinds, n, (int)(st->batches % XU_NCLS_VALUES), 1);
}

/* ---- special values --------------------------------------------------- */

#define ROW(a, b, c, t) { a, b, c, t }
#define MAT(r0, r1, r2) { { r0, r1, r2 } }
static const double specials[] = {
    NAN, -NAN, INF, -INF, 0.0, -0.0, 0x1p-1074, -DBL_MIN, 1.0, -1.0, 2.0,
    0x1p509, 0x1.0000000000001p509, -0x1p509, 0x1p1018, -0x1.0000000000001p1018, 0x1p1019,
    DBL_MAX, -DBL_MAX
};
#define N_SPECIAL ((int)(sizeof specials / sizeof specials[0]))
/* one base map of each class, identity first */
static const cbx_affine base_maps[] = {
    MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0)),
    MAT(ROW(1, 0, 0, 1), ROW(0, 1, 0, -2), ROW(0, 0, 1, 3)),
    MAT(ROW(2, 0, 0, 1), ROW(0, -3, 0, -2), ROW(0, 0, 0.5, 3)),
    MAT(ROW(0, 1, 0, 1), ROW(0, 0, -3, -2), ROW(0.5, 0, 0, 3)),
    MAT(ROW(0.5, -2, 0.25, 1), ROW(0, 1.5, -1, -3), ROW(4, 0, 0.125, 0.75)),
};
#define N_BASE ((int)(sizeof base_maps / sizeof base_maps[0]))

/* Each special value in each of the 18 positions (12 map entries, 6 box
 * ends) of each base map and the base box: a batch of one box, with every
 * forged cls value. */
static void run_specials(stats *st, xu_exact *x)
{
    static const cbx_box base_box = { { -1, 0.5, -4 }, { 2, 3, -2 } };
    static const int kind = B_SPECIAL;
    int m, p, v;
    for (m = 0; m < N_BASE; m++)
        for (p = 0; p < 18; p++)
            for (v = 0; v < N_SPECIAL; v++) {
                cbx_affine a = base_maps[m];
                cbx_box b = base_box;
                if (p < 12) a.m[p / 4][p % 4] = specials[v];
                else if (p < 15) b.lo[p - 12] = specials[v];
                else b.hi[p - 15] = specials[v];
                st->special++;
                run_batch(st, x, &a, &b, &kind, 1, 0, XU_NCLS_VALUES);
            }
}

int main(int argc, char **argv)
{
    long rounds = (long)xu_arg_num(argc, argv, 1, 200, "[N] [seed]"), c;
    uint64_t seed = (uint64_t)xu_arg_num(argc, argv, 2, 1, "[N] [seed]");
    static const size_t sizes[5] = { 0, 1, 2, 7, 1000 };
    static stats st;
    xu_rng rng;
    xu_exact x;
    cbx_affine a;
    cbx_prepared p;
    int q, seq;
    clock_t t0 = clock();

    xu_init(&x);
    rng.s = UINT64_C(0xb7e151628aed2a6a) ^ seed;
    printf("-- test_batch: cbx_transform_boxes against cbx_transform_box per box, and the "
           "prepared forms (cbx_prepare, cbx_transform_box_prep, cbx_transform_boxes_prep), "
           "%ld rounds, seed %llu --\n", rounds, (unsigned long long)seed);

    for (c = 0; c < rounds; c++) {
        /* ordinary 40%, zero columns 15%, class maps 15%, fast-range edge 10%,
         * infinite, huge, NaN entries 5%, 10%, 5% */
        static const int mk_kind[20] = { 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 5, 5, 5, 6, 6, 2, 4, 4, 3 };
        gen_map(&rng, &a, mk_kind[xu_rng_int(&rng, 0, 19)]);
        for (q = 0; q < 5; q++) random_batch(&rng, &st, &x, &a, sizes[q]);
        random_batch(&rng, &st, &x, &a, (size_t)xu_rng_int(&rng, 0, 64));
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
        run_batch(&st, &x, &a, in, kinds, 3, seq % XU_NCLS_VALUES, 1);
    }
    run_specials(&st, &x);

    /* n == 0 with null pointers: nothing may be touched, CBX_OK */
    st.checked[K_STATUS]++;
    st.batches++;
    st.by_n[0]++;
    if (cbx_transform_boxes(&a, (const cbx_box *)0, (cbx_box *)0, 0) != CBX_OK) {
        st.fail[K_STATUS]++;
        st.failed++;
        printf("FAIL n == 0 with null in / out: status is not CBX_OK\n");
    }
    /* the same for the prepared batch, with a forged struct (huge map, fast
     * 1, cls IDENTITY) */
    a.m[0][1] = 1e300;
    cbx_prepare(&a, &p);
    p.fast = 1;
    p.cls = CBX_CLASS_IDENTITY;
    st.batches++;
    st.by_n[0]++;
    st.many[V_FORGED]++;
    if (cbx_transform_boxes_prep(&p, (const cbx_box *)0, (cbx_box *)0, 0) != CBX_OK) {
        st.many_fail[V_FORGED]++;
        st.failed++;
        printf("FAIL n == 0 with null in / out: cbx_transform_boxes_prep's status is not CBX_OK\n");
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
    printf("  special values: %ld inputs (%d base maps, one per class, x 18 positions x %d "
           "values), each a batch of one box with all %d cls values forged\n", st.special,
           N_BASE, N_SPECIAL, XU_NCLS_VALUES);
    printf("  prepared maps: cbx_prepare on %ld maps (%ld in the fast range), %ld failed (copy, "
           "class, fast flag)\n", st.prep_maps, st.prep_fast, st.prep_fail);
    for (q = 0; q < NV; q++) {
        if (q == V_FORGED)
            printf("  %-16s box_prep: not called (it trusts the fast flag);", v_name[q]);
        else
            printf("  %-16s box_prep vs cbx_transform_box_as(&p.a, p.cls): %7ld boxes, %ld "
                   "differ, in place %ld differ;", v_name[q], st.one[q], st.one_fail[q],
                   st.inplace_fail[q]);
        printf(" boxes_prep vs cbx_transform_boxes: %5ld batches (%ld boxes), %ld differ\n",
               st.many[q], st.many_boxes[q], st.many_fail[q]);
    }
    printf("  forged structs' boxes_prep boxes against the exact oracle: %ld boxes, %ld failed\n",
           st.exact, st.exact_fail);
    printf("  CPU time %.2f s\n", (double)(clock() - t0) / CLOCKS_PER_SEC);
    xu_clear(&x);
    printf("%ld passed, %ld failed\n", st.batches - st.failed, st.failed);
    return st.failed ? 1 : 0;
}
