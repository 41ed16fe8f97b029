/*
 * certbox scene files: a node hierarchy of affine transforms with box,
 * sphere and ellipsoid leaves; world-space bounds of every leaf and of the
 * scene, level by level through the proven kernels (deep leaves: then by
 * outward-rounded interval maps composed once per node).  Format:
 * examples/scene-format.md.  Used by the `certbox` tool (main.c) and by
 * tests/test_scene.c.
 */
#ifndef CBX_SCENE_H
#define CBX_SCENE_H

#include <stddef.h>
#include "certbox.h"

#define SC_NAME_MAX 64
#define SC_LINE_MAX 4096
#define SC_COUNT_MAX 1000000

enum sc_kind { SC_BOX = 0, SC_SPHERE = 1, SC_ELLIPSOID = 2 };

/* One operation: its given double map, prepared at load (cbx_prepare: its
 * class and fast-range flag), so that a node's operations are the array
 * cbx_transform_box_chain takes. */
typedef cbx_prepared sc_op;

/* A node: parent (-1 for a root), its operations ops[first .. first+n-1]
 * in file order (O1 .. On: p_parent = O1(O2(...On(p)))); a motion node
 * has exactly one operation per side: ops[first] at s = 0 and
 * ops[first + 1] at s = 1, or (trs > 0) no operation and the keyframes
 * keys[trs - 1] (s = 0) and keys[trs] (s = 1), interpolated by slerp
 * (nlerp != 0: nlerp). */
typedef struct sc_node {
    char name[SC_NAME_MAX];
    int parent, first, n, motion, line, trs, nlerp;
} sc_node;

/* The cells of a keyframes node's shutter (cbx_motion_trs_box's depth):
 * 2^5 = 32, about 2.4% of the box's side for turns of 45 to 180 degrees. */
#define SC_TRS_DEPTH 5U

/* A leaf: box v[0..5] = lo, hi; sphere v[0..3] = center, radius;
 * ellipsoid v[0..2] center, v[3..5] radii, v[6..14] orientation (row-major). */
typedef struct sc_leaf {
    char name[SC_NAME_MAX];
    int node, kind, line;
    double v[15];
    cbx_box world;      /* set by scene_eval */
    cbx_status st;      /* most severe status met on the way up */
} sc_leaf;

typedef struct scene {
    sc_node *nodes; int nn, capn;
    sc_op *ops; int no, capo;
    sc_leaf *leaves; int nl, capl;
    cbx_trs *keys; int nk, capk;  /* the keyframes of keyframes nodes, two each */
    int *hash; int hcap;          /* name lookup: index+1 of node (>0) or -(leaf+1) */
    cbx_box world;                /* union of the leaves' world boxes */
    cbx_status st;                /* most severe leaf status */
} scene;

/* Parse a whole scene from text (NUL-terminated).  0 on success; else -1
 * and err holds "FILE:LINE: message" (file is the name used in messages);
 * on failure nothing is kept (the scene is freed). */
int scene_parse(scene *s, const char *text, const char *file, char *err, size_t errlen);
/* The same for text[0 .. n-1] (text[n] must be '\0'): a NUL byte inside is
 * refused with its line, "FILE:LINE: the file contains a NUL byte (column C)". */
int scene_parse_buf(scene *s, const char *text, size_t n, const char *file, char *err, size_t errlen);
/* Read a file and parse it (scene_parse_buf). */
int scene_load(scene *s, const char *path, char *err, size_t errlen);
/* Compute every leaf's world box and the scene box (linear time). */
void scene_eval(scene *s);
void scene_free(scene *s);
const char *scene_kind_name(int kind);
/* Severity order used for "most severe": OK < EMPTY < ERANGE < EINVAL. */
int scene_severity(cbx_status st);

#endif /* CBX_SCENE_H */
