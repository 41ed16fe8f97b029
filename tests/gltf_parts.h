/*
 * gltf_parts.h: the pieces of tests/test_gltf.c (the glTF reader against
 * GMP) that need neither the tool's headers nor jansson, for the driver
 * test_gltf.c and tests/gltf_anim.c:
 *   gltf_exact.c  the exact helpers the checks share, and
 *                 cbx_transform_box_imat alone on random cases;
 *   gltf_files.c  DATA_DIR/expect.txt, and the glTF files under a folder.
 * They are compiled once into build/libtestutil.a (scripts/testutil.sh),
 * without -DCBX_GLTF, -Itools/certbox or jansson; what needs those is in
 * the driver and in gltf_anim.c (gltf_anim.h).  The exported names carry
 * the prefix glt_.
 */
#ifndef GLTF_PARTS_H
#define GLTF_PARTS_H

#include <gmp.h>

#include "certbox.h"

/* ---- exact helpers and the imat test (gltf_exact.c) --------------------- */
/* relative excess of box end e over the exact bound x (sign: outward) */
double glt_excess(double e, const mpq_t x, double scale, int upper);
/* max(|a|, |b|) as doubles */
double glt_qabs_max(const mpq_t a, const mpq_t b);
/* 1 if the exact q lies outside [lo, hi] (an infinite end holds all) */
int glt_q_out(const mpq_t q, double lo, double hi, mpq_t t);
/* the exact sign of the dot product of two stored quaternions */
int glt_dot_sign(const double *a, const double *b);
/* n random cases of cbx_transform_box_imat, checked exactly; each failure
 * counted in *nfail (the first 50 printed, as FAIL in the driver); the
 * cases with every axis in the fast range in *n_fin, the others *n_inf */
void glt_test_imat_box(long n, long *nfail, long *n_fin, long *n_inf);

/* ---- files and expectations (gltf_files.c) ------------------------------ */
typedef struct expect { char file[512]; char kind[8]; char sub[200]; int seen; } expect;

/* the lines of expect.txt (exit 2 if it cannot be read) */
int glt_read_expect(const char *path, expect **out);
/* qsort's comparison of two char * */
int glt_cmpstr(const void *a, const void *b);
/* append every .gltf / .glb under dir (recursively) to *list */
void glt_find_files(const char *dir, char ***list, int *n, int *cap);

#endif /* GLTF_PARTS_H */
