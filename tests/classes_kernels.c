/*
 * Parts 1 and 2 of test_classes (tests/classes_parts.h): cbx_classify on
 * maps of a known class and their near misses, and the class kernels
 * (cbx_transform_box_as with every class that holds the map) against
 * cbx_transform_box and the exact checks of exact_util.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "classes_parts.h"

/* ---------------------------------------------------------------------- */
/* Part 1: classification                                                 */
/* ---------------------------------------------------------------------- */

const char *const clt_kind_name[NKIND] = {
    "identity", "translate", "scale", "permute", "general",
    "diag 1+2^-52", "diag 1-2^-53", "diag -1", "off-diag 2^-1074", "tiny in zero row",
    "permute+tiny", "translation 2^-1074", "all zeros -0.0", "zero scale", "NaN entry",
    "inf entry", "DBL_MAX entries"
};

/* Builds a map of kind k; returns the class expected by construction. */
static int gen_kind(xu_rng *r, cbx_affine *a, int k)
{
    int g = xu_rng_int(r, 0, 2) == 0, i, j, c;
    switch (k) {
    case C_ID: clt_gen_map_cls(r, a, CBX_CLASS_IDENTITY, g); return CBX_CLASS_IDENTITY;
    case C_TR: clt_gen_map_cls(r, a, CBX_CLASS_TRANSLATE, g); return CBX_CLASS_TRANSLATE;
    case C_SC: clt_gen_map_cls(r, a, CBX_CLASS_SCALE, g); return CBX_CLASS_SCALE;
    case C_PE: clt_gen_map_cls(r, a, CBX_CLASS_PERMUTE, g); return CBX_CLASS_PERMUTE;
    case C_GE:
        clt_gen_map_cls(r, a, CBX_CLASS_GENERAL, g);
        return CBX_CLASS_GENERAL;
    case M_DIAG_UP: case M_DIAG_DN:
        c = xu_rng_int(r, 0, 1) ? CBX_CLASS_IDENTITY : CBX_CLASS_TRANSLATE;
        clt_gen_map_cls(r, a, c, g);
        i = xu_rng_int(r, 0, 2);
        a->m[i][i] = k == M_DIAG_UP ? 1.0 + 0x1p-52 : 1.0 - 0x1p-53;
        return CBX_CLASS_SCALE;
    case M_NEG_ONE:
        clt_gen_map_cls(r, a, xu_rng_int(r, 0, 1) ? CBX_CLASS_IDENTITY : CBX_CLASS_TRANSLATE, g);
        a->m[0][0] = -1.0;
        a->m[1][1] = 1.0;
        a->m[2][2] = 1.0;
        return CBX_CLASS_SCALE;
    case M_OFF_TINY:
        clt_gen_map_cls(r, a, xu_rng_int(r, 0, 1) ? CBX_CLASS_IDENTITY : CBX_CLASS_TRANSLATE, g);
        i = xu_rng_int(r, 0, 2);
        j = (i + xu_rng_int(r, 1, 2)) % 3;
        a->m[i][j] = clt_sgn(r) * 0x1p-1074;
        return CBX_CLASS_GENERAL;
    case M_OFF_TINY_ZROW:
        clt_gen_map_cls(r, a, CBX_CLASS_SCALE, g);
        i = xu_rng_int(r, 0, 2);
        j = (i + xu_rng_int(r, 1, 2)) % 3;
        a->m[i][i] = clt_sgn(r) * 0.0;
        a->m[i][j] = clt_sgn(r) * 0x1p-1074;
        return CBX_CLASS_PERMUTE;
    case M_PERM_EXTRA:
        clt_gen_map_cls(r, a, CBX_CLASS_PERMUTE, g);
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++)
                if (a->m[i][j] != 0.0) break;
            if (j < 3) {
                a->m[i][(j + xu_rng_int(r, 1, 2)) % 3] = clt_sgn(r) * 0x1p-1074;
                break;
            }
        }
        return CBX_CLASS_GENERAL;
    case M_TR_TINY:
        clt_gen_map_cls(r, a, CBX_CLASS_IDENTITY, g);
        a->m[xu_rng_int(r, 0, 2)][3] = clt_sgn(r) * 0x1p-1074;
        return CBX_CLASS_TRANSLATE;
    case M_NEGZERO:
        for (i = 0; i < 3; i++)
            for (j = 0; j < 4; j++) a->m[i][j] = i == j ? 1.0 : -0.0;
        if (xu_rng_int(r, 0, 1)) {
            a->m[1][1] = -0.0; /* a diagonal -0.0: a zero scale */
            return CBX_CLASS_SCALE;
        }
        return CBX_CLASS_IDENTITY;
    case M_ZERO_SCALE:
        clt_gen_map_cls(r, a, CBX_CLASS_SCALE, g);
        for (i = 0; i < 3; i++)
            if (xu_rng_int(r, 0, 1)) a->m[i][i] = clt_sgn(r) * 0.0;
        if (a->m[0][0] == 1.0 && a->m[1][1] == 1.0 && a->m[2][2] == 1.0) a->m[1][1] = 0.0;
        return CBX_CLASS_SCALE;
    case M_NAN: case M_INF:
        clt_gen_map_cls(r, a, xu_rng_int(r, 0, NCLS - 1), g);
        a->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 3)] = k == M_NAN ? NAN : clt_sgn(r) * INF;
        return CBX_CLASS_GENERAL;
    default: /* M_HUGE */
        c = xu_rng_int(r, 0, 1) ? CBX_CLASS_SCALE : CBX_CLASS_PERMUTE;
        clt_gen_map_cls(r, a, c, g);
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++)
                if (a->m[i][j] != 0.0 && a->m[i][j] != 1.0) a->m[i][j] = clt_sgn(r) * DBL_MAX;
            a->m[i][3] = clt_sgn(r) * DBL_MAX;
        }
        return c; /* SCALE keeps a diagonal != 1, PERMUTE an off-diagonal nonzero */
    }
}

void clt_run_classify(xu_rng *r, cbx_affine *a, cstats *st, long n)
{
    long c;
    for (c = 0; c < n; c++) {
        int k = (int)(c % NKIND), want = gen_kind(r, a, k), rule = clt_rule_class(a);
        cbx_affine a0 = *a;
        int got = (int)cbx_classify(a);
        st->cases++;
        st->kind[k]++;
        if (got >= 0 && got < NCLS) st->got[got]++;
        if (rule != want) st->rule_disagree++;
        if (got != want || rule != want || memcmp(&a0, a, sizeof a0)) {
            st->failed++;
            st->kind_fail[k]++;
            if (clt_fail_logs++ < MAX_FAIL_LOGS) {
                printf("FAIL classify case %ld (%s): cbx_classify %d, by construction %d, "
                       "by rule %d\n", c, clt_kind_name[k], got, want, rule);
                clt_print_map("m", &a0);
            }
        }
    }
}

/* ---------------------------------------------------------------------- */
/* Part 2: class kernels                                                  */
/* ---------------------------------------------------------------------- */

static void log_kernel(long id, int cls, int as, const char *why, const cbx_affine *a,
                       const cbx_box *in, const cbx_box *o, const cbx_box *g)
{
    if (clt_fail_logs++ >= MAX_FAIL_LOGS) return;
    printf("FAIL kernel case %ld (classify %s, called as %s): %s\n", id, clt_cls_name[cls],
           clt_cls_name[as], why);
    xu_print_case(stdout, a, in);
    if (o) xu_print_box(stdout, "as", o);
    if (g) xu_print_box(stdout, "general", g);
}

static int contain_flags(const xu_verdict *v)
{
    return v->flag[XU_F_CONTAIN] + v->flag[XU_F_CORNER] + v->flag[XU_F_ENDCONT]
           + v->flag[XU_F_ENDCORNER] + v->flag[XU_F_FINITE] + v->flag[XU_F_ENDFIN];
}

static void kernel_case(xu_exact *x, kstats *ks, const cbx_affine *a, const cbx_box *in,
                        int corners, long id)
{
    cbx_affine a0 = *a;
    cbx_box in0 = *in, g, o, ip;
    cbx_status sg, s, s2;
    xu_verdict vg, v;
    int cls = (int)cbx_classify(a), c, i, f, bad = 0;
    char why[200];

    clt_fill_nan(&g);
    sg = cbx_transform_box(a, in, &g);
    if (xu_check_result(x, &a0, &in0, &g, sg, corners, &vg)) {
        for (f = 0; f < XU_NFLAGS; f++) ks[cls].gflag_fail[f] += vg.flag[f];
        log_kernel(id, cls, CBX_CLASS_GENERAL, vg.why, &a0, &in0, (const cbx_box *)0, &g);
        bad = 1;
    }
    ks[cls].cases++;
    if (xu_status_index(sg) >= 0) ks[cls].st[xu_status_index(sg)]++;

    for (c = cls; c >= 0; c--) {
        int nbad = 0;
        kstats *k = &ks[cls];
        clt_fill_nan(&o);
        s = cbx_transform_box_as(a, (cbx_class)c, in, &o);
        k->calls++;
        if (memcmp(&a0, a, sizeof a0) || memcmp(&in0, in, sizeof in0)) {
            k->input_diff++;
            log_kernel(id, cls, c, "the call modified its inputs", &a0, &in0, &o, &g);
            nbad = 1;
        }
        if (xu_check_result(x, &a0, &in0, &o, s, corners, &v)) {
            for (f = 0; f < XU_NFLAGS; f++) k->flag_fail[f] += v.flag[f];
            k->contain_fail += contain_flags(&v);
            if (!nbad) log_kernel(id, cls, c, v.why, &a0, &in0, &o, &g);
            nbad = 1;
        }
        if (s != sg) {
            k->status_diff++;
            snprintf(why, sizeof why, "status %s, cbx_transform_box %s", cbx_status_name(s),
                     cbx_status_name(sg));
            if (!nbad) log_kernel(id, cls, c, why, &a0, &in0, &o, &g);
            nbad = 1;
        }
        for (i = 0; i < 6; i++) {
            int up = i >= 3, j = i % 3;
            double e = up ? o.hi[j] : o.lo[j], eg = up ? g.hi[j] : g.lo[j];
            k->ends++;
            if (isinf(e) || isinf(eg) || e != e || eg != eg) {
                k->inf_ends++;
                if (!clt_same_bits(e, eg)) {
                    k->inf_diff++;
                    snprintf(why, sizeof why, "axis %d %s end %a, general %a (infinite ends must "
                             "be identical)", j, up ? "hi" : "lo", e, eg);
                    if (!nbad) log_kernel(id, cls, c, why, &a0, &in0, &o, &g);
                    nbad = 1;
                }
            } else {
                k->fin_ends++;
                if (up ? e > eg : e < eg) {
                    k->looser++;
                    snprintf(why, sizeof why, "axis %d %s end %a looser than general %a", j,
                             up ? "hi" : "lo", e, eg);
                    if (!nbad) log_kernel(id, cls, c, why, &a0, &in0, &o, &g);
                    nbad = 1;
                } else if (e != eg) {
                    k->tighter++;
                }
            }
        }
        /* in place */
        ip = in0;
        s2 = cbx_transform_box_as(a, (cbx_class)c, &ip, &ip);
        if (s2 != s || memcmp(&ip, &o, sizeof o)) {
            k->inplace_diff++;
            if (!nbad) log_kernel(id, cls, c, "in place (out == in) differs", &a0, &in0, &ip, &o);
            nbad = 1;
        }
        /* excess of the class kernel (own class) and of the general one */
        if (c == cls)
            for (i = 0; i < 3; i++)
                if (v.ax[i].checked && vg.ax[i].checked && !v.ax[i].tiny) {
                    double e1 = v.ax[i].ex_lo > v.ax[i].ex_hi ? v.ax[i].ex_lo : v.ax[i].ex_hi;
                    double e2 = vg.ax[i].ex_lo > vg.ax[i].ex_hi ? vg.ax[i].ex_lo : vg.ax[i].ex_hi;
                    k->axes++;
                    k->sum_ex += v.ax[i].ex_lo + v.ax[i].ex_hi;
                    k->sum_exg += vg.ax[i].ex_lo + vg.ax[i].ex_hi;
                    if (e1 > k->max_ex) k->max_ex = e1;
                    if (e2 > k->max_exg) k->max_exg = e2;
                }
        bad |= nbad;
    }
    if (bad) ks[cls].failed++;
}

/* A case of the class kernels: a map of class cls (realistic, extreme or
 * random exponents over the fast range; a NaN entry in 1 of 50) and a box
 * (fast-range boxes for most random-exponent maps); returns the box kind. */
int clt_gen_kernel_case(xu_rng *r, cbx_affine *a, cbx_box *in, int cls)
{
    int p = xu_rng_int(r, 0, 9), g = p < 4 ? 0 : p < 8 ? 1 : 2;
    int bk = g == 2 && xu_rng_int(r, 0, 3) ? BX_FASTR : clt_pick_box_kind(r);
    clt_gen_map_cls(r, a, cls, g);
    if (xu_rng_int(r, 0, 49) == 0) a->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 3)] = NAN;
    clt_gen_box(r, in, bk);
    return bk;
}

void clt_run_kernels(xu_rng *r, xu_exact *x, kstats *ks, long n, long *bxk,
                     long corner_every)
{
    long c;
    cbx_affine a;
    cbx_box in;
    for (c = 0; c < n; c++) {
        bxk[clt_gen_kernel_case(r, &a, &in, (int)(c % NCLS))]++;
        kernel_case(x, ks, &a, &in, c % corner_every == 0, c);
    }
}
