/*
 * Part 3 of test_classes (tests/classes_parts.h): the motion box
 * (cbx_motion_box) of pairs of maps against exact integer and rational
 * arithmetic over sampled s, with the pairs drawn here.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "classes_parts.h"

#define NS 10 /* sampled s per motion case */

/* ---------------------------------------------------------------------- */
/* Part 3: motion                                                         */
/* ---------------------------------------------------------------------- */

const char *const clt_pair_name[NPAIR] = { "general pair", "class pair", "identical",
                                           "sign-flipped", "NaN", "out-of-domain",
                                           "half-space", "empty" };

typedef struct mscratch {
    mpz_t V0[8], V1[8], LO, HI, W, Tq, L0, L1, S0, S1, M, G, Sm;
    mpq_t c[3], t, v, w, s, s1, lo, hi;
} mscratch;

static void ms_init(mscratch *m)
{
    int k;
    for (k = 0; k < 8; k++) mpz_inits(m->V0[k], m->V1[k], (mpz_ptr)0);
    mpz_inits(m->LO, m->HI, m->W, m->Tq, m->L0, m->L1, m->S0, m->S1, m->M, m->G, m->Sm,
              (mpz_ptr)0);
    for (k = 0; k < 3; k++) mpq_init(m->c[k]);
    mpq_inits(m->t, m->v, m->w, m->s, m->s1, m->lo, m->hi, (mpq_ptr)0);
}

static void ms_clear(mscratch *m)
{
    int k;
    for (k = 0; k < 8; k++) mpz_clears(m->V0[k], m->V1[k], (mpz_ptr)0);
    mpz_clears(m->LO, m->HI, m->W, m->Tq, m->L0, m->L1, m->S0, m->S1, m->M, m->G, m->Sm,
               (mpz_ptr)0);
    for (k = 0; k < 3; k++) mpq_clear(m->c[k]);
    mpq_clears(m->t, m->v, m->w, m->s, m->s1, m->lo, m->hi, (mpq_ptr)0);
}

/* z = (t + sum_j m_j c_j) * 2^XU_SHIFT at corner c (row i; all finite). */
static void corner_scaled(xu_exact *x, mpz_t z, const cbx_affine *a, const cbx_box *in, int i,
                          unsigned c)
{
    int j;
    xu_scaled_d(x, z, a->m[i][3]);
    for (j = 0; j < 3; j++) {
        xu_scaled_mul(x, x->pl, a->m[i][j], (c >> j) & 1u ? in->hi[j] : in->lo[j]);
        mpz_add(z, z, x->pl);
    }
}

/* The interpolated row of M(s), s = p/q, into m->c[0..2], m->t (mpq). */
static void interp_row(mscratch *m, const cbx_affine *a0, const cbx_affine *a1, int i,
                       unsigned long p, unsigned long q)
{
    int j;
    mpq_set_ui(m->s, p, q);
    mpq_canonicalize(m->s);
    mpq_set_ui(m->s1, 1, 1);
    mpq_sub(m->s1, m->s1, m->s);
    for (j = 0; j < 4; j++) {
        mpq_ptr d = j < 3 ? m->c[j] : m->t;
        mpq_set_d(m->v, a0->m[i][j]);
        mpq_mul(d, m->v, m->s1);
        mpq_set_d(m->v, a1->m[i][j]);
        mpq_mul(m->v, m->v, m->s);
        mpq_add(d, d, m->v);
    }
}

/* Extended vertex value of the interpolated row (mpq in m->v): upper = 0,
 * the inf over the real points of the box; returns 0 when it is -inf
 * (+inf for upper = 1), i.e. a needed box end is infinite. */
static int interp_vertex(mscratch *m, const cbx_box *in, int upper)
{
    int j;
    mpq_set(m->v, m->t);
    for (j = 0; j < 3; j++) {
        int sg = mpq_sgn(m->c[j]);
        double e;
        if (sg == 0) continue;
        e = (sg > 0) == (upper != 0) ? in->hi[j] : in->lo[j];
        if (isinf(e)) return 0;
        mpq_set_d(m->w, e);
        mpq_mul(m->w, m->w, m->c[j]);
        mpq_add(m->v, m->v, m->w);
    }
    return 1;
}

static void log_motion(long id, const char *kind, const char *why, const cbx_affine *a0,
                       const cbx_affine *a1, const cbx_box *in, const cbx_box *o)
{
    if (clt_fail_logs++ >= MAX_FAIL_LOGS) return;
    printf("FAIL motion case %ld (%s): %s\n", id, kind, why);
    clt_print_map("m0", a0);
    clt_print_map("m1", a1);
    xu_print_box(stdout, "in", in);
    if (o) xu_print_box(stdout, "out", o);
}

/* the union end: bitwise one of the two, with the value of the min / max
 * (a tie between 0.0 and -0.0 may take either) */
static int union_ok(double e, double e0, double e1, int upper, long *ties)
{
    double want = upper ? (e0 >= e1 ? e0 : e1) : (e0 <= e1 ? e0 : e1);
    if (e0 == e1 && !clt_same_bits(e0, e1)) (*ties)++;
    return (clt_same_bits(e, e0) || clt_same_bits(e, e1)) && e == want;
}

static void motion_case(xu_exact *x, mscratch *m, mstats *st, const cbx_affine *a0,
                        const cbx_affine *a1, const cbx_box *in, int kind, int direct, long id,
                        const unsigned long sp[NS], const unsigned long sq[NS])
{
    cbx_affine c0 = *a0, c1 = *a1;
    cbx_box cin = *in, o, b0, b1, ip;
    cbx_status s, s2, want;
    int i, j, bad = 0;
    char why[240];
    const char *kn = clt_pair_name[kind];

    st->cases++;
    st->kind[kind]++;
    clt_fill_nan(&o);
    s = cbx_motion_box(a0, a1, in, &o);
    if (memcmp(&c0, a0, sizeof c0) || memcmp(&c1, a1, sizeof c1) || memcmp(&cin, in, sizeof cin)) {
        st->input_fail++;
        log_motion(id, kn, "the call modified its inputs", &c0, &c1, &cin, &o);
        bad = 1;
    }
    (void)cbx_transform_box(&c0, &cin, &b0);
    (void)cbx_transform_box(&c1, &cin, &b1);

    if (xu_has_nan(&c0, &cin) || xu_has_nan(&c1, &cin)) {
        want = CBX_EINVAL;
        for (i = 0; i < 3; i++)
            if (!(isinf(o.lo[i]) && o.lo[i] < 0 && isinf(o.hi[i]) && o.hi[i] > 0)) {
                st->special_fail++;
                if (!bad) log_motion(id, kn, "EINVAL: out is not [-inf,+inf]^3", &c0, &c1, &cin, &o);
                bad = 1;
                break;
            }
    } else if (xu_is_empty(&cin)) {
        want = CBX_EMPTY;
        for (i = 0; i < 3; i++)
            if (!(isinf(o.lo[i]) && o.lo[i] > 0 && isinf(o.hi[i]) && o.hi[i] < 0)) {
                st->special_fail++;
                if (!bad) log_motion(id, kn, "EMPTY: out is not lo=+inf, hi=-inf", &c0, &c1, &cin, &o);
                bad = 1;
                break;
            }
    } else {
        int mixed = 0;
        for (i = 0; i < 3; i++) {
            int f0 = xu_row_in_domain(&c0, &cin, i), f1 = xu_row_in_domain(&c1, &cin, i);
            double lo = o.lo[i], hi = o.hi[i];
            if (f0 != f1) mixed = 1;
            if (f0 != f1 || !xu_map_row_finite(&c0, i) || !xu_map_row_finite(&c1, i)) {
                if (f0 != f1) st->ax_mixed++;
                else st->ax_infmap++;
                if (!(isinf(lo) && lo < 0 && isinf(hi) && hi > 0)) {
                    st->whole_fail++;
                    snprintf(why, sizeof why, "axis %d: %s but not [-inf,+inf]", i,
                             f0 != f1 ? "one row full, the other not" : "infinite map entry");
                    if (!bad) log_motion(id, kn, why, &c0, &c1, &cin, &o);
                    bad = 1;
                }
                continue;
            }
            /* not mixed: the union of the two general outputs */
            st->union_checks++;
            if (!union_ok(lo, b0.lo[i], b1.lo[i], 0, &st->zero_ties)
                || !union_ok(hi, b0.hi[i], b1.hi[i], 1, &st->zero_ties)) {
                st->union_fail++;
                snprintf(why, sizeof why, "axis %d: [%a, %a] is not the union of [%a, %a] and "
                         "[%a, %a]", i, lo, hi, b0.lo[i], b0.hi[i], b1.lo[i], b1.hi[i]);
                if (!bad) log_motion(id, kn, why, &c0, &c1, &cin, &o);
                bad = 1;
            }
            if (f0 && f1) {
                unsigned c;
                int k, cf = 0, ef = 0;
                st->ax_full++;
                if (!isfinite(lo) || !isfinite(hi) || lo > hi) {
                    st->finite_fail++;
                    snprintf(why, sizeof why, "axis %d: both rows full but out = [%a, %a]", i, lo, hi);
                    if (!bad) log_motion(id, kn, why, &c0, &c1, &cin, &o);
                    bad = 1;
                    continue;
                }
                for (c = 0; c < 8; c++) {
                    corner_scaled(x, m->V0[c], &c0, &cin, i, c);
                    corner_scaled(x, m->V1[c], &c1, &cin, i, c);
                }
                xu_scaled_d(x, m->LO, lo);
                xu_scaled_d(x, m->HI, hi);
                xu_row_bounds(x, &c0, &cin, i);
                mpz_set(m->L0, x->L); mpz_set(m->S0, x->S); mpz_set(m->M, x->H);
                xu_row_bounds(x, &c1, &cin, i);
                mpz_set(m->L1, x->L); mpz_set(m->S1, x->S);
                /* m->L0 = min(L0, L1) (the extreme over s in {0, 1}), m->M = max */
                if (mpz_cmp(m->L1, m->L0) < 0) mpz_set(m->L0, m->L1);
                if (mpz_cmp(x->H, m->M) > 0) mpz_set(m->M, x->H);
                for (k = 0; k < NS; k++) {
                    unsigned long p = sp[k], q = sq[k];
                    for (c = 0; c < 8; c++) {
                        /* W = q (M(s) c)_i = (q - p) V0 + p V1 */
                        mpz_mul_ui(m->W, m->V0[c], q - p);
                        mpz_addmul_ui(m->W, m->V1[c], p);
                        st->corner_checks++;
                        mpz_mul_ui(m->Tq, m->LO, q);
                        if (mpz_cmp(m->Tq, m->W) > 0) cf++;
                        mpz_mul_ui(m->Tq, m->HI, q);
                        if (mpz_cmp(m->W, m->Tq) > 0) cf++;
                        /* the extreme over s: never beyond the one over {0, 1} */
                        st->extreme_checks++;
                        mpz_mul_ui(m->Tq, m->L0, q);
                        if (mpz_cmp(m->W, m->Tq) < 0) ef++;
                        mpz_mul_ui(m->Tq, m->M, q);
                        if (mpz_cmp(m->W, m->Tq) > 0) ef++;
                    }
                }
                if (cf) {
                    st->corner_fail += cf;
                    snprintf(why, sizeof why, "axis %d: %d corner images (M(s) c) outside "
                             "[%a, %a]", i, cf, lo, hi);
                    if (!bad) log_motion(id, kn, why, &c0, &c1, &cin, &o);
                    bad = 1;
                }
                if (ef) {
                    st->extreme_fail += ef;
                    snprintf(why, sizeof why, "axis %d: an extreme over sampled s beyond the one "
                             "over s in {0,1} (oracle)", i);
                    if (!bad) log_motion(id, kn, why, &c0, &c1, &cin, &o);
                    bad = 1;
                }
                /* tightness against the exact extreme over s */
                mpz_set(m->Sm, mpz_cmp(m->S0, m->S1) >= 0 ? m->S0 : m->S1);
                mpz_sub(m->G, m->L0, m->LO);
                mpz_set(x->S, m->Sm);
                {
                    double u1 = xu_units(x, m->G, m->Sm), u2;
                    int t1, t2;
                    mpz_set(x->L, m->L0);
                    t1 = xu_lo_within_proven(x, lo);
                    mpz_sub(m->G, m->HI, m->M);
                    u2 = xu_units(x, m->G, m->Sm);
                    mpz_set(x->H, m->M);
                    mpz_set(x->S, m->Sm);
                    t2 = xu_hi_within_proven(x, hi);
                    if (!t1 || !t2) {
                        st->tight_fail++;
                        snprintf(why, sizeof why, "axis %d: beyond 12 u max(S0,S1) + 2^-1065 of "
                                 "the exact extreme over s (units %.3g, %.3g)", i, u1, u2);
                        if (!bad) log_motion(id, kn, why, &c0, &c1, &cin, &o);
                        bad = 1;
                    }
                    if (!xu_scale_tiny(m->Sm)) {
                        st->ex_axes++;
                        st->sum_ex += u1 + u2;
                        if (u1 > st->max_ex) st->max_ex = u1;
                        if (u2 > st->max_ex) st->max_ex = u2;
                    }
                }
                if (direct) { /* M(s) entry by entry, mpq, every corner */
                    int df = 0;
                    mpq_set_d(m->lo, lo);
                    mpq_set_d(m->hi, hi);
                    for (k = 0; k < NS; k++) {
                        interp_row(m, &c0, &c1, i, sp[k], sq[k]);
                        for (c = 0; c < 8; c++) {
                            mpq_set(m->v, m->t);
                            for (j = 0; j < 3; j++) {
                                mpq_set_d(m->w, (c >> j) & 1u ? cin.hi[j] : cin.lo[j]);
                                mpq_mul(m->w, m->w, m->c[j]);
                                mpq_add(m->v, m->v, m->w);
                            }
                            st->direct_checks++;
                            if (mpq_cmp(m->lo, m->v) > 0 || mpq_cmp(m->v, m->hi) > 0) df++;
                        }
                    }
                    if (df) {
                        st->direct_fail += df;
                        snprintf(why, sizeof why, "axis %d: %d corner images outside (mpq, M(s) "
                                 "entry by entry)", i, df);
                        if (!bad) log_motion(id, kn, why, &c0, &c1, &cin, &o);
                        bad = 1;
                    }
                }
            } else { /* neither row full, finite map rows */
                int k, up, ef = 0;
                st->ax_none++;
                for (k = 0; k < NS; k++) {
                    interp_row(m, &c0, &c1, i, sp[k], sq[k]);
                    for (up = 0; up < 2; up++) {
                        double e = up ? hi : lo;
                        int bounded;
                        if (isinf(e) && (up ? e > 0 : e < 0)) continue; /* no claim */
                        st->end_checks++;
                        bounded = interp_vertex(m, &cin, up);
                        if (!isfinite(e) || !bounded) {
                            ef++;
                            continue;
                        }
                        mpq_set_d(m->w, e);
                        if (up ? mpq_cmp(m->w, m->v) < 0 : mpq_cmp(m->w, m->v) > 0) ef++;
                    }
                }
                if (ef) {
                    st->end_fail += ef;
                    snprintf(why, sizeof why, "axis %d (neither row full): %d end checks fail "
                             "against the exact inf/sup of M(s) over the box", i, ef);
                    if (!bad) log_motion(id, kn, why, &c0, &c1, &cin, &o);
                    bad = 1;
                }
            }
        }
        want = xu_expected_status(&c0, &cin) == CBX_OK && xu_expected_status(&c1, &cin) == CBX_OK
               && !mixed ? CBX_OK : CBX_ERANGE;
    }
    if (s != want) {
        st->status_fail++;
        snprintf(why, sizeof why, "status %s, expected %s", cbx_status_name(s), cbx_status_name(want));
        if (!bad) log_motion(id, kn, why, &c0, &c1, &cin, &o);
        bad = 1;
    }
    if (xu_status_index(s) >= 0) st->st[xu_status_index(s)]++;
    ip = cin;
    s2 = cbx_motion_box(&c0, &c1, &ip, &ip);
    if (s2 != s || memcmp(&ip, &o, sizeof o)) {
        st->inplace_fail++;
        if (!bad) log_motion(id, kn, "in place (out == in) differs", &c0, &c1, &cin, &ip);
        bad = 1;
    }
    if (bad) st->failed++;
}

static void make_ood(xu_rng *r, cbx_affine *a)
{
    int i = xu_rng_int(r, 0, 2);
    if (xu_rng_int(r, 0, 1)) a->m[i][3] = clt_sgn(r) * (xu_rng_int(r, 0, 1) ? 0x1p1019 : DBL_MAX);
    else {
        double v = clt_sgn_pow(r, 1000, 1023); /* then the column: gcc's order, made explicit */
        a->m[i][xu_rng_int(r, 0, 2)] = v;
    }
}

void clt_run_motion(xu_rng *r, xu_exact *x, mstats *st, long n, long direct_every)
{
    mscratch m;
    long c;
    cbx_affine a0, a1;
    cbx_box in;
    unsigned long sp[NS] = { 0, 1, 1, 1, 2 }, sq[NS] = { 1, 1, 2, 3, 7 };
    int i, j, k;
    ms_init(&m);
    for (c = 0; c < n; c++) {
        int kind = (int)(c % NPAIR), g = xu_rng_int(r, 0, 3) == 0;
        for (k = 5; k < NS; k++) {
            sq[k] = (unsigned long)xu_rng_int(r, 2, 1 << 20);
            sp[k] = (unsigned long)xu_rng_int(r, 1, (int)sq[k] - 1);
        }
        clt_gen_map_cls(r, &a0, xu_rng_int(r, 0, NCLS - 1), g);
        clt_gen_map_cls(r, &a1, xu_rng_int(r, 0, NCLS - 1), g);
        clt_gen_box(r, &in, g ? clt_pick_box_kind(r) : BX_REAL);
        switch (kind) {
        case P_GENGEN:
            clt_gen_map_cls(r, &a0, CBX_CLASS_GENERAL, 0);
            clt_gen_map_cls(r, &a1, CBX_CLASS_GENERAL, 0);
            clt_gen_box(r, &in, xu_rng_int(r, 0, 3) ? BX_REAL : BX_FLAT);
            break;
        case P_CLASSES:
            clt_gen_map_cls(r, &a0, xu_rng_int(r, 0, NCLS - 1), g);
            clt_gen_map_cls(r, &a1, xu_rng_int(r, 0, NCLS - 1), g);
            break;
        case P_SAME:
            a1 = a0;
            break;
        case P_FLIP: /* entries change sign (cross 0) inside the interval */
            a1 = a0;
            for (i = 0; i < 3; i++)
                for (j = 0; j < 4; j++)
                    if (xu_rng_int(r, 0, 1)) a1.m[i][j] = -a1.m[i][j];
            if (xu_rng_int(r, 0, 1)) clt_gen_box(r, &in, BX_HALF);
            break;
        case P_NAN:
            if (xu_rng_int(r, 0, 2) == 0) clt_gen_box(r, &in, BX_NAN);
            else (xu_rng_int(r, 0, 1) ? &a0 : &a1)->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 3)] = NAN;
            if (xu_rng_int(r, 0, 3) == 0) clt_gen_box(r, &in, BX_EMPTY); /* NaN wins over empty */
            break;
        case P_OOD:
            if (xu_rng_int(r, 0, 2)) make_ood(r, xu_rng_int(r, 0, 1) ? &a0 : &a1);
            else clt_gen_box(r, &in, BX_BIG);
            if (xu_rng_int(r, 0, 3) == 0) make_ood(r, &a0), make_ood(r, &a1);
            if (xu_rng_int(r, 0, 5) == 0)
                (xu_rng_int(r, 0, 1) ? &a0 : &a1)->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 3)] = clt_sgn(r) * INF;
            break;
        case P_HALF:
            clt_gen_box(r, &in, BX_HALF);
            if (xu_rng_int(r, 0, 4) == 0)
                (xu_rng_int(r, 0, 1) ? &a0 : &a1)->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 3)] = clt_sgn(r) * INF;
            break;
        default: /* P_EMPTY */
            clt_gen_box(r, &in, BX_EMPTY);
            break;
        }
        motion_case(x, &m, st, &a0, &a1, &in, kind, c % direct_every == 0, c, sp, sq);
    }
    ms_clear(&m);
}
