/*
 * batch_parts.h: the parts of tests/test_batch.c (cbx_transform_boxes and
 * the prepared forms against cbx_transform_box_as box by box), shared by
 * its files:
 *   tests/batch_gen.c    the random maps, boxes and batches, and the
 *                        special values (a base map of each class, a base
 *                        box, each value in each position);
 *   tests/batch_check.c  one batch checked (bits, statuses, guards,
 *                        inputs), the prepared forms on it, the failure log.
 * The driver, tests/test_batch.c, runs the batches in order and prints the
 * summary.  Every name with linkage starts with bat_ (one archive, every
 * test links it: build/libtestutil.a).
 */
#ifndef BATCH_PARTS_H
#define BATCH_PARTS_H

#include <stddef.h>
#include <math.h>

#include "certbox.h"
#include "exact_util.h"

#define INF HUGE_VAL
#define GUARD 4
#define MAXN 1000
#define MAX_FAIL_LOGS 20

/* box kinds; the random batches draw the first NB_RAND */
enum { B_NORMAL, B_NAN, B_EMPTY, B_OOD, B_HALF, B_FLAT, B_EDGE, NB_RAND, B_SPECIAL = NB_RAND,
       NB };

/* the checks (see tests/test_batch.c) */
enum { K_BITS, K_STATUS, K_GUARDS, K_INPUTS, NK };

/* the structs handed to the prepared forms (see the top comment) */
enum { V_PREP, V_ZERO, V_CLS, V_FORGED, NV };

typedef struct stats {
    long batches, failed, boxes;
    long by_n[6];                /* batches of n = 0, 1, 2, 7, 1000, other   */
    long kinds[NB];              /* boxes by kind                            */
    long status_ret[4];          /* returned statuses                        */
    long checked[NK], fail[NK];
    long logs;
    /* prepared maps */
    long prep_maps, prep_fast, prep_fail;     /* cbx_prepare's struct checked */
    long one[NV], one_fail[NV];               /* box_prep: boxes              */
    long inplace_fail[NV];                    /* box_prep in place: boxes     */
    long many[NV], many_boxes[NV], many_fail[NV]; /* boxes_prep: batches      */
    long exact, exact_fail;                   /* forged structs' boxes, exact */
    long special;                             /* special-value inputs         */
} stats;

/* ---- tests/batch_gen.c ------------------------------------------------- */

/* a random map of a kind (0 ordinary, 1 zero columns, 2 an infinite entry,
 * 3 a NaN, 4 huge entries, 5 a map of a class, 6 the fast range's edge) */
void bat_gen_map(xu_rng *r, cbx_affine *a, int kind);
/* a random box of a kind (B_NORMAL .. B_EDGE) */
void bat_gen_box(xu_rng *r, cbx_box *b, int kind);
/* a batch of n boxes (n <= MAXN) with a random mix of kinds, checked */
void bat_random_batch(xu_rng *r, stats *st, xu_exact *x, const cbx_affine *a, size_t n);
/* the special values, the base maps (one per class) */
extern const int bat_n_special, bat_n_base;
/* each special value in each of the 18 positions of each base map and the
 * base box, a batch of one box, with every forged cls value */
void bat_run_specials(stats *st, xu_exact *x);

/* ---- tests/batch_check.c ----------------------------------------------- */

extern const char *const bat_b_name[NB];
extern const char *const bat_v_name[NV];
/* One batch of n boxes in[0 .. n-1] (n <= MAXN) of the given kinds, checked,
 * and the prepared forms on it with nforge forged cls values of
 * xu_cls_values from index f0 on. */
void bat_run_batch(stats *st, xu_exact *x, const cbx_affine *a, const cbx_box *in,
                   const int *kinds, size_t n, int f0, int nforge);

#endif /* BATCH_PARTS_H */
