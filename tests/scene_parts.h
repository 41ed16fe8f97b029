/*
 * scene_parts.h: the pieces of tests/test_scene.c (the scene tool against
 * GMP) that need neither the tool's headers nor its sources, for the
 * driver test_scene.c and for each other:
 *   scene_exact.c  the exact maps (mpq): operations, motion, keyframes
 *                  (slerp in MPFR), composition; the tightness ratios;
 *   scene_gen.c    the generated scene texts (deep random scenes, scenes
 *                  whose composed maps are the whole bound).
 * They are compiled once into build/libtestutil.a (scripts/testutil.sh),
 * without -Itools/certbox: what needs scene.h (the leaves' checks, the
 * level-by-level evaluation, the error cases) stays in the driver.  The
 * exported names carry the prefix sct_.
 */
#ifndef SCENE_PARTS_H
#define SCENE_PARTS_H

#include <stddef.h>
#include <gmp.h>

#include "certbox.h"
#include "exact_util.h"

/* ---- the exact maps (scene_exact.c) ------------------------------------ */
typedef struct qmap { mpq_t m[3][4]; } qmap;   /* y = M x + T, exact */

void sct_qm_init(qmap *q);
void sct_qm_clear(qmap *q);
void sct_qm_ident(qmap *q);
/* q = (1 - s) a0 + s a1, exactly (s = 0: a0) */
void sct_qm_from(qmap *q, const cbx_affine *a0, const cbx_affine *a1, const mpq_t s);
/* r = a o b (apply b first); r may not alias a or b */
void sct_qm_compose(qmap *r, const qmap *a, const qmap *b);
/* A keyframes node's map at time tm (T(tm) + R(tm) diag(S(tm)), R by slerp
 * or nlerp in MPFR at 300 bits, as a rational). */
void sct_trs_map(const cbx_trs *k0, const cbx_trs *k1, int nlerp, const mpq_t tm, qmap *out);

typedef struct stats { long leaves, checks, fails, ratios_n, ratios_cap; double *ratios; } stats;

/* append a tightness ratio (exit 2 when out of memory) */
void sct_add_ratio(stats *st, double r);

/* ---- generated scenes (scene_gen.c) ------------------------------------ */
/* A growing text buffer for generated scenes. */
typedef struct sbuf { char *p; size_t n, cap; } sbuf;

void sct_sb_add(sbuf *b, const char *fmt, ...);
/* a deep random scene: nn nodes (branch probability pb %, motion nodes
 * probability pm %), nl leaves */
void sct_gen_deep(xu_rng *r, sbuf *b, int nn, int nl, int pm, int pb);
/* the scenes whose composed maps are the whole bound (kind 0, 1, 2) */
void sct_gen_tight(xu_rng *r, sbuf *b, int kind, int nn, int nl);

#endif /* SCENE_PARTS_H */
