/*
 * glTF 2.0 input for the certbox tool (.gltf JSON with .bin buffers or
 * data: URIs, or one binary .glb): a sound world box for every mesh
 * instance (node path, mesh, primitive) and for every scene.  Limits and
 * promise: docs/gltf.md.  JSON is parsed by jansson; only the tool links
 * it (the library stays dependency-free).  Used by main.c and by
 * tests/test_gltf.c.
 */
#ifndef CBX_GLTF_H
#define CBX_GLTF_H

#include <stddef.h>
#include <stdio.h>
#include "certbox.h"

/* An interval 3x4 affine map: y_i = sum_j M_ij x_j + M_i3 for some real
 * M_ij in [lo[i][j], hi[i][j]] (ends may be infinite, never NaN): the
 * library's cbx_imat, composed by cbx_imat_compose and applied to boxes by
 * cbx_transform_box_imat (certbox.h, proven). */
typedef cbx_imat gl_imat;

/* A node as written: its local map (a degenerate interval for `matrix`,
 * outward-rounded T*R*S for TRS), the numbers it came from, its parent. */
typedef struct gl_node {
    int parent, mesh, has_matrix;
    double matrix[16];          /* column-major, as in the file */
    double t[3], r[4], s[3];    /* TRS as in the file (r = x, y, z, w) */
    gl_imat local;
    gl_imat world;              /* memoised: parent world * local */
    int world_done;
} gl_node;

/* A POSITION accessor (or an index accessor) after checking. */
typedef struct gl_acc {
    int used;                   /* 1 once checked as a POSITION accessor */
    int ctype, normalized;      /* componentType, normalized flag */
    long count;
    int has_minmax;
    double min[3], max[3];
    int no_data;                /* Draco: the vertices are not readable */
    /* vertex data: element k at base + k * stride (NULL: all zero) */
    const unsigned char *base;
    size_t stride;
    /* sparse: sp_n indices (componentType sp_ict at sp_idx, strictly
     * increasing: checked), values at sp_val (element size as above) */
    long sp_n;
    int sp_ict;
    const unsigned char *sp_idx, *sp_val;
    cbx_box vbox;               /* hull of the vertices (outward) */
    int vnan, vinf;             /* some vertex is NaN / infinite */
    long outside, first_out;    /* vertices outside min/max; the first */
} gl_acc;

/* One mesh instance: a primitive of the mesh of a node, in one scene. */
typedef struct gl_leaf {
    int scene, node, mesh, prim, acc;
    char path[256];             /* node indices root to leaf, "0/3/7" */
    cbx_box local;              /* the box that is transformed */
    cbx_box world;
    cbx_status st;
} gl_leaf;

typedef struct gl_scene { cbx_box world; cbx_status st; int first, n; } gl_scene;

/* An animation sampler as read (--animated): n key times t (finite,
 * strictly increasing) and, per key, ncomp numbers (3: translation or
 * scale; 4: a rotation, as stored: normalized integers as their
 * numerators, a common factor that leaves the rotation unchanged), three
 * such groups per key for CUBICSPLINE (in-tangent, value, out-tangent).
 * v is NULL until a channel reads the sampler's output (its path decides
 * the type).  interp: GL_LINEAR, GL_STEP, GL_CUBICSPLINE. */
enum { GL_LINEAR, GL_STEP, GL_CUBICSPLINE };
typedef struct gl_sampler { int interp, ncomp; long n; long long output; double *t, *v; } gl_sampler;
/* A channel: node, path (0 translation, 1 rotation, 2 scale), sampler. */
typedef struct gl_channel { int node, path, sampler; } gl_channel;
typedef struct gl_anim { gl_sampler *smp; int nsmp; gl_channel *ch; int nch; } gl_anim;

/* gltf_load's options */
#define GLTF_FROM_VERTICES 1u   /* each accessor bounded by its vertices, not min/max */
#define GLTF_ANIMATED      2u   /* boxes over the static pose and every pose of every animation */
/* --animated: each interval between consecutive key times of an animation
 * is cut into n cells of equal length, 1 <= n <= GLTF_ANIM_CELLS_MAX
 * (GLTF_ANIM_CELLS when not given); the excess about halves when n
 * doubles (docs/gltf.md) */
#define GLTF_CELLS(n)      ((unsigned)(n) << 8)
#define GLTF_ANIM_CELLS_MAX 4096
/* --animated --animation k: only animation k (0 <= k <= GLTF_ANIM_ONLY_MAX)
 * joins the static pose (an index the file does not have is refused) */
#define GLTF_ANIM_ONLY(k)  ((unsigned)((k) + 1) << 21)
#define GLTF_ANIM_ONLY_MAX 2046
#define GLTF_ANIM_CELLS 32

typedef struct gl_doc {
    void *json;                 /* json_t * (the parsed document) */
    unsigned char *file; size_t nfile;
    unsigned char **bufs; size_t *nbufs; int nbuf;
    gl_node *nodes; int nn;
    gl_acc *accs; int na;
    gl_leaf *leaves; int nl, capl;
    gl_scene *scenes; int ns;
    gl_anim *anims; int nanim;  /* read with GLTF_ANIMATED only */
    int cells;                  /* cells per key interval (GLTF_ANIMATED) */
    int only_anim;              /* the one animation bounded, or -1: all */
    int notes;                  /* flagged problems (printed on stderr) */
} gl_doc;

/* 1 if the file's content looks like glTF (GLB magic, or JSON: `{` after
 * blanks), 0 otherwise (or unreadable). */
int gltf_sniff(const char *path);

/* Load, check and bound a glTF file.  opts: GLTF_FROM_VERTICES (bound
 * each accessor by its vertices instead of its min/max), GLTF_ANIMATED
 * (each mesh instance's box also holds it at every time of every
 * animation: translation, rotation and scale channels, LINEAR (rotation:
 * slerp), STEP and CUBICSPLINE).  0 on success (notes on the
 * file's own claims, if any, are printed on `notes`, which may be NULL);
 * -1 and err "FILE:LINE:COLUMN: msg", "FILE: byte N: msg" or
 * "FILE: /json/pointer: msg" on a bad file (nothing kept). */
int gltf_load(gl_doc *d, const char *path, unsigned opts, FILE *notes,
              char *err, size_t errlen);
void gltf_free(gl_doc *d);

/* Vertex k of accessor a, exactly: component j is num[j] / den (den = 1
 * for float32; 127, 255, 32767 or 65535 for normalized integers, where
 * num is already clamped to -den as the spec says). */
void gltf_vertex(const gl_doc *d, int a, long k, double num[3], double *den);

/* The vertex index of sparse entry s (0 <= s < sp_n) of accessor a.  An
 * accessor without a bufferView holds zeros but at its sparse indices:
 * its count may be 2^31 - 1 with a few bytes of data, so its vertices are
 * visited as its sparse entries plus one zero vertex (the first index that
 * is not sparse, gltf_first_zero), never one by one. */
long gltf_sparse_index(const gl_doc *d, int a, long s);
/* That first zero vertex of accessor a (no bufferView), or -1 if every
 * vertex is sparse (or the accessor has a bufferView). */
long gltf_first_zero(const gl_doc *d, int a);

/* The tool: certbox [--json] [--hex] [--from-vertices] [--animated [--cells N] [--animation K]]
 * FILE.gltf|FILE.glb.
 * Returns the exit status, or -1 if FILE is not glTF (or no FILE given):
 * then the caller goes on with its own formats. */
int gltf_main(int argc, char **argv);

/* The tool's box output, for both formats: "lo X Y Z hi X Y Z" (%.17g, or
 * %a with hex), or the same as JSON fields with json. */
void tool_print_box(const cbx_box *b, int hex, int json);

#endif /* CBX_GLTF_H */
