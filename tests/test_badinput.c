/*
 * test_badinput: special values, table-driven.
 *
 * Every case starts from one ordinary in-domain map and box and applies up
 * to four edits (one input set to a special value each).  The hand-written
 * expected status, rows with a loss and kinds of the six output ends
 * (A full row, F vertex, U unbounded, L lost, W whole line: the rules of
 * exact_util.h) are compared both with the library and with the exact
 * oracle of exact_util (so a mistake in either the table or the oracle
 * shows up).  The library's output is then checked exactly as in
 * test_exact: EINVAL -> [-inf,+inf]^3, EMPTY (hi < lo, lo = +inf or
 * hi = -inf) -> lo +inf / hi -inf, full rows finite, containing the exact
 * image (and its 8 corners) within the proven bound, rule-B ends exactly
 * -inf / +inf (U, L) or finite around the exact vertex value within
 * 12 u S_v + 2^-1065 (F), rows with an infinite entry [-inf,+inf].
 * Last line: "N passed, M failed".
 */
#include <stdio.h>
#include <string.h>
#include <float.h>
#include <math.h>

#include "certbox.h"
#include "exact_util.h"

/* Where an edit goes: matrix entry (i, j) (j = 3: translation), lo[j] or
 * hi[j].  NONE ends the list. */
#define M(i, j) ((i) * 4 + (j))
#define LO(j) (12 + (j))
#define HI(j) (15 + (j))
#define NONE (-1)

#define INF HUGE_VAL

typedef struct edit { int where; double v; } edit;

typedef struct bad_case {
    const char *group;
    const char *name;
    edit e[4];          /* unused slots: { NONE, 0 } */
    cbx_status expect;
    int loss;           /* rows with a loss (ERANGE only)                   */
    const char *ends;   /* end kinds "lo hi" per axis (NULL: EINVAL, EMPTY) */
} bad_case;

#define E(w, v) { w, v }
#define E0 { NONE, 0 }

/* The base case: every |m| <= 4, box within [-4, 3]: deep in the domain. */
static const cbx_affine base_a = { {
    { 0.5, -2, 0.25, 1 },
    { 3, 0.125, -1, -4 },
    { -0.75, 1.5, 2, 0.5 },
} };
static const cbx_box base_in = { { -1, 0.5, -4 }, { 2, 3, -1 } };

static const bad_case cases[] = {
    /* --- NaN in each of the 12 matrix entries ------------------------ */
    { "nan", "NaN in m[0][0]", { E(M(0, 0), NAN), E0, E0, E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "NaN in m[0][1]", { E(M(0, 1), NAN), E0, E0, E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "NaN in m[0][2]", { E(M(0, 2), NAN), E0, E0, E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "NaN in m[0][3] (t0)", { E(M(0, 3), NAN), E0, E0, E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "NaN in m[1][0]", { E(M(1, 0), NAN), E0, E0, E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "-NaN in m[1][1]", { E(M(1, 1), -NAN), E0, E0, E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "NaN in m[1][2]", { E(M(1, 2), NAN), E0, E0, E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "NaN in m[1][3] (t1)", { E(M(1, 3), NAN), E0, E0, E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "NaN in m[2][0]", { E(M(2, 0), NAN), E0, E0, E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "NaN in m[2][1]", { E(M(2, 1), NAN), E0, E0, E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "-NaN in m[2][2]", { E(M(2, 2), -NAN), E0, E0, E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "NaN in m[2][3] (t2)", { E(M(2, 3), NAN), E0, E0, E0 }, CBX_EINVAL, 0, NULL },
    /* --- NaN in each of the 6 box coordinates ------------------------ */
    { "nan", "NaN in lo[0]", { E(LO(0), NAN), E0, E0, E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "NaN in lo[1]", { E(LO(1), NAN), E0, E0, E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "-NaN in lo[2]", { E(LO(2), -NAN), E0, E0, E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "NaN in hi[0]", { E(HI(0), NAN), E0, E0, E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "NaN in hi[1]", { E(HI(1), NAN), E0, E0, E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "NaN in hi[2]", { E(HI(2), NAN), E0, E0, E0 }, CBX_EINVAL, 0, NULL },
    /* NaN in a zero-weight place still counts: the rule is "anywhere" */
    { "nan", "NaN in lo[0], column 0 all zero",
      { E(LO(0), NAN), E(M(0, 0), 0), E(M(1, 0), 0), E(M(2, 0), 0) }, CBX_EINVAL, 0, NULL },
    /* --- NaN wins over everything else ------------------------------- */
    { "nan", "NaN + empty axis 0 (EINVAL wins)",
      { E(M(1, 2), NAN), E(LO(0), 3), E0, E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "NaN in hi[2] + empty axis 1",
      { E(HI(2), NAN), E(LO(1), 4), E0, E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "NaN in lo[0] + inverted infinities on axis 1",
      { E(LO(0), NAN), E(LO(1), INF), E(HI(1), -INF), E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "NaN + infinite entry",
      { E(M(0, 0), INF), E(M(2, 3), NAN), E0, E0 }, CBX_EINVAL, 0, NULL },
    { "nan", "NaN + out-of-domain coordinate",
      { E(HI(1), DBL_MAX), E(M(0, 1), NAN), E0, E0 }, CBX_EINVAL, 0, NULL },

    /* --- empty boxes ------------------------------------------------- */
    { "empty", "axis 0: lo = hi + 1 ulp",
      { E(LO(0), 0x1.0000000000001p1), E0, E0, E0 }, CBX_EMPTY, 0, NULL },
    { "empty", "axis 1: lo > hi",
      { E(LO(1), 3.5), E0, E0, E0 }, CBX_EMPTY, 0, NULL },
    { "empty", "axis 2: lo = -1, hi = -4 (swapped)",
      { E(LO(2), -1), E(HI(2), -4), E0, E0 }, CBX_EMPTY, 0, NULL },
    { "empty", "axis 0: lo = +inf, hi = -inf",
      { E(LO(0), INF), E(HI(0), -INF), E0, E0 }, CBX_EMPTY, 0, NULL },
    { "empty", "axis 2: lo = +inf, hi = 0",
      { E(LO(2), INF), E(HI(2), 0), E0, E0 }, CBX_EMPTY, 0, NULL },
    { "empty", "axis 1: lo = 0, hi = -inf",
      { E(LO(1), 0), E(HI(1), -INF), E0, E0 }, CBX_EMPTY, 0, NULL },
    { "empty", "axis 0: lo = 2^-1074, hi = +0",
      { E(LO(0), 0x1p-1074), E(HI(0), 0.0), E0, E0 }, CBX_EMPTY, 0, NULL },
    { "empty", "empty wins over an infinite entry",
      { E(LO(1), 3.5), E(M(0, 0), INF), E0, E0 }, CBX_EMPTY, 0, NULL },
    { "empty", "empty wins over an out-of-domain coordinate",
      { E(LO(2), 0), E(HI(2), -1), E(HI(0), 1e308), E0 }, CBX_EMPTY, 0, NULL },
    { "empty", "all three axes empty",
      { E(LO(0), 3), E(LO(1), 4), E(LO(2), 0), E0 }, CBX_EMPTY, 0, NULL },

    /* --- infinite coordinates: half-spaces (rule B), each end on its own:
     * unbounded (U) where the coefficient needs the infinite end, proven
     * (F) elsewhere; no loss, so CBX_OK ----------------------------- */
    { "inf", "lo[0] = -inf (half-space: no loss)", { E(LO(0), -INF), E0, E0, E0 }, CBX_OK, 0, "UF UF FU" },
    { "inf", "hi[1] = +inf (half-space: no loss)", { E(HI(1), INF), E0, E0, E0 }, CBX_OK, 0, "UF FU FU" },
    { "empty", "lo[2] = hi[2] = -inf (no real point)",
      { E(LO(2), -INF), E(HI(2), -INF), E0, E0 }, CBX_EMPTY, 0, NULL },
    { "inf", "lo[0] = -inf, hi[0] = +inf",
      { E(LO(0), -INF), E(HI(0), INF), E0, E0 }, CBX_OK, 0, "UU UU UU" },
    /* 0 * inf is NaN in floating point, 0 over the reals: proven, no NaN
     * out */
    { "inf", "hi[0] = +inf with column 0 all zero",
      { E(HI(0), INF), E(M(0, 0), 0), E(M(1, 0), -0.0), E(M(2, 0), 0) }, CBX_OK, 0, "FF FF FF" },
    /* --- infinite matrix entries: only that row, the whole line (W) ---- */
    { "inf", "m[0][0] = +inf", { E(M(0, 0), INF), E0, E0, E0 }, CBX_ERANGE, 1, "WW AA AA" },
    { "inf", "m[1][2] = -inf", { E(M(1, 2), -INF), E0, E0, E0 }, CBX_ERANGE, 2, "AA WW AA" },
    { "inf", "m[2][1] = +inf", { E(M(2, 1), INF), E0, E0, E0 }, CBX_ERANGE, 4, "AA AA WW" },
    { "inf", "t1 = -inf", { E(M(1, 3), -INF), E0, E0, E0 }, CBX_ERANGE, 2, "AA WW AA" },
    { "inf", "t2 = +inf", { E(M(2, 3), INF), E0, E0, E0 }, CBX_ERANGE, 4, "AA AA WW" },
    { "inf", "rows 0 and 2 infinite",
      { E(M(0, 1), -INF), E(M(2, 3), INF), E0, E0 }, CBX_ERANGE, 5, "WW AA WW" },
    /* inf * 0 again, this time with the zero in the box */
    { "inf", "m[0][0] = +inf with box axis 0 = [0, 0]",
      { E(M(0, 0), INF), E(LO(0), 0), E(HI(0), 0), E0 }, CBX_ERANGE, 1, "WW AA AA" },
    { "inf", "m[2][2] = -inf with box axis 2 = [-0, +0]",
      { E(M(2, 2), -INF), E(LO(2), -0.0), E(HI(2), 0.0), E0 }, CBX_ERANGE, 4, "AA AA WW" },
    { "inf", "all three rows have an infinite entry",
      { E(M(0, 2), INF), E(M(1, 0), -INF), E(M(2, 3), INF), E0 }, CBX_ERANGE, 7, "WW WW WW" },

    /* --- finite but outside the domain: per end, lost (L) where the
     * vertex is out, proven (F) where it is in ------------------------ */
    { "range", "m[0][0] = 1e300 with |x0| up to 2",
      { E(M(0, 0), 1e300), E0, E0, E0 }, CBX_ERANGE, 1, "FL AA AA" },
    { "range", "lo[1] = -1e308 (beyond 2^1018 for any m)",
      { E(LO(1), -1e308), E0, E0, E0 }, CBX_ERANGE, 7, "FL LF LF" },
    { "range", "t0 = DBL_MAX", { E(M(0, 3), DBL_MAX), E0, E0, E0 }, CBX_ERANGE, 1, "LL AA AA" },
    { "range", "t2 = -2^1019", { E(M(2, 3), -0x1p1019), E0, E0, E0 }, CBX_ERANGE, 4, "AA AA LL" },
    { "range", "m[2][2] = DBL_MAX", { E(M(2, 2), DBL_MAX), E0, E0, E0 }, CBX_ERANGE, 4, "AA AA LL" },
    { "range", "m[1][1] = 2^1018 with x1 in [0.5, 3]",
      { E(M(1, 1), 0x1p1018), E0, E0, E0 }, CBX_ERANGE, 2, "AA FL AA" },
    { "range", "hi[2] = 2^1018 (1 + 2^-52), column 2 small",
      { E(HI(2), 0x1.0000000000001p1018), E0, E0, E0 }, CBX_ERANGE, 7, "FL LF FL" },
    /* the same edges from the inside: all rows proven */
    { "range", "m[1][1] = 2^1018 with x1 in [0.5, 1] (in domain)",
      { E(M(1, 1), 0x1p1018), E(HI(1), 1), E0, E0 }, CBX_OK, 0, "AA AA AA" },
    { "range", "t2 = -2^1018 (in domain)", { E(M(2, 3), -0x1p1018), E0, E0, E0 }, CBX_OK, 0, "AA AA AA" },
    /* c = 2^1018 needs |m| <= 1: rows 0 (0.25) and 1 (-1) in, row 2 (2) out */
    { "range", "hi[2] = 2^1018: |m[i][2]| <= 1 in, m[2][2] = 2 out",
      { E(HI(2), 0x1p1018), E0, E0, E0 }, CBX_ERANGE, 4, "AA AA FL" },

    /* --- half-spaces and huge ends, mixed ------------------------------ */
    { "half", "three half-lines: lo[0], lo[2] = -inf, hi[1] = +inf",
      { E(LO(0), -INF), E(HI(1), INF), E(LO(2), -INF), E0 }, CBX_OK, 0, "UF UU UU" },
    /* axis 0 the whole line; row 0 reads it with zeros (+0 and -0) */
    { "half", "x0 unbounded both ways, m[0][0..1] = +0, -0",
      { E(LO(0), -INF), E(HI(0), INF), E(M(0, 0), 0), E(M(0, 1), -0.0) },
      CBX_OK, 0, "FF UU UU" },
    /* a -0.0 coefficient against +inf: 0, not NaN */
    { "half", "hi[2] = +inf, m[1][2] = -0",
      { E(HI(2), INF), E(M(1, 2), -0.0), E0, E0 }, CBX_OK, 0, "FU FF FU" },
    /* the bounded end of row 2 has its vertex out of the domain */
    { "half", "hi[0] = +inf, m[2][2] = DBL_MAX",
      { E(HI(0), INF), E(M(2, 2), DBL_MAX), E0, E0 }, CBX_ERANGE, 4, "FU FU UL" },
    /* t out of the domain: the bounded end is lost, the other unbounded */
    { "half", "lo[1] = -inf, t0 = DBL_MAX",
      { E(LO(1), -INF), E(M(0, 3), DBL_MAX), E0, E0 }, CBX_ERANGE, 1, "LU UF UF" },
    /* a finite box, one huge end: lost only where the sign needs it */
    { "half", "hi[0] = DBL_MAX (finite box)",
      { E(HI(0), DBL_MAX), E0, E0, E0 }, CBX_ERANGE, 7, "FL FL LF" },
    /* a huge finite axis read only through zeros in rows 0 and 1 */
    { "half", "x0 in [-DBL_MAX, DBL_MAX], m[0][0] = +0, m[1][0] = -0",
      { E(LO(0), -DBL_MAX), E(HI(0), DBL_MAX), E(M(0, 0), 0), E(M(1, 0), -0.0) },
      CBX_ERANGE, 4, "FF FF LL" },
    /* an infinite entry beside a half-space: that row whole, others ends */
    { "half", "lo[0] = -inf, m[1][1] = +inf",
      { E(LO(0), -INF), E(M(1, 1), INF), E0, E0 }, CBX_ERANGE, 2, "UF WW FU" },
    /* no real point although lo <= hi in IEEE order */
    { "empty", "axis 1: lo = hi = +inf (no real point)",
      { E(LO(1), INF), E(HI(1), INF), E0, E0 }, CBX_EMPTY, 0, NULL },
    { "empty", "axis 0: lo = -inf, hi = -inf, with an infinite entry",
      { E(LO(0), -INF), E(HI(0), -INF), E(M(2, 2), INF), E0 }, CBX_EMPTY, 0, NULL },

    /* --- point boxes, zeros, signed zeros ---------------------------- */
    { "point", "base case (ordinary box)", { E0, E0, E0, E0 }, CBX_OK, 0, "AA AA AA" },
    { "point", "point box",
      { E(LO(0), 2), E(LO(1), 3), E(HI(2), -4), E0 }, CBX_OK, 0, "AA AA AA" },
    { "point", "axes 0 and 1 = [0, 0]",
      { E(LO(0), 0), E(HI(0), 0), E(LO(1), 0), E(HI(1), 0) }, CBX_OK, 0, "AA AA AA" },
    { "point", "point box of -0.0 on axis 0 and 1",
      { E(LO(0), -0.0), E(HI(0), -0.0), E(LO(1), -0.0), E(HI(1), -0.0) }, CBX_OK, 0, "AA AA AA" },
    { "point", "box [+0, -0] on axis 2 (equal, not empty)",
      { E(LO(2), 0.0), E(HI(2), -0.0), E0, E0 }, CBX_OK, 0, "AA AA AA" },
    { "point", "box [-0, +0] on axis 0",
      { E(LO(0), -0.0), E(HI(0), 0.0), E0, E0 }, CBX_OK, 0, "AA AA AA" },
    { "point", "-0.0 matrix entries and translation",
      { E(M(0, 0), -0.0), E(M(1, 3), -0.0), E(M(2, 1), -0.0), E(M(2, 3), -0.0) }, CBX_OK, 0, "AA AA AA" },
    { "point", "subnormal point box",
      { E(LO(0), 0x1p-1074), E(HI(0), 0x1p-1074), E(LO(1), -0x1p-1060), E(HI(1), -0x1p-1060) },
      CBX_OK, 0, "AA AA AA" },
};

#define N_CASES ((int)(sizeof cases / sizeof cases[0]))

static void apply_edits(const bad_case *c, cbx_affine *a, cbx_box *in)
{
    int k;
    *a = base_a;
    *in = base_in;
    for (k = 0; k < 4; k++) {
        int w = c->e[k].where;
        if (w == NONE) continue;
        if (w < 12) a->m[w / 4][w % 4] = c->e[k].v;
        else if (w < 15) in->lo[w - 12] = c->e[k].v;
        else in->hi[w - 15] = c->e[k].v;
    }
}

/* Per-group pass/fail counts, in order of first appearance. */
#define MAX_GROUPS 8
static const char *group_name[MAX_GROUPS];
static long group_pass[MAX_GROUPS], group_fail[MAX_GROUPS];
static int n_groups;

static void count(const char *group, int ok)
{
    int g;
    for (g = 0; g < n_groups; g++)
        if (strcmp(group_name[g], group) == 0) break;
    if (g == n_groups && n_groups < MAX_GROUPS) group_name[n_groups++] = group;
    if (g == MAX_GROUPS) g = MAX_GROUPS - 1;
    if (ok) group_pass[g]++;
    else group_fail[g]++;
}

static int run_table(xu_exact *x, xu_stats *st)
{
    int n, bad = 0;
    for (n = 0; n < N_CASES; n++) {
        const bad_case *c = &cases[n];
        cbx_affine a;
        cbx_box in, out;
        xu_verdict v;
        int table_ok, special;
        char ends[9] = "-";
        apply_edits(c, &a, &in);
        xu_run_case(x, &a, &in, &out, 1, &v);
        special = v.expected == CBX_EINVAL || v.expected == CBX_EMPTY;
        if (!special) xu_ends_str(&a, &in, ends);
        /* the hand-written expectation must match the oracle too */
        table_ok = v.expected == c->expect
                   && (c->expect != CBX_ERANGE ? 1 : xu_loss_mask(&a, &in) == c->loss)
                   && (c->expect == CBX_ERANGE || c->loss == 0)
                   && (special ? c->ends == NULL
                               : c->ends != NULL && strcmp(ends, c->ends) == 0);
        if (!table_ok) {
            if (!v.failed)
                snprintf(v.why, sizeof v.why, "table says %s/loss %d/ends %s, oracle %s/loss "
                        "%d/ends %s", cbx_status_name(c->expect), c->loss,
                        c->ends ? c->ends : "-", cbx_status_name(v.expected),
                        special ? 0 : xu_loss_mask(&a, &in), ends);
            v.failed = 1;
        }
        xu_stats_add(st, &v, &a, &in);
        count(c->group, !v.failed);
        printf("  %-6s %-54s %-10s %-8s %s\n", c->group, c->name,
               cbx_status_name(v.got), ends, v.failed ? "FAIL" : "ok");
        if (v.failed) {
            bad++;
            printf("FAIL: %s\n", v.why);
            xu_print_case(stdout, &a, &in);
            xu_print_box(stdout, "out", &out);
        }
    }
    return bad;
}

/* cbx_status_name: the four exact names, and non-NULL for anything else. */
static int run_names(void)
{
    static const struct { cbx_status s; const char *name; } known[] = {
        { CBX_OK, "CBX_OK" }, { CBX_EMPTY, "CBX_EMPTY" },
        { CBX_EINVAL, "CBX_EINVAL" }, { CBX_ERANGE, "CBX_ERANGE" },
    };
    /* values outside the enumeration, still representable in its type */
    static const int unknown[] = { 2, -3, 42, -100 };
    int k, bad = 0;
    for (k = 0; k < 4; k++) {
        const char *got = cbx_status_name(known[k].s);
        int ok = got != NULL && strcmp(got, known[k].name) == 0;
        printf("  names  cbx_status_name(%d) = \"%s\" %s\n", (int)known[k].s,
               got ? got : "(null)", ok ? "ok" : "FAIL");
        count("names", ok);
        bad += !ok;
    }
    for (k = 0; k < 4; k++) {
        const char *got = cbx_status_name((cbx_status)unknown[k]);
        int ok = got != NULL;
        printf("  names  cbx_status_name(%d) = \"%s\" %s\n", unknown[k],
               got ? got : "(null)", ok ? "ok" : "FAIL");
        count("names", ok);
        bad += !ok;
    }
    return bad;
}

int main(void)
{
    xu_exact x;
    xu_stats st;
    long failed, total;
    int g;

    xu_init(&x);
    xu_stats_init(&st);
    printf("-- special-value cases (%d) --\n", N_CASES);
    failed = run_table(&x, &st);
    failed += run_names();
    total = N_CASES + 8;
    xu_clear(&x);

    printf("\n");
    for (g = 0; g < n_groups; g++)
        printf("group %-6s %3ld passed, %ld failed\n", group_name[g],
               group_pass[g], group_fail[g]);
    xu_stats_print(stdout, "special-value table", &st);
    printf("%ld passed, %ld failed\n", total - failed, failed);
    return failed ? 1 : 0;
}
