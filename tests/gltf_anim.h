/*
 * gltf_anim.h: what tests/test_gltf.c shares with tests/gltf_anim.c (built
 * like tests/gltf_oracle.c: -DCBX_GLTF, jansson, -Itools/certbox; not in
 * build/libtestutil.a): the statistics, the failure count (defined in the
 * driver), the exact image of a box, and the checks of --animated.
 */
#ifndef GLTF_ANIM_H
#define GLTF_ANIM_H

#include <stdio.h>
#include <gmp.h>
#include "gltf.h"
#include "gltf_oracle.h"

typedef struct stats {
    long files, loaded, refused, flagged, instances, teeth, imat_fin, imat_inf;
    long locals, worlds;                /* node interval matrices checked entry-wise */
    gx_counts c;                        /* vertices, corners, infinite ends checked */
    double round_mm, round_v;           /* max relative excess over the exact image of the box mapped */
    double excess_mm, excess_v;         /* ... over the exact hull of the mapped vertices */
    long anim_files, anim_keys, anim_poses, anim_checks, anim_axes;   /* --animated */
    long anim_only, anim_only_refused;  /* --animation k loads; out-of-range k refused */
    double anim_excess, anim_excess_sum, anim_excess4;
} stats;

/* every failure (test_gltf.c) */
extern long glt_n_fail;
/* counts every failure, prints the first 50 */
#define FAIL(...) do { if (++glt_n_fail <= 50) fprintf(stderr, "FAIL " __VA_ARGS__); } while (0)

/* exact image of box b (finite) under W on axis i: lo, hi */
void glt_box_image(const cbx_box *b, const gx_map *W, int i, mpq_t lo, mpq_t hi);

/* random times between each two consecutive key times (check_anim) */
#define ANIM_T 24
/* the largest excess accepted at the default cells (measured 2026-11-27:
 * 0.086 on anim_rot.gltf, a box on cubic splines under a turning, moving,
 * scaling parent) */
#define ANIM_MAX_EXCESS 0.1
/* set while a file of kind "anim loose" is checked: its excess is not
 * counted (an exact half turn, both arcs: expect.txt) */
extern int glt_anim_no_stats;
/* The --animated checks of a loaded document (gltf_anim.c); returns the
 * largest excess of a box over the hull of its sampled images. */
double glt_check_anim(const gl_doc *d, const char *file, stats *st);

#endif /* GLTF_ANIM_H */
