/*
 * batch_check.c: part of tests/test_batch.c (batch_parts.h): one batch
 * checked (cbx_transform_boxes against cbx_transform_box_as box by box:
 * bits, statuses, guards, inputs), and the prepared forms on it
 * (cbx_prepare's struct, a zero-initialised one, forged classes and fast
 * flags: cbx_transform_box_prep, cbx_transform_boxes_prep and the exact
 * oracle), with the failure log.
 */
#include <stdio.h>
#include <string.h>
#include <math.h>

#include "batch_parts.h"

/* the names of the box kinds and of the prepared structs, in the logs */
const char *const bat_b_name[NB] = { "normal", "NaN", "empty", "out-of-domain",
                                     "half-space", "flat", "fast-range-edge", "special" };
const char *const bat_v_name[NV] = { "cbx_prepare", "zero-init", "cls forged",
                                     "fast+cls forged" };

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
                         bat_b_name[kinds[k]], bat_v_name[v], p->fast, cls, cbx_status_name(s),
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
                         "(out == in) differs", (unsigned long)k, bat_b_name[kinds[k]],
                         bat_v_name[v]);
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
                 "cbx_transform_boxes %s; boxes %s, guards %s, *p %s", bat_v_name[v], p0.fast, cls,
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
                         "cls %s): %s", (unsigned long)k, bat_b_name[kinds[k]], bat_v_name[v],
                         p0.fast, cls, vd.why);
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
void bat_run_batch(stats *st, xu_exact *x, const cbx_affine *a, const cbx_box *in,
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
                     "expects %s", (unsigned long)k, bat_b_name[kinds[k]], cbx_status_name(s),
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
                         (unsigned long)k, bat_b_name[kinds[k]]);
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
