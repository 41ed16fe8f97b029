/*
 * The exact (GMP) oracle of the glTF reader, shared by tests/test_gltf.c
 * and the libFuzzer harness tests/fuzz/fuzz_gltf.c (one copy only).
 *
 *   - gx_world: every node's exact map (mpq) from the numbers the reader
 *     kept: `matrix` as written, TRS as T * R(q)/|q|^2 * S with the exact
 *     normalised quaternion rotation, composed root first;
 *   - gx_check_leaf: every vertex of a mesh instance (float32 exactly,
 *     normalized integers as exact fractions), mapped by that exact map,
 *     lies inside a given box (an infinite coordinate: the end it pushes
 *     must be infinite); optionally the 8 corners of min/max too.
 */
#ifndef GLTF_ORACLE_H
#define GLTF_ORACLE_H

#include <gmp.h>
#include "gltf.h"

typedef struct gx_map { mpq_t m[3][4]; int done; } gx_map;   /* y = M x + T */

/* what gx_check_leaf checked */
typedef struct gx_counts { long vertices, corners, inf_checks; } gx_counts;

/* called once per failure found (printf-style, the message ends in \n) */
typedef void (*gx_report_fn)(const char *fmt, ...);

void gx_init(gx_map *q);
void gx_clear(gx_map *q);
/* T R(q)/|q|^2 diag(S), exactly (q not zero) */
void gx_trs(gx_map *L, mpq_t T[3], mpq_t q[4], mpq_t S[3]);
/* The node's exact local map from the numbers the reader kept. */
void gx_local(gx_map *L, const gl_node *g);
/* r = a o b (b first) */
void gx_compose(gx_map *r, const gx_map *a, const gx_map *b);
/* exact world map of node k, memoised in W (d->nn entries, gx_init'ed) */
const gx_map *gx_world(const gl_doc *d, gx_map *W, int k);
/* y outside [b->lo[i], b->hi[i]] (an infinite end holds everything) */
int gx_outside(const mpq_t y, const cbx_box *b, int i, mpq_t tmp);
/* Check leaf L's box `b` against the exact vertices mapped by W (and the
 * min/max corners if `corners`; with `skip_outside`, only the vertices
 * inside a flagged accessor's min/max).  Returns the failures, each also
 * passed to `report` (NULL: quiet); fills the exact hull of the mapped
 * vertices (hlo, hhi, mpq_init'ed by the caller) and their number *nh. */
long gx_check_leaf(const gl_doc *d, const gl_leaf *L, const cbx_box *b, const gx_map *W, int corners,
                   int skip_outside, gx_counts *st, const char *file, gx_report_fn report,
                   mpq_t hlo[3], mpq_t hhi[3], int *nh);

#endif /* GLTF_ORACLE_H */
