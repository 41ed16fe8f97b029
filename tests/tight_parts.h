/*
 * tight_parts.h: the pieces of tests/test_tight.c (cbx_transform_box_tight
 * against GMP and MPFR) that live in their own files, for the driver
 * test_tight.c and for each other:
 *   tight_check.c  the context, the checks of one finite end and of one
 *                  case, the statistics per section and their report;
 *   tight_gen.c    the random generators of sections 1 to 5;
 *   tight_cases.c  the hard cases of section 0.
 * They are compiled once into build/libtestutil.a (scripts/testutil.sh)
 * with the library's normal flags: nothing here depends on CBX_NO_FMA
 * (build/test_tight_nofma); the two_prod form is printed by the driver.
 * The exported names carry the prefix tgt_.
 */
#ifndef TIGHT_PARTS_H
#define TIGHT_PARTS_H

#include <math.h>
#include <gmp.h>
#include <mpfr.h>

#include "certbox.h"
#include "exact_util.h"

#define INF HUGE_VAL

/* ---------------------------------------------------------------------- */
/* Context and statistics (tight_check.c)                                 */
/* ---------------------------------------------------------------------- */

typedef struct tctx {
    xu_exact x;
    mpz_t E, p, tiny, big, big1000, smallE, near967;
    mpq_t q, qa, qb;
    mpfr_t r53;
    xu_rng rng;
    long logs, cat_logs[4], notes;
} tctx;

enum { C_STATUS, C_ORACLE, C_KINDS, C_CONTAIN, C_LOOSER, C_OPTIMAL, C_CROSS,
       C_INPLACE, C_INPUTS, C_GAP, NC };

typedef struct sec {
    const char *title;
    long cases, failed;
    long status_seen[4];         /* by the status cbx_transform_box gave    */
    long kind[XU_NEND];          /* end kinds (inputs without NaN, not empty) */
    long fin;                    /* finite ends checked exactly              */
    long fin_exact;              /* E is a double: the end equals it        */
    long tightened;              /* tight end != cbx_transform_box's end     */
    long nc_ends;                /* ends with 4 |E| >= S > 0 (no cancellation) */
    long gap_kernel_out;         /* ends in the gap check's range where
                                    cbx_transform_box's end is outside the
                                    gap (the check's teeth)               */
    double base_ulps_max, base_ulps_sum; /* there: cbx_transform_box's end
                                    minus the tight one, in ulps of E      */
    long exc, exc_tiny, exc_big; /* ends in the documented exception         */
    long exc_opt, exc_kernel, exc_between, exc_nonopt_999;
    long checked[NC], fail[NC];
    /* optimality failures outside the exception, by a guess at the cause */
    long opt_near968;            /* smallest nonzero |m_j v_j| in [2^-968, 2^-967) */
    long opt_tiny_e;             /* 0 < |E| < 2^-900                         */
    long opt_other;
    long opt_between;            /* of all those: tighter than cbx_transform_box's end, yet not the tightest */
    long opt_exact_e;            /* of all those: E is a double (the end should be E) */
    long near968_maxlog;         /* largest floor(log2) of that product     */
    long tiny_e_maxlog;          /* largest floor(log2 |E|) in that bucket  */
} sec;

/* One case: cbx_transform_box_tight(a, in) against cbx_transform_box and
 * the exact values; counted in s, the first failures printed. */
void tgt_run_case(tctx *k, sec *s, const cbx_affine *a, const cbx_box *in);
void tgt_sec_init(sec *s, const char *title);
/* t += s (counts summed, maxima kept) */
void tgt_sec_add(sec *t, const sec *s);
void tgt_sec_print(const sec *s);

/* ---------------------------------------------------------------------- */
/* Generators (tight_gen.c)                                               */
/* ---------------------------------------------------------------------- */

/* Section 1: random full rows, exponents over the whole range. */
void tgt_gen_wide(xu_rng *r, cbx_affine *a, cbx_box *b);
/* Section 2: integers and small dyadics, often with a representable E. */
void tgt_gen_int(xu_rng *r, cbx_affine *a, cbx_box *b);
/* Section 3: heavy cancellation at one end of each row. */
void tgt_gen_cancel(xu_rng *r, cbx_affine *a, cbx_box *b);
/* Section 4: half-spaces, huge ends, zeros, infinities, NaN, empty. */
void tgt_gen_special(xu_rng *r, cbx_affine *a, cbx_box *b);
/* Section 5: near the exception's boundaries. */
void tgt_gen_boundary(xu_rng *r, cbx_affine *a, cbx_box *b);

/* ---------------------------------------------------------------------- */
/* Hard cases (tight_cases.c)                                             */
/* ---------------------------------------------------------------------- */

typedef struct hard { const char *name; cbx_affine a; cbx_box in; } hard;

extern const hard tgt_hard_cases[];
extern const int tgt_n_hard;

#endif /* TIGHT_PARTS_H */
