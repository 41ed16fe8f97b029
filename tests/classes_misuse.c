/*
 * Part 4 of test_classes (tests/classes_parts.h): misuse of the class hint
 * of cbx_transform_box_as (a class the map is not in, ints outside the
 * enum), on a table of maps with the exact image written out and on part
 * 2's random draws.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "classes_parts.h"

/* ---------------------------------------------------------------------- */
/* Part 4: misuse, cbx_transform_box_as with any cls                      */
/* ---------------------------------------------------------------------- */

/* The cls of cbx_transform_box_as is a hint (certbox.h): a class the map is
 * not in (larger than its class) or a value outside the enum runs the
 * general kernel.  Whether v is a class of the map is decided here by
 * rule_class (part 1 checks it against cbx_classify). */
static int general_expected(int v, const cbx_affine *a)
{
    return v == CBX_CLASS_GENERAL || !(v >= 0 && v <= clt_rule_class(a));
}

static void log_misuse(long id, const char *what, int v, const char *why, const cbx_affine *a,
                       const cbx_box *in, const cbx_box *o, const cbx_box *g)
{
    char nb[16];
    if (clt_fail_logs++ >= MAX_FAIL_LOGS) return;
    printf("FAIL misuse %s %ld (map of class %s, called as %s): %s\n", what, id,
           clt_cls_name[clt_rule_class(a)], xu_cls_str(v, nb), why);
    xu_print_case(stdout, a, in);
    xu_print_box(stdout, "as", o);
    xu_print_box(stdout, "cbx_transform_box", g);
}

/* One call cbx_transform_box_as(a, xu_cls_values[vi], in, o), judged by
 * every exact check of exact_util (mpq corners when corners != 0), against
 * cbx_transform_box's status sg, and bit for bit against its output g when
 * the general kernel is expected; inputs unchanged.  Returns 1 on failure. */
static int misuse_call(xu_exact *x, ustats *st, int vi, const cbx_affine *a, const cbx_box *in,
                       const cbx_box *g, cbx_status sg, int corners, const char *what, long id,
                       cbx_box *o)
{
    int v = xu_cls_values[vi], bad = 0;
    cbx_affine a0 = *a;
    cbx_box in0 = *in;
    cbx_status s;
    xu_verdict vd;
    char why[200];
    clt_fill_nan(o);
    s = cbx_transform_box_as(a, (cbx_class)v, in, o);
    st->calls++;
    st->v_calls[vi]++;
    if (memcmp(&a0, a, sizeof a0) || memcmp(&in0, in, sizeof in0)) {
        st->v_input_fail[vi]++;
        log_misuse(id, what, v, "the call modified its inputs", &a0, &in0, o, g);
        return 1;
    }
    if (xu_check_result(x, a, in, o, s, corners, &vd)) {
        st->v_exact_fail[vi]++;
        log_misuse(id, what, v, vd.why, a, in, o, g);
        bad = 1;
    }
    if (s != sg) {
        st->v_status_fail[vi]++;
        snprintf(why, sizeof why, "status %s, cbx_transform_box %s", cbx_status_name(s),
                 cbx_status_name(sg));
        if (!bad) log_misuse(id, what, v, why, a, in, o, g);
        bad = 1;
    }
    if (general_expected(v, a)) {
        st->v_general[vi]++;
        if (memcmp(o, g, sizeof *o)) {
            st->v_bits_fail[vi]++;
            if (!bad) log_misuse(id, what, v, "not bit for bit cbx_transform_box's output (the "
                                 "general kernel is expected)", a, in, o, g);
            bad = 1;
        }
    }
    return bad;
}

/* Every cls value on one input; o[vi] gets each call's output, *sg
 * cbx_transform_box's status (every call must return it). */
static int misuse_case(xu_exact *x, ustats *st, const cbx_affine *a, const cbx_box *in,
                       int corners, const char *what, long id, cbx_box o[XU_NCLS_VALUES],
                       cbx_status *sg)
{
    cbx_box g;
    int vi, bad = 0;
    clt_fill_nan(&g);
    *sg = cbx_transform_box(a, in, &g);
    for (vi = 0; vi < XU_NCLS_VALUES; vi++)
        bad |= misuse_call(x, st, vi, a, in, &g, *sg, corners, what, id, &o[vi]);
    return bad;
}

/* Maps and boxes whose exact image is known and written out (all values
 * small integers, or powers of 2: the comparisons below are exact), each
 * with every cls value: the output must contain img with CBX_OK.  Before
 * the hint was checked, IDENTITY on diag(2,2,2) returned [0,1]^3 with
 * CBX_OK (the identity kernel copies the box). */
typedef struct misuse_row { const char *name; cbx_affine a; cbx_box in, img; } misuse_row;
static const misuse_row misuse_table[] = {
    { "diag(2,2,2) on [0,1]^3",
      XU_MAT(XU_ROW(2, 0, 0, 0), XU_ROW(0, 2, 0, 0), XU_ROW(0, 0, 2, 0)),
      XU_BOX(0, 1, 0, 1, 0, 1), XU_BOX(0, 2, 0, 2, 0, 2) },
    { "translation (1,2,3) on [0,1]^3",
      XU_MAT(XU_ROW(1, 0, 0, 1), XU_ROW(0, 1, 0, 2), XU_ROW(0, 0, 1, 3)),
      XU_BOX(0, 1, 0, 1, 0, 1), XU_BOX(1, 2, 2, 3, 3, 4) },
    { "diag(-1,3,1/2) + (0,0,1)",
      XU_MAT(XU_ROW(-1, 0, 0, 0), XU_ROW(0, 3, 0, 0), XU_ROW(0, 0, 0.5, 1)),
      XU_BOX(0, 1, -1, 2, 2, 4), XU_BOX(-1, 0, -3, 6, 2, 3) },
    { "permutation (y, -z, 2x)",
      XU_MAT(XU_ROW(0, 1, 0, 0), XU_ROW(0, 0, -1, 0), XU_ROW(2, 0, 0, 0)),
      XU_BOX(0, 1, 2, 3, 4, 5), XU_BOX(2, 3, -5, -4, 0, 2) },
    { "shear x + y",
      XU_MAT(XU_ROW(1, 1, 0, 0), XU_ROW(0, 1, 0, 0), XU_ROW(0, 0, 1, 0)),
      XU_BOX(0, 1, 2, 3, 4, 5), XU_BOX(2, 4, 2, 3, 4, 5) },
    { "huge diag(2^600, 2^600, 1) + (0, 0, 2^1000)",
      XU_MAT(XU_ROW(0x1p600, 0, 0, 0), XU_ROW(0, 0x1p600, 0, 0), XU_ROW(0, 0, 1, 0x1p1000)),
      XU_BOX(0, 1, 0, 1, 0, 1), XU_BOX(0, 0x1p600, 0, 0x1p600, 0x1p1000, 0x1p1000) },
    { "huge permutation (2^1000 z, y, x)",
      XU_MAT(XU_ROW(0, 0, 0x1p1000, 0), XU_ROW(0, 1, 0, 0), XU_ROW(1, 0, 0, 0)),
      XU_BOX(0, 1, 0, 1, 0, 1), XU_BOX(0, 0x1p1000, 0, 1, 0, 1) },
};
#define N_MISUSE_TABLE ((int)(sizeof misuse_table / sizeof misuse_table[0]))

const int clt_n_misuse_table = N_MISUSE_TABLE;

static int contains(const cbx_box *o, const cbx_box *img)
{
    int j;
    for (j = 0; j < 3; j++)
        if (!(o->lo[j] <= img->lo[j] && o->hi[j] >= img->hi[j])) return 0;
    return 1;
}

void clt_run_misuse(xu_rng *r, xu_exact *x, ustats *st, long n, long *bxk,
                    long corner_every)
{
    cbx_box o[XU_NCLS_VALUES], in;
    cbx_affine a;
    cbx_status sg;
    long c;
    int k, vi;
    char nb[16];
    for (k = 0; k < N_MISUSE_TABLE; k++) {
        const misuse_row *t = &misuse_table[k];
        int bad = misuse_case(x, st, &t->a, &t->in, 1, "table", k, o, &sg);
        for (vi = 0; vi < XU_NCLS_VALUES; vi++) { /* every call returned sg */
            st->table_calls++;
            if (sg != CBX_OK || !contains(&o[vi], &t->img)) {
                st->table_img_fail++;
                if (!bad) log_misuse(k, "table", xu_cls_values[vi], "the exact image (written "
                                     "out) is not contained, or the status is not CBX_OK",
                                     &t->a, &t->in, &o[vi], &t->img);
                bad = 1;
            }
        }
        if (k == 0) /* the case of the old bug, shown */
            printf("  %s as %s: [%a, %a] x [%a, %a] x [%a, %a] (%s [0,2]^3)\n", t->name,
                   xu_cls_str(CBX_CLASS_IDENTITY, nb), o[CBX_CLASS_IDENTITY].lo[0],
                   o[CBX_CLASS_IDENTITY].hi[0], o[CBX_CLASS_IDENTITY].lo[1],
                   o[CBX_CLASS_IDENTITY].hi[1], o[CBX_CLASS_IDENTITY].lo[2],
                   o[CBX_CLASS_IDENTITY].hi[2],
                   contains(&o[CBX_CLASS_IDENTITY], &t->img) ? "contains" : "DOES NOT contain");
        st->cases++;
        if (bad) st->failed++;
    }
    for (c = 0; c < n; c++) {
        bxk[clt_gen_kernel_case(r, &a, &in, (int)(c % NCLS))]++;
        st->map_cls[clt_rule_class(&a)]++;
        st->cases++;
        if (misuse_case(x, st, &a, &in, c % corner_every == 0, "case", c, o, &sg)) st->failed++;
    }
}
