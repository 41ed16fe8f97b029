/*
 * cbox_parts.h: the pieces of tests/test_cbox.c (the centre/half-diagonal
 * functions against GMP) that live in their own files, for the driver
 * test_cbox.c and for each other:
 *   cbox_check.c   verdicts, statistics, the exact context, and the
 *                  oracle and checks of cbx_transform_cbox (kinds A, D, W);
 *   cbox_conv.c    the oracle and checks of cbx_box_to_cbox and
 *                  cbx_cbox_to_box, the round trips, the reproducers (hex);
 *   cbox_cases.c   the tables of hand-picked cases;
 *   cbox_random.c  the random case generators.
 * They are compiled once into build/libtestutil.a (scripts/testutil.sh),
 * so nothing here may depend on a macro given to test_cbox alone: the
 * constants below are fixed (a -DCONV_EMAX=... on the driver is refused by
 * -Werror, as a redefinition).  The exported names carry the prefix cbt_.
 */
#ifndef CBOX_PARTS_H
#define CBOX_PARTS_H

#include <math.h>

#include "certbox.h"
#include "exact_util.h"

/* Domain of the conversions: |input| <= 2^CONV_EMAX.  certbox.h and
 * conv_dom in specs/cbx_spec.h say 2^1019 (an earlier draft said 2^1020). */
#define CONV_EMAX 1019
/* 2^CONV_EMAX and one ulp above it, as constant expressions (tables) */
#define XPOW_(e) 0x1p##e
#define XPOW(e) XPOW_(e)
#define CLIM XPOW(CONV_EMAX)
#define CLIMU (CLIM * 0x1.0000000000001p0)
#define SANITY 64.0
#define MAX_FAIL_LOGS 20

#define INF HUGE_VAL
#define TC_UNITS "u*S + eta, S = |t| + sum |m_j|(|c_j| + h_j) (D axes: S' of the dropped row)"

/* 2^509 (1 + 2^-52), 2^1018 (1 + 2^-52), 2^CONV_EMAX (1 + 2^-52) */
#define P509U 0x1.0000000000001p509
#define P1018U 0x1.0000000000001p1018
#define P1019U CLIMU

/* ---------------------------------------------------------------------- */
/* Checks, verdicts, statistics (cbox_check.c)                            */
/* ---------------------------------------------------------------------- */

enum {
    F_STATUS,    /* status differs from the exactly decided one          */
    F_UNSET,     /* NaN pre-fill left in the output                      */
    F_SPECIAL,   /* EINVAL / EMPTY output not exactly as specified       */
    F_OOB,       /* lost axis (W, out of domain) not exactly the whole line */
    F_FINITE,    /* in-domain (A) axis not finite (or lo > hi, h < 0)     */
    F_CONTAIN,   /* the exact image is not contained (exact)             */
    F_SPEC,      /* beyond 12 u S + 2^-1065 (cbox_tight, transform only) */
    F_SANITY,    /* > 64 units where u S >= 2^-1000                      */
    F_TINYABS,   /* gap > max(64 (u S + eta), 2^-1000) where u S < 2^-1000 */
    F_CORNER,    /* an mpq corner image is outside the output            */
    F_CROSS,     /* mpq corner min / max != fixed-point C -+ H           */
    /* transform_cbox, axes of kind D (zero-coefficient columns dropped):
     * the same checks on the dropped row, S' instead of S               */
    F_DFINITE,   /* D axis not finite (or h < 0)                         */
    F_DCONTAIN,  /* D: the exact image (dropped row) not contained       */
    F_DSPEC,     /* D: beyond 12 u S' + 2^-1065                          */
    F_DCORNER,   /* D: an mpq corner of the dropped box maps outside     */
    F_DCROSS,    /* D: mpq corner min / max != fixed-point C' -+ H'      */
    F_ROUND,     /* round trip does not contain the original             */
    F_INPUT,     /* the call modified its input                          */
    F_CSPEC,     /* conversions: beyond 16 u (|x| + |y|) + 2^-1066 (conv_gap) */
    NF
};

typedef struct verdict {
    cbx_status expected, got;
    int failed;
    int flag[NF], applied[NF];
    char why[200];
} verdict;

typedef struct exstat {      /* excess of in-domain axes, in units        */
    long n, n_tiny, n_exact, over8;
    double max, sum, max_tiny;
} exstat;

typedef struct group {
    const char *name;
    long cases, failed;
    long status_seen[4];
    long applied[NF], fails[NF];
    exstat lo, hi, main;     /* main: the quantity the sanity bound uses  */
    exstat drop;             /* transform_cbox D axes: max of both ends,
                                units of u S' + eta (not in lo/hi/main)   */
    long kinds[XU_NCAX];     /* transform_cbox axes by kind (A, D, W)     */
    const char *main_what;
    long rt_n, rt_skipped;   /* round trips checked / second step not OK  */
    double rt_max;           /* round-trip excess, units                  */
} group;

/* failure reports printed so far (at most MAX_FAIL_LOGS per function; the
 * driver resets it before each function) */
extern long cbt_fail_logs;

void cbt_v_init(verdict *v);
void cbt_v_fail(verdict *v, int f, const char *why);
void cbt_ex_add(exstat *e, double u, int tiny, int exact);
void cbt_g_init(group *g, const char *name, const char *main_what);
void cbt_g_add(group *g, const verdict *v);
void cbt_g_print(const group *g);

/* ---------------------------------------------------------------------- */
/* Exact context (cbox_check.c)                                           */
/* ---------------------------------------------------------------------- */

typedef struct ctx {
    xu_exact x;
    mpz_t C, H, S, p, olo, ohi, elo, ehi, g, t;
    mpq_t q, qa, qb, qlo, qhi, qmin, qmax;
} ctx;

void cbt_ctx_init(ctx *k);
void cbt_ctx_clear(ctx *k);
int cbt_is_pinf(double d);
int cbt_is_ninf(double d);
/* k->olo, k->ohi = c -+ h, scaled */
void cbt_cbox_ends(ctx *k, double c, double h);
/* One side: gap (scaled, >= 0 when contained) against scale S. Returns the
 * excess in units; sets *sanity_bad. */
double cbt_side_units(ctx *k, const mpz_t gap, const mpz_t S, int tiny, int *sanity_bad);

/* ---------------------------------------------------------------------- */
/* cbx_transform_cbox: oracle and checks (cbox_check.c)                   */
/* ---------------------------------------------------------------------- */

/* The status by exact_util's rules; *oob = the W axes (losses), kinds =
 * "ADW"-letters per axis ("---" for EINVAL / EMPTY). */
cbx_status cbt_tc_expected(const cbx_affine *a, const cbx_cbox *in, int *oob, char kinds[4]);
/* Run one transform case (corners: also the mpq corner checks); adds the
 * excess to g; returns v->failed. */
int cbt_tc_run(ctx *k, group *g, const cbx_affine *a, const cbx_cbox *in,
           cbx_cbox *out, int corners, verdict *v, double *mx);
/* checks shared with the conversions */
void cbt_check_cwhole_axis(verdict *v, const cbx_cbox *o, int i, int flag, const char *what);
void cbt_check_cspecial(verdict *v, const cbx_cbox *o, int whole);
int cbt_check_unset_c(verdict *v, const cbx_cbox *o);
void cbt_check_status(verdict *v);

/* ---------------------------------------------------------------------- */
/* Conversions: oracle and checks, reproducers (cbox_conv.c)              */
/* ---------------------------------------------------------------------- */

cbx_status cbt_b2c_expected(const cbx_box *in, int *oob);
cbx_status cbt_c2b_expected(const cbx_cbox *in, int *oob);
int cbt_b2c_run(ctx *k, group *g, const cbx_box *in, cbx_cbox *out, verdict *v, double *mx);
int cbt_c2b_run(ctx *k, group *g, const cbx_cbox *in, cbx_box *out, verdict *v, double *mx);
/* box -> cbox -> box must contain the box (b2c OK assumed by the caller). */
void cbt_roundtrip_box(ctx *k, group *g, const cbx_box *in, const cbx_cbox *cb, verdict *v);
/* cbox -> box -> cbox must contain the cbox (exactly). */
void cbt_roundtrip_cbox(ctx *k, group *g, const cbx_cbox *in, const cbx_box *bx, verdict *v);
void cbt_print_cbox(const char *label, const cbx_cbox *b);
void cbt_print_affine(const cbx_affine *a);
/* the FAIL line of a case; 0 (nothing printed) past MAX_FAIL_LOGS */
int cbt_log_head(const char *what, long id, const verdict *v);

/* ---------------------------------------------------------------------- */
/* Hard cases (cbox_cases.c)                                              */
/* ---------------------------------------------------------------------- */

typedef struct tc_case {
    const char *name;
    cbx_affine a;
    cbx_cbox in;
    cbx_status expect;
    int oob;            /* the lost (W) axes                             */
    const char *kinds;  /* per axis A, D or W ("---": EINVAL / EMPTY)     */
} tc_case;

typedef struct b2c_case {
    const char *name;
    cbx_box in;
    cbx_status expect;
    int oob;
} b2c_case;

typedef struct c2b_case {
    const char *name;
    cbx_cbox in;
    cbx_status expect;
    int oob;
} c2b_case;

extern const tc_case cbt_tc_hard[];     /* transform_cbox, hard cases         */
extern const int cbt_n_tc_hard;
extern const tc_case cbt_tc_drop[];     /* transform_cbox, zero columns       */
extern const int cbt_n_tc_drop;
extern const b2c_case cbt_b2c_hard[];
extern const int cbt_n_b2c_hard;
extern const c2b_case cbt_c2b_hard[];
extern const int cbt_n_c2b_hard;

/* ---------------------------------------------------------------------- */
/* Random generation (cbox_random.c)                                      */
/* ---------------------------------------------------------------------- */

/* ~87% in domain, ~10% pushed out (or to the edge), ~1.5% NaN, ~1.5% empty */
void cbt_gen_tc_case(xu_rng *r, cbx_affine *a, cbx_cbox *b);
/* zero-coefficient columns (kind D and its neighbours) */
void cbt_gen_tc_drop_case(xu_rng *r, cbx_affine *a, cbx_cbox *b);
void cbt_gen_b2c_case(xu_rng *r, cbx_box *b);
void cbt_gen_c2b_case(xu_rng *r, cbx_cbox *b);

#endif /* CBOX_PARTS_H */
