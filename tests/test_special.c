/*
 * test_special [-v]: special values, table-driven, for every public
 * function of certbox.h.
 *
 * The table is generated in code (spc_make_table) as the cross product
 *     function x base input x input position x special value
 * and then run row by row (spc_run_row).  Its columns (struct row):
 *   fn      the function called: transform_box, transform_cbox,
 *           box_to_cbox, cbox_to_box, sphere_box, ellipsoid_box;
 *   base    the otherwise ordinary input the value is placed into:
 *             ord    an ordinary map and box (|m| <= 3, box in [-4, 3]);
 *             point  a point box: lo == hi on every axis, h == 0 (for
 *                    sphere_box the linear part is 0, for ellipsoid_box
 *                    the radii are 0: the image is a point);
 *             empty  axis 1 empty: lo[1] > hi[1], h[1] = -1 (the four
 *                    box functions only);
 *             half   ord with lo[0] = -inf and hi[2] = +inf: two half-lines
 *                    (transform_box and box_to_cbox only);
 *             zcol   ord with column 1 of the map zero (+0, -0, +0 in rows
 *                    0, 1, 2) against c[1] = h[1] = +inf: every row drops
 *                    that column (transform_cbox only);
 *   pos     the one input position overwritten: m[i][j] (j = 3 is the
 *           translation), lo[j], hi[j], c[j], h[j], center[i], radii[j],
 *           rot[i][j] (every input of the function);
 *   val     the value written there, from spc_vals[]: NaN, -NaN, +inf,
 *           -inf, +0, -0, -+ smallest subnormal, largest subnormal,
 *           smallest normal, -+ DBL_MAX, -+ 1, and -+ each documented
 *           domain limit 2^254, 2^509, 2^1018, 2^1019 (just inside) and
 *           the next double above it in magnitude (just outside);
 *   expect  the status certbox.h's rules give (spc_oracle(), written from the
 *           header and specs/cbx_spec.h, independently of the library and
 *           of exact_util; for transform_box and transform_cbox it is also
 *           cross-checked against exact_util's oracle, status and ends,
 *           check "oracle");
 *   ends    per output axis, the kind of its lower and its upper end (OK and
 *           ERANGE rows; enum E_A.. in special_parts.h, printed "AFULW"):
 *             A  in the domain: the kernel's finite end (transform_box: a
 *                full row, every input of the row finite and in the domain);
 *             F  transform_box, a finite map row that is not full (an
 *                infinite box end, or a box end outside the domain): the
 *                end from its vertex v_j = lo_j (m_j > 0), hi_j (m_j < 0),
 *                0 (m_j == 0, also -0; 0 * inf = 0), mirrored for the upper
 *                end, with the vertex in the domain: finite;
 *             U  transform_box, that vertex needs an infinite box end: the
 *                image is unbounded there; exactly -inf / +inf, no loss;
 *             L  transform_box, the vertex is outside the domain: exactly
 *                -inf / +inf, a loss;
 *             D  transform_cbox, a row that is not full but is once its
 *                zero-coefficient columns are dropped (c_j = h_j = 0 where
 *                m_j == 0, also -0; 0 * x = 0 whatever c_j, h_j, +-inf
 *                included; the map row finite and in the domain with those
 *                values): the kernel on the dropped row, finite (both ends
 *                of the axis);
 *             W  the whole axis is the whole line, a loss (transform_box:
 *                an infinite map entry; transform_cbox: not full even after
 *                dropping; the others: outside the domain).
 *           ERANGE iff some end is L or W.  A box axis with no real point
 *           (hi < lo, lo = +inf or hi = -inf) is EMPTY (transform_box,
 *           box_to_cbox).
 *
 * For every row, checks (a failure of any one fails the row):
 *   status     the status equals expect;
 *   out-set    the output was pre-filled with a NaN sentinel bit pattern;
 *              none of it may remain (no function documents a NaN output);
 *   nan-out    no other NaN in the output either;
 *   special    EINVAL: the whole space ([-inf,+inf]^3, or c = 0, h = +inf),
 *              EMPTY: the empty box (lo = +inf, hi = -inf, or c = 0,
 *              h = -inf), exactly, on every axis;
 *   whole      W axes exactly the whole line ([-inf, +inf], or c = 0,
 *              h = +inf);
 *   inf-end    U and L ends exactly -inf (lower) / +inf (upper);
 *   v-finite   F ends finite;
 *   v-contain  F ends on the right side of the exact vertex value
 *              V = t + sum_j m_j v_j (the exact inf / sup of the image over
 *              the real points of the box; mpq);
 *   v-tight    F ends within 12 u S_v + 2^-1065 of V, S_v = |t| +
 *              sum_j |m_j v_j| (exact, mpq);
 *   finite     A and D axes finite (and lo <= hi, h >= 0);
 *   contain    A and D axes contain the exact image (D: of the dropped
 *              box, where a dropped column adds exactly 0), decided exactly
 *              with GMP: boxes by the 8 corners (mpq_t), the conversions by
 *              the exact ends c -+ h / lo, hi, spheres and ellipsoids by
 *              lo <= t - sqrt(s) <=> t - lo >= 0 and (t - lo)^2 >= s
 *              (xu_sqrt_lo_ok / xu_sqrt_hi_ok; s exact);
 *   tight      transform_box: the proven bound of certbox.h (each end within
 *              12 u S + 2^-1065 of the exact end); transform_cbox: the same
 *              bound of specs/cbx_spec.h (cbox_tight; D axes: on the dropped
 *              row, 12 u S' + 2^-1065 with S' = |t| + sum_j |m_j c_j'| +
 *              |m_j h_j'|); the others (no bound
 *              is documented): a loose sanity bound, each end within
 *              2^-40 * (magnitude) + 2^-1060 (conversions) or + 2^-500
 *              (sphere, ellipsoid) of the exact end, only to catch a
 *              grossly wide box that would pass "contain";
 *   inputs     the inputs are unchanged.
 * Printed: one line per (function, position) with the expected statuses
 * and failures, per function the rows checked and failed (and, for
 * transform_box and transform_cbox, the ends of each kind per base
 * input), per check the items checked and
 * failed; -v prints every row with its ends.  The first failures are
 * printed with their inputs and outputs in hex (a reproducer).
 * Last line: "N passed, M failed" (rows); exit status 1 on failure.
 *
 * This file is the driver (the table's rows run in order, the summaries);
 * its parts, declared in tests/special_parts.h: the columns' values, the
 * base inputs and the table in tests/special_cases.c, the oracle in
 * tests/special_oracle.c, the checks and running a row in
 * tests/special_check.c.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <math.h>

#include "certbox.h"
#include "exact_util.h"
#include "special_parts.h"

#define MAX_FAIL_LOGS 30

int main(int argc, char **argv)
{
    static const cbx_status st_of[4] = { CBX_OK, CBX_EMPTY, CBX_EINVAL, CBX_ERANGE };
    int verbose = argc > 1 && strcmp(argv[1], "-v") == 0;
    long n, k, failed = 0, logs = 0;
    long fn_rows[NFN] = { 0 }, fn_fail[NFN] = { 0 }, fn_st[NFN][4];
    long tbox_ends[NBASE][NEND], tcbox_axes[NBASE][NEND];
    long pos_rows[NFN][18], pos_fail[NFN][18], pos_st[NFN][18][4];
    row *t;
    ctx c;
    int fn, p, s;

    if (argc > 2 || (argc == 2 && !verbose)) {
        fprintf(stderr, "usage: %s [-v]\n", argv[0]);
        return 2;
    }
    memset(fn_st, 0, sizeof fn_st);
    memset(tbox_ends, 0, sizeof tbox_ends);
    memset(tcbox_axes, 0, sizeof tcbox_axes);
    memset(pos_rows, 0, sizeof pos_rows);
    memset(pos_fail, 0, sizeof pos_fail);
    memset(pos_st, 0, sizeof pos_st);

    n = spc_make_table(NULL);
    t = malloc((size_t)n * sizeof *t);
    if (!t) {
        fprintf(stderr, "out of memory\n");
        return 2;
    }
    spc_make_table(t);
    spc_ctx_init(&c);

    printf("-- special-value table: %d values x positions x base inputs x %d functions"
           " = %ld rows --\n", NVAL, NFN, n);
    for (k = 0; k < n; k++) {
        const row *r = &t[k];
        verdict v;
        int bad = spc_run_row(&c, r, &v);
        int si = xu_status_index(r->expect);
        fn_rows[r->fn]++;
        pos_rows[r->fn][r->pos]++;
        if (r->fn == FN_TBOX && (r->expect == CBX_OK || r->expect == CBX_ERANGE)) {
            int i, e;
            for (i = 0; i < 3; i++)
                for (e = 0; e < 2; e++) tbox_ends[r->base][r->end[i][e]]++;
        }
        if (r->fn == FN_TCBOX && (r->expect == CBX_OK || r->expect == CBX_ERANGE)) {
            int i;
            for (i = 0; i < 3; i++) tcbox_axes[r->base][r->end[i][0]]++;
        }
        if (si >= 0) {
            fn_st[r->fn][si]++;
            pos_st[r->fn][r->pos][si]++;
        }
        if (bad) {
            failed++;
            fn_fail[r->fn]++;
            pos_fail[r->fn][r->pos]++;
        }
        if (verbose || (bad && logs < MAX_FAIL_LOGS)) {
            char ends[9] = "-";
            if (r->expect == CBX_OK || r->expect == CBX_ERANGE)
                spc_ends_str((const unsigned char (*)[2])r->end, ends);
            printf("  ");
            spc_print_row_id(stdout, r);
            printf(" expect %-10s got %-10s ends %-8s %s\n", cbx_status_name(r->expect),
                   cbx_status_name(v.got), ends, bad ? "FAIL" : "ok");
        }
        if (bad && logs < MAX_FAIL_LOGS) {
            logs++;
            printf("FAIL: %s\n", c.why);
            spc_print_inputs(stdout, r->fn, &v.in);
            spc_print_output(stdout, r->fn, &v.out);
        }
    }

    printf("\nper function and position (expected statuses; rows = base inputs x %d values):\n",
           NVAL);
    for (fn = 0; fn < NFN; fn++) {
        for (p = 0; p < spc_fn_npos[fn]; p++) {
            char pn[32];
            spc_pos_name(fn, p, pn, sizeof pn);
            printf("  %-14s %-13s %4ld rows: OK %3ld EMPTY %3ld EINVAL %3ld ERANGE %3ld  "
                   "%ld failed\n", spc_fn_name[fn], pn, pos_rows[fn][p], pos_st[fn][p][0],
                   pos_st[fn][p][1], pos_st[fn][p][2], pos_st[fn][p][3], pos_fail[fn][p]);
        }
    }
    printf("\nper check:\n");
    for (s = 0; s < NCHECK; s++)
        printf("  check %-8s %7ld %-4s checked, %ld failed\n", spc_check_name[s], c.applied[s],
               spc_check_unit[s], c.failed[s]);
    printf("\nper function:\n");
    for (fn = 0; fn < NFN; fn++) {
        printf("  %-14s %5ld rows checked, %ld failed  (expected", spc_fn_name[fn], fn_rows[fn],
               fn_fail[fn]);
        for (s = 0; s < 4; s++) printf(" %s %ld", cbx_status_name(st_of[s]), fn_st[fn][s]);
        printf(")\n");
    }
    printf("\ntransform_box ends by kind (OK and ERANGE rows; A full row, F vertex, "
           "U unbounded, L lost, W whole line):\n");
    for (p = 0; p < NBASE; p++) {
        if (!(spc_fn_bases[FN_TBOX] & (1u << p))) continue;
        printf("  base %-5s", spc_base_name[p]);
        for (s = 0; s < E_D; s++) printf("  %c %5ld", spc_end_char[s], tbox_ends[p][s]);
        printf("\n");
    }
    printf("transform_cbox axes by kind (OK and ERANGE rows; A full row, D zero columns "
           "dropped, W lost):\n");
    for (p = 0; p < NBASE; p++) {
        if (!(spc_fn_bases[FN_TCBOX] & (1u << p))) continue;
        printf("  base %-5s  A %5ld  D %5ld  W %5ld\n", spc_base_name[p], tcbox_axes[p][E_A],
               tcbox_axes[p][E_D], tcbox_axes[p][E_W]);
    }
    spc_ctx_clear(&c);
    free(t);
    printf("%ld passed, %ld failed\n", n - failed, failed);
    return failed ? 1 : 0;
}
