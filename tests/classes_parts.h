/*
 * classes_parts.h: the parts of test_classes (tests/test_classes.c, the
 * driver): the generators of maps and boxes shared by the parts
 * (tests/classes_gen.c), part 1 classification and part 2 class kernels
 * (tests/classes_kernels.c), part 3 motion (tests/classes_motion.c) and
 * part 4 misuse (tests/classes_misuse.c), with the statistics each part
 * fills and the driver prints.  Every name has the prefix clt_: these
 * objects go into build/libtestutil.a, which every test links.
 */
#ifndef CLASSES_PARTS_H
#define CLASSES_PARTS_H

#include <math.h>

#include "certbox.h"
#include "exact_util.h"

#define INF HUGE_VAL
#define MAX_FAIL_LOGS 20
#define NCLS 5

extern const char *const clt_cls_name[NCLS];
/* FAIL lines printed so far (all parts together print MAX_FAIL_LOGS) */
extern long clt_fail_logs;

/* ---- generators (tests/classes_gen.c) ---------------------------------- */

double clt_sgn(xu_rng *r);
/* clt_sgn(r) * (1 + unit) * 2^e, e in [lo, hi] */
double clt_sgn_pow(xu_rng *r, int lo, int hi);
/* A map of class cls by construction (the smallest class that holds it);
 * g = 0 realistic magnitudes, g = 1 extreme, g = 2 random exponents over
 * the fast range of the class kernels. */
void clt_gen_map_cls(xu_rng *r, cbx_affine *a, int cls, int g);
/* The class by an independent rule: count nonzero linear entries. */
int clt_rule_class(const cbx_affine *a);

/* Boxes */
enum { BX_REAL, BX_TINY, BX_POINT, BX_FLAT, BX_BIG, BX_HALF, BX_EMPTY, BX_NAN, BX_RAND,
       BX_FASTR, NBX };
extern const char *const clt_bx_name[NBX];
void clt_gen_box(xu_rng *r, cbx_box *b, int kind);
int clt_pick_box_kind(xu_rng *r);

void clt_print_map(const char *label, const cbx_affine *a);
void clt_fill_nan(cbx_box *b);
int clt_same_bits(double p, double q);

/* ---- part 1: classification (tests/classes_kernels.c) ------------------ */

enum {
    C_ID, C_TR, C_SC, C_PE, C_GE,
    M_DIAG_UP, M_DIAG_DN, M_NEG_ONE, M_OFF_TINY, M_OFF_TINY_ZROW, M_PERM_EXTRA,
    M_TR_TINY, M_NEGZERO, M_ZERO_SCALE, M_NAN, M_INF, M_HUGE, NKIND
};
extern const char *const clt_kind_name[NKIND];

typedef struct cstats {
    long cases, failed, rule_disagree;
    long kind[NKIND], kind_fail[NKIND];
    long got[NCLS];
} cstats;

void clt_run_classify(xu_rng *r, cbx_affine *a, cstats *st, long n);

/* ---- part 2: class kernels (tests/classes_kernels.c) ------------------- */

typedef struct kstats {
    long cases, calls, failed;
    long ends, fin_ends, inf_ends, tighter;
    long contain_fail, looser, status_diff, inf_diff, inplace_diff, input_diff;
    long flag_fail[XU_NFLAGS], gflag_fail[XU_NFLAGS];
    long st[4];
    long axes;                        /* full-row axes with excess, not tiny */
    double sum_ex, max_ex, sum_exg, max_exg;
} kstats;

/* A case of the class kernels (a map of class cls and a box); returns the
 * box kind. */
int clt_gen_kernel_case(xu_rng *r, cbx_affine *a, cbx_box *in, int cls);
/* n cases; the mpq corners on every corner_every-th */
void clt_run_kernels(xu_rng *r, xu_exact *x, kstats *ks, long n, long *bxk, long corner_every);

/* ---- part 3: motion (tests/classes_motion.c) --------------------------- */

enum { P_GENGEN, P_CLASSES, P_SAME, P_FLIP, P_NAN, P_OOD, P_HALF, P_EMPTY, NPAIR };
extern const char *const clt_pair_name[NPAIR];

typedef struct mstats {
    long cases, failed, kind[NPAIR], st[4];
    long ax_full, ax_none, ax_mixed, ax_infmap;
    long corner_checks, corner_fail, direct_checks, direct_fail;
    long end_checks, end_fail;       /* neither-full ends against the exact inf / sup */
    long union_checks, union_fail, zero_ties;
    long extreme_checks, extreme_fail, tight_fail;
    long status_fail, special_fail, whole_fail, finite_fail, inplace_fail, input_fail;
    long ex_axes;
    double sum_ex, max_ex;
} mstats;

/* n pairs; M(s) entry by entry in mpq on every direct_every-th */
void clt_run_motion(xu_rng *r, xu_exact *x, mstats *st, long n, long direct_every);

/* ---- part 4: misuse (tests/classes_misuse.c) --------------------------- */

typedef struct ustats {
    long cases, failed, calls;
    long map_cls[NCLS];                   /* random maps by rule_class       */
    long v_calls[XU_NCLS_VALUES];         /* calls per cls value             */
    long v_general[XU_NCLS_VALUES];       /* of which GENERAL or not a class */
    long v_exact_fail[XU_NCLS_VALUES], v_bits_fail[XU_NCLS_VALUES];
    long v_status_fail[XU_NCLS_VALUES], v_input_fail[XU_NCLS_VALUES];
    long table_calls, table_img_fail;     /* the table: image written out    */
} ustats;

/* the number of maps in the table with the exact image written out */
extern const int clt_n_misuse_table;
/* the table, then n random cases; the mpq corners on every corner_every-th */
void clt_run_misuse(xu_rng *r, xu_exact *x, ustats *st, long n, long *bxk, long corner_every);

#endif /* CLASSES_PARTS_H */
