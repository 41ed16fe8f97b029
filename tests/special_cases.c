/*
 * special_cases.c: the table of test_special (tests/test_special.c, where
 * its columns are described): the columns' values (functions, base inputs,
 * special values, end kinds), the base inputs and the positions in them,
 * making the table (the expected columns from tests/special_oracle.c), and
 * printing a row's inputs and outputs (a failure's reproducer).
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <float.h>
#include <math.h>

#include "certbox.h"
#include "exact_util.h"
#include "special_parts.h"

/* ---------------------------------------------------------------------- */
/* The columns' values                                                    */
/* ---------------------------------------------------------------------- */

const char *const spc_fn_name[NFN] = {
    "transform_box", "transform_cbox", "box_to_cbox", "cbox_to_box",
    "sphere_box", "ellipsoid_box"
};
const int spc_fn_npos[NFN] = { 18, 18, 6, 6, 12, 15 };
const unsigned spc_fn_bases[NFN] = { 0x0f, 0x17, 0x0f, 0x07, 0x03, 0x03 };
const int spc_fn_cout[NFN] = { 0, 1, 1, 0, 0, 0 };

const char *const spc_base_name[NBASE] = { "ord", "point", "empty", "half", "zcol" };

const sval spc_vals[] = {
    { "NaN", NAN },
    { "-NaN", -NAN },
    { "+inf", INF },
    { "-inf", -INF },
    { "+0", 0.0 },
    { "-0", -0.0 },
    { "2^-1074", 0x1p-1074 },             /* smallest subnormal        */
    { "-2^-1074", -0x1p-1074 },
    { "maxsub", 0x0.fffffffffffffp-1022 }, /* largest subnormal         */
    { "2^-1022", 0x1p-1022 },             /* smallest normal (DBL_MIN) */
    { "1", 1.0 },
    { "-1", -1.0 },
    { "2^254", 0x1p254 },                 /* ellipsoid limit: inside   */
    { "2^254+", 0x1.0000000000001p254 },  /*                  outside  */
    { "-2^254", -0x1p254 },
    { "-2^254-", -0x1.0000000000001p254 },
    { "2^509", 0x1p509 },                 /* sphere / class 509 limit  */
    { "2^509+", 0x1.0000000000001p509 },
    { "-2^509", -0x1p509 },
    { "-2^509-", -0x1.0000000000001p509 },
    { "2^1018", 0x1p1018 },               /* translation / coordinate  */
    { "2^1018+", 0x1.0000000000001p1018 },
    { "-2^1018", -0x1p1018 },
    { "-2^1018-", -0x1.0000000000001p1018 },
    { "2^1019", 0x1p1019 },               /* conversions' limit        */
    { "2^1019+", 0x1.0000000000001p1019 },
    { "-2^1019", -0x1p1019 },
    { "-2^1019-", -0x1.0000000000001p1019 },
    { "DBL_MAX", DBL_MAX },
    { "-DBL_MAX", -DBL_MAX },
};
/* NVAL (special_parts.h) is the number of values: a compile-time check */
typedef char spc_nval_check[(int)(sizeof spc_vals / sizeof spc_vals[0]) == NVAL ? 1 : -1];

const char spc_end_char[NEND + 1] = "AFULWD";

/* ---------------------------------------------------------------------- */
/* Base inputs                                                            */
/* ---------------------------------------------------------------------- */

/* |m| <= 3: deep in the domain; column entries of magnitude <= 1 and > 1
 * both occur, so a coordinate of 2^1018 puts some rows in and some out. */
static const cbx_affine base_a = { {
    { 0.5, -2, 0.25, 1 },
    { 3, 0.125, -1, -4 },
    { -0.75, 1.5, 2, 0.5 },
} };
static const cbx_box ord_box = { { -1, 0.5, -4 }, { 2, 3, -1 } };
/* same box as ord_box, as centre / half */
static const cbx_cbox ord_cbox = { { 0.5, 1.75, -2.5 }, { 1.5, 1.25, 1.5 } };
/* a point with a zero coordinate (m = inf times 0) and |c| <= 1
 * (m = 2^1018 then stays in the domain) */
static const double point_c[3] = { 0.0, -0.5, 1.0 };

static const double ell_center[3] = { 1, -4, 0.5 };
static const double ell_radii[3] = { 1.5, 0.25, -2 };   /* negative is valid */
static const double ell_rot[3][3] = {                   /* not orthogonal    */
    { 0.5, -2, 0.25 }, { 3, 0.125, -1 }, { -0.75, 1.5, 2 }
};

static void base_input(int fn, int base, input *in)
{
    int i, j;
    memset(in, 0, sizeof *in);
    in->a = base_a;
    in->b = ord_box;
    in->cb = ord_cbox;
    memcpy(in->center, ell_center, sizeof in->center);
    memcpy(in->radii, ell_radii, sizeof in->radii);
    memcpy(in->rot, ell_rot, sizeof in->rot);
    if (base == B_POINT) {
        for (j = 0; j < 3; j++) {
            in->b.lo[j] = in->b.hi[j] = point_c[j];
            in->cb.c[j] = point_c[j];
            in->cb.h[j] = 0.0;
        }
        if (fn == FN_SPH)
            for (i = 0; i < 3; i++)
                for (j = 0; j < 3; j++) in->a.m[i][j] = 0.0;
        for (j = 0; j < 3; j++) in->radii[j] = 0.0;
    } else if (base == B_EMPTY) {
        in->b.lo[1] = 3.5;   /* > hi[1] = 3 */
        in->cb.h[1] = -1.0;
    } else if (base == B_HALF) {
        in->b.lo[0] = -INF;  /* x0 <= 2 */
        in->b.hi[2] = INF;   /* x2 >= -4 */
    } else if (base == B_ZCOL) {
        in->a.m[0][1] = 0.0; /* column 1 zero, both signs */
        in->a.m[1][1] = -0.0;
        in->a.m[2][1] = 0.0;
        in->cb.c[1] = INF;   /* unusable unless dropped */
        in->cb.h[1] = INF;
    }
}

/* The address of position pos of function fn in *in. */
static double *slot(input *in, int fn, int pos)
{
    switch (fn) {
    case FN_TBOX:
        if (pos < 12) return &in->a.m[pos / 4][pos % 4];
        return pos < 15 ? &in->b.lo[pos - 12] : &in->b.hi[pos - 15];
    case FN_TCBOX:
        if (pos < 12) return &in->a.m[pos / 4][pos % 4];
        return pos < 15 ? &in->cb.c[pos - 12] : &in->cb.h[pos - 15];
    case FN_B2C:
        return pos < 3 ? &in->b.lo[pos] : &in->b.hi[pos - 3];
    case FN_C2B:
        return pos < 3 ? &in->cb.c[pos] : &in->cb.h[pos - 3];
    case FN_SPH:
        return &in->a.m[pos / 4][pos % 4];
    default:
        if (pos < 3) return &in->center[pos];
        if (pos < 6) return &in->radii[pos - 3];
        return &in->rot[(pos - 6) / 3][(pos - 6) % 3];
    }
}

void spc_pos_name(int fn, int pos, char *buf, size_t n)
{
    switch (fn) {
    case FN_TBOX:
    case FN_TCBOX:
        if (pos < 12) snprintf(buf, n, "m[%d][%d]%s", pos / 4, pos % 4, pos % 4 == 3 ? " (t)" : "");
        else snprintf(buf, n, "%s[%d]", pos < 15 ? (fn == FN_TBOX ? "lo" : "c")
                                            : (fn == FN_TBOX ? "hi" : "h"), (pos - 12) % 3);
        break;
    case FN_B2C: snprintf(buf, n, "%s[%d]", pos < 3 ? "lo" : "hi", pos % 3); break;
    case FN_C2B: snprintf(buf, n, "%s[%d]", pos < 3 ? "c" : "h", pos % 3); break;
    case FN_SPH:
        snprintf(buf, n, "m[%d][%d]%s", pos / 4, pos % 4, pos % 4 == 3 ? " (t)" : "");
        break;
    default:
        if (pos < 3) snprintf(buf, n, "center[%d]", pos);
        else if (pos < 6) snprintf(buf, n, "radii[%d]", pos - 3);
        else snprintf(buf, n, "rot[%d][%d]", (pos - 6) / 3, (pos - 6) % 3);
    }
}

void spc_make_input(const row *r, input *in)
{
    base_input(r->fn, r->base, in);
    *slot(in, r->fn, r->pos) = spc_vals[r->val].v;
}

/* ---------------------------------------------------------------------- */
/* The table                                                              */
/* ---------------------------------------------------------------------- */

long spc_make_table(row *t)
{
    long n = 0;
    int fn, b, p, v;
    for (fn = 0; fn < NFN; fn++)
        for (b = 0; b < NBASE; b++)
            if (spc_fn_bases[fn] & (1u << b))
            for (p = 0; p < spc_fn_npos[fn]; p++)
                for (v = 0; v < NVAL; v++) {
                    if (t) {
                        input in;
                        row *r = &t[n];
                        r->fn = fn;
                        r->base = b;
                        r->pos = p;
                        r->val = v;
                        spc_make_input(r, &in);
                        r->expect = spc_oracle(fn, &in, r->end);
                    }
                    n++;
                }
    return n;
}

void spc_print_row_id(FILE *fp, const row *r)
{
    char pn[32];
    spc_pos_name(r->fn, r->pos, pn, sizeof pn);
    fprintf(fp, "%-14s %-5s %-13s = %-9s", spc_fn_name[r->fn], spc_base_name[r->base], pn,
            spc_vals[r->val].name);
}

void spc_print_inputs(FILE *fp, int fn, const input *in)
{
    int i;
    switch (fn) {
    case FN_TBOX:
        xu_print_case(fp, &in->a, &in->b);
        break;
    case FN_TCBOX:
    case FN_SPH:
        for (i = 0; i < 3; i++)
            fprintf(fp, "  m[%d] = {%a, %a, %a | %a}\n", i, in->a.m[i][0], in->a.m[i][1],
                    in->a.m[i][2], in->a.m[i][3]);
        if (fn == FN_SPH) break;
        /* fall through */
    case FN_C2B:
        for (i = 0; i < 3; i++)
            fprintf(fp, "  in c[%d] = %a, h[%d] = %a\n", i, in->cb.c[i], i, in->cb.h[i]);
        break;
    case FN_B2C:
        xu_print_box(fp, "in", &in->b);
        break;
    default:
        for (i = 0; i < 3; i++)
            fprintf(fp, "  center[%d] = %a  radii[%d] = %a  rot[%d] = {%a, %a, %a}\n", i,
                    in->center[i], i, in->radii[i], i, in->rot[i][0], in->rot[i][1],
                    in->rot[i][2]);
    }
}

void spc_print_output(FILE *fp, int fn, const output *o)
{
    int i;
    if (spc_fn_cout[fn])
        for (i = 0; i < 3; i++)
            fprintf(fp, "  out c[%d] = %a, h[%d] = %a\n", i, o->cb.c[i], i, o->cb.h[i]);
    else
        xu_print_box(fp, "out", &o->b);
}
