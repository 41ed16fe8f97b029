/*
 * special_parts.h: the parts of test_special (tests/test_special.c, the
 * driver: special values, table-driven, for every public function of
 * certbox.h; the table's columns and the checks are described there),
 * shared by its files:
 *   tests/special_cases.c   the columns' values, the base inputs, making
 *                           the table, printing a row's inputs and outputs;
 *   tests/special_oracle.c  the oracle: certbox.h's rules written out again
 *                           (the expected status and end kinds), and
 *                           exact_util's oracle beside it;
 *   tests/special_check.c   the checks, and running one row.
 * Every name with linkage starts with spc_ (one archive, every test links
 * it: build/libtestutil.a).
 */
#ifndef SPECIAL_PARTS_H
#define SPECIAL_PARTS_H

#include <math.h>
#include <stdio.h>

#include "certbox.h"
#include "exact_util.h"

#define INF HUGE_VAL

/* ---------------------------------------------------------------------- */
/* The columns' values (tests/special_cases.c)                            */
/* ---------------------------------------------------------------------- */

enum { FN_TBOX, FN_TCBOX, FN_B2C, FN_C2B, FN_SPH, FN_ELL, NFN };
extern const char *const spc_fn_name[NFN];
/* positions per function (see slot(), special_cases.c) and base inputs per
 * function */
extern const int spc_fn_npos[NFN];
/* bit b set: base input b is used with the function */
extern const unsigned spc_fn_bases[NFN];
/* output form: 1 = cbx_cbox, 0 = cbx_box */
extern const int spc_fn_cout[NFN];

enum { B_ORD, B_POINT, B_EMPTY, B_HALF, B_ZCOL, NBASE };
extern const char *const spc_base_name[NBASE];

typedef struct sval { const char *name; double v; } sval;
/* the special values: NVAL of them (special_cases.c does not compile if
 * its table has another number) */
#define NVAL 30
extern const sval spc_vals[];

/* What one output end must be (column "ends"; printed as a letter):
 *   A  in the domain: the kernel's finite end (transform_box: a full row,
 *      every input of the row finite and in the domain; the 8-corner
 *      containment and the proven 12 u S + 2^-1065);
 *   F  transform_box, a finite map row that is not full: finite, from the
 *      vertex (v_j = lo_j if m_j > 0, hi_j if m_j < 0, 0 if m_j == 0;
 *      mirrored for the upper end) in the domain: on the right side of
 *      t + sum m_j v_j and within 12 u S_v + 2^-1065, S_v = |t| + sum
 *      |m_j v_j| (exact, mpq);
 *   U  transform_box: the image is unbounded on that side (the vertex
 *      needs an infinite box end): exactly -inf / +inf, not a loss;
 *   L  transform_box: the vertex is outside the domain: exactly -inf /
 *      +inf, a loss (CBX_ERANGE);
 *   W  the whole line (both ends of the axis), a loss: an infinite map
 *      entry (transform_box), not full even with its zero-coefficient
 *      columns dropped (transform_cbox), or outside the domain (the other
 *      functions);
 *   D  transform_cbox, both ends of an axis whose row is full only once
 *      its zero-coefficient columns are dropped (c_j = h_j = 0 where
 *      m_j == 0): the kernel on the dropped row, finite, checked like A on
 *      the dropped box. */
enum { E_A, E_F, E_U, E_L, E_W, E_D, NEND };
extern const char spc_end_char[NEND + 1];

/* One table row (see test_special.c's header comment). */
typedef struct row {
    int fn, base, pos, val;
    cbx_status expect;
    unsigned char end[3][2]; /* [axis][0 lower, 1 upper] (not EINVAL/EMPTY) */
} row;

/* Every input any function reads. */
typedef struct input {
    cbx_affine a;
    cbx_box b;
    cbx_cbox cb;
    double center[3], radii[3], rot[3][3];
} input;

typedef struct output {
    cbx_box b;
    cbx_cbox cb;
} output;

/* The input of row r: its base input with its value at its position. */
void spc_make_input(const row *r, input *in);
/* The name of position pos of function fn, into buf[n]. */
void spc_pos_name(int fn, int pos, char *buf, size_t n);
/* The table into t[] (t == NULL: only count); returns the number of rows. */
long spc_make_table(row *t);
void spc_print_row_id(FILE *fp, const row *r);
void spc_print_inputs(FILE *fp, int fn, const input *in);
void spc_print_output(FILE *fp, int fn, const output *o);

/* ---------------------------------------------------------------------- */
/* The oracle (tests/special_oracle.c)                                    */
/* ---------------------------------------------------------------------- */

int spc_nan_(double x);
int spc_is_pinf(double d);
int spc_is_ninf(double d);
/* transform_box, one end of a finite map row that is not full: U when
 * the coordinate it needs is infinite, else F when the vertex is in the
 * domain, else L.  v[] receives the vertex (when not U). */
int spc_tbox_end(const input *in, int i, int upper, double v[3]);
/* transform_cbox, row i with its zero-coefficient columns dropped: c_j and
 * h_j replaced by 0 where m_ij == 0, copied elsewhere. */
void spc_tcbox_drop(const input *in, int i, double dc[3], double dh[3]);
/* Expected status; end[][] = the kind of every output end (A F U L W). */
cbx_status spc_oracle(int fn, const input *in, unsigned char end[3][2]);
/* The end kinds as "ab cd ef" (s: at least 9 chars). */
void spc_ends_str(const unsigned char end[3][2], char *s);
/* exact_util's oracle, where it has one (-1: none): the status and the
 * end kinds as a string like spc_ends_str()'s ("" for EINVAL / EMPTY). */
int spc_xu_oracle(int fn, const input *in, cbx_status *st, char ends[9]);

/* ---------------------------------------------------------------------- */
/* The checks (tests/special_check.c)                                     */
/* ---------------------------------------------------------------------- */

enum { C_ORACLE, C_STATUS, C_UNSET, C_NANOUT, C_SPECIAL, C_WHOLE, C_FINITE,
       C_CONTAIN, C_TIGHT, C_INFEND, C_VFINITE, C_VCONTAIN, C_VTIGHT, C_INPUT, NCHECK };
extern const char *const spc_check_name[NCHECK];
extern const char *const spc_check_unit[NCHECK];

typedef struct ctx {
    xu_exact x;
    mpq_t q, qa, qb, qc, qlo, qhi, tol, eps, eta;
    mpz_t s, z;
    long applied[NCHECK], failed[NCHECK];
    /* the current row */
    int flag[NCHECK];
    int row_failed;
    char why[200];
} ctx;

typedef struct verdict {
    cbx_status got;
    output out;
    input in;
} verdict;

void spc_ctx_init(ctx *k);
void spc_ctx_clear(ctx *k);
/* Run row r and check it (v: the call's status, output and input);
 * returns 1 if the row failed (k->why: the first reason). */
int spc_run_row(ctx *k, const row *r, verdict *v);

#endif /* SPECIAL_PARTS_H */
