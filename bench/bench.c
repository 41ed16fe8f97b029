/*
 * bench: the benchmark of issue 5 and of the fast path (`make bench`,
 * `make bench-smoke`).
 *
 * Usage: bench [-n N] [-r R] [-calls C] [-exact NE] [-gmp NG] [-cache NC]
 *              [-big NB] [-scene NS] [-seed S] [-o DIR]
 *   N   cases of the main rows (default 20000)  R   timed rounds (11)
 *   C   calls per run (200000)                   NE  exactly measured (20000)
 *   NG  cases of the GMP row (2000)              NC  in-cache throughput (1000)
 *   NB  large-array throughput (4000000; 0: no throughput rows)
 *   NS  scene instances (NB / 4; N when NB is 0)
 *   S   seed (20240501)                          DIR output (build/bench-out)
 * Writes DIR/bench.tsv: every row of this build (one line each: times,
 * ratios, exact excess, checks, notes) and, as "#meta" lines, the machine,
 * the compiler, the flags and the date; prints a short summary.
 * scripts/bench_table.py renders the bench.tsv of one or more builds as one
 * markdown table, DIR/bench.md, and DIR/bench.dat for the plot
 * (scripts/bench_plot.sh, scripts/bench.gp).  `make bench` and `make
 * bench-smoke` build this file twice: build/bench with the library's flags
 * (-O2) against build/libcertbox.a, and build/bench-native with
 * -O3 -march=native against build/native/libcertbox.a (the library
 * compiled again with those flags); both keep -ffp-contract=off
 * -fno-fast-math.  They run one after the other and their tables are
 * merged, one column group per build.
 * Exit status 1 if a certbox row has a containment failure, a call that
 * does not return CBX_OK, an output that is not bit-identical to the row it
 * must equal (the prepared and batch forms against cbx_transform_box(f)
 * on the same maps and boxes, checked untimed), a tight end that is not the
 * tightest double, or a scene class-kernel end looser than the general
 * kernel's.
 *   make bench        -n 20000 -r 11 -calls 200000 -exact 20000 -gmp 2000
 *                     -cache 1000 -big 4000000 (about 2.5 GB of memory)
 *   make bench-smoke  -n 2000 -r 11 -calls 10000 -exact 2000 -gmp 200
 *                     -cache 500 -big 50000 (a few seconds per build)
 *
 * Inputs (fixed seed S): N random affine maps M = R diag(s) with T (R a
 * rotation from a uniform random unit quaternion, s_j = +-2^[-4,4] with 10%
 * reflections, T_i = +-[0,1) * 2^[-2,10]) and N boxes of mixed sizes
 * (center +-[0,1) * 2^[-4,8], half-width 2^[-12,6] per axis, 5% of the
 * axes flat: lo = hi).  The binary32 rows run on the same N cases rounded
 * to binary32 (untimed).  All inputs lie in the fast range of the
 * prepared maps, so the fast path is what the certbox rows time.
 *
 * Rows (main table: every row against a classic round-to-nearest Arvo
 * baseline run on the same inputs in the same rounds)
 *   1   naive 8 corners, RN: each corner transformed as a point, min / max
 *       (pbrt, Embree); bench/bench_ref.h ref_naive8.  Against row 2.
 *   2   classic Arvo interval form, RN (cglm, Godot): ref_arvo_box, each
 *       box under its own map.  Unsound (no widening).  The baseline of
 *       rows 1, 3, 3p, 3t, 3i, 4-7.
 *   3   cbx_transform_box, each box under its own map.
 *   3p  cbx_transform_box_prep, each box under its own prepared map
 *       (cbx_prepare, untimed): output bit-identical to row 3's.
 *   3t  tight: cbx_transform_box_tight (every finite end the tightest
 *       double, RD / RU of the exact end); its notes give, exactly (GMP,
 *       MPFR), how many ends are not the tightest double (must be 0).
 *   3i  cbx_transform_box_imat, each box under its own map as a point
 *       interval matrix (lo = hi = the map, built untimed): what the
 *       interval-matrix kernel (four corner products per term) costs.
 *   2a  ref_arvo_box with one map (the first case's) for every box: the
 *       baseline of 3a-3bp.
 *   3a  cbx_transform_box, that one map for every box.
 *   3ap cbx_transform_box_prep, that map prepared once (untimed).
 *   3b  cbx_transform_boxes(&a[0], in, out, N), one call.
 *   3bp cbx_transform_boxes_prep, one call.  3ap, 3b and 3bp: output
 *       bit-identical to row 3a's.
 *   2f, 3f, 3fp      binary32: ref_arvo_boxf (bench/bench_ref.h),
 *       cbx_transform_boxf and cbx_transform_box_prepf, each box under its
 *       own map; 3fp bit-identical to 3f.
 *   2af, 3af, 3afp, 3bf, 3bfp   binary32, one map for every box:
 *       ref_arvo_boxf, cbx_transform_boxf, cbx_transform_box_prepf,
 *       cbx_transform_boxesf, cbx_transform_boxes_prepf; the last three
 *       bit-identical to 3af.
 *   4   cbx_transform_cbox; inputs converted with cbx_box_to_cbox
 *       (outward) before the timed loops.
 *   5   classic Arvo center/half form, RN: ref_arvo_cbox on inputs
 *       converted with c = (lo+hi)/2, h = (hi-lo)/2 in RN (untimed).
 *   6a  sphere: cbx_sphere_box (exact dual-quadric bound t -+ sqrt(sum
 *       m^2), outward) of the unit ball under the same N maps.
 *   6b  sphere by Arvo: cbx_transform_box of [-1,1]^3 under the same maps
 *       (sound, but the box of a rotated box); the notes give the mean of
 *       vol(6b) / vol(6a) over the exact subset.
 *   7   GMP exact: xu_row_bounds (tests/exact_fixed.c) for the 3 rows of
 *       each of the first NG cases.
 *   S-A, S, Sc   scene: NS instances (default NB / 4), each with its own
 *       map and box, in random order, with a mix of transform classes: 20%
 *       IDENTITY, 35% TRANSLATE, 15% SCALE (+ translation), 10% PERMUTE (a
 *       90-degree rotation, times a uniform scale half of the time, +
 *       translation), 20% GENERAL (as the main rows); boxes as the main
 *       rows.  Each instance is classified once (cbx_classify) when the
 *       scene is built (untimed).  S-A: ref_arvo_box on every instance
 *       (the baseline); S: cbx_transform_box; Sc: cbx_transform_box_as
 *       with the stored class.  The notes give the speed-up S / Sc and the
 *       same on the first NC instances (in cache: repeated passes let the
 *       branch predictor learn the class sequence, so that figure is
 *       optimistic), and the check that no finite Sc end is looser than
 *       S's (infinite ends identical) over all NS.
 *   S-ID, S-TR, S-SC, S-PE, S-GE  the instances of one class, copied
 *       contiguously (untimed), through cbx_transform_box_as, against
 *       ref_arvo_box on the same instances; the notes give
 *       cbx_transform_box on them and the speed-up.
 *       Checked (untimed): S and Sc exactly on the first NE instances, the
 *       8 corners of Sc in mpq on the first NG, no Sc end looser than S's.
 * Throughput table (every row against a memcpy of the same bytes, in the
 * same rounds)
 *   M1, T1   NC cases (in cache), each with its own map: memcpy of 192
 *       bytes per case (map 96, box in 48, box out 48), and
 *       cbx_transform_box.
 *   M2, T2   the same over NB cases (a large array, out of cache when above
 *       the L3 size in the header: 768 MB under make bench).
 *   M1b, T1a, T1b, T1p, T1f   NC boxes under one map (the first case's):
 *       memcpy of 96 bytes per case (box in, box out), ref_arvo_box,
 *       cbx_transform_boxes, cbx_transform_boxes_prep, and
 *       cbx_transform_boxesf over 2 NC binary32 boxes (the same bytes).
 *   M2b, T2a, T2b, T2p, T2f  the same over NB boxes (384 MB under make
 *       bench).  Each certbox output is checked (untimed, one more run)
 *       bit for bit against single cbx_transform_box(f) calls on every
 *       case, and exactly on its first NE cases.
 *
 * Timing: clock_gettime(CLOCK_MONOTONIC) around one run; a run is P passes
 * over the row's array (P = max(1, C / N): about C calls, so that a run
 * lasts milliseconds even for a small array).  The rows are timed in
 * groups, a baseline and the rows measured against it: one untimed
 * warm-up round, then R rounds, each running the baseline once and then
 * each row of the group once, so that drift (frequency, load) hits the
 * baseline and the rows alike.  ns per box = median over the rounds of
 * run time / (P N); "vs baseline" = median over the rounds of the ratio
 * of the row's run to the baseline's run of the same round (per box; in
 * the throughput table per byte, and shown as the percentage of memcpy's
 * bandwidth).  The same in the thread's CPU time
 * (CLOCK_THREAD_CPUTIME_ID), which leaves out the time the thread was
 * descheduled: on a loaded machine the figure to trust.  The baselines are
 * static inline (as in the header-only libraries they stand for) and
 * compiled with the same flags as the library; certbox is an out-of-line
 * call into the library.  Dead-code elimination is defeated by writing
 * every result to an output array, by an opaque call (a volatile function
 * pointer) after each pass, and by checksumming the output array after
 * each run into a volatile sink (outside the timed region).
 *
 * Exact columns
 *   excess       for each end of each axis of the first NE cases, computed
 *                exactly with GMP (exact_util): lower end L - lo, upper end
 *                hi - H, with L, H the exact bounds of the image of the
 *                input box, in units of u S + eta (u = 2^-53, eta =
 *                2^-1074; binary32 rows: u = 2^-24, eta = 2^-149, the
 *                exact image of the binary32 inputs), S = |t| + sum_j
 *                |m_j| max(|lo_j|, |hi_j|) (xu_row_bounds); max and mean
 *                over all ends.  A center/half output (c, h) is the real
 *                box [c - h, c + h], taken exactly.  Negative = the end is
 *                inside the exact image.  For the sphere rows the exact
 *                ends are t -+ sqrt(sum_j m_j^2) (MPFR, 320 bits) and the
 *                unit is u (|t| + sqrt(sum_j m_j^2)) + eta.
 *   ulps         the same gaps in ulps of the exact end (the spacing of
 *                the row's format at |L| or |H|), max and mean over the
 *                ends with no cancellation, |end| >= S / 4 (where the end
 *                is small against S its ulp is small and the count grows
 *                like S / |end|, measuring the cancellation rather than
 *                the method); the number of ends left out is in the notes.
 *   containment  ends that are NOT outside-or-equal the exact bound
 *                (lo > L or hi < H, decided exactly), out of all ends
 *                measured.  May be > 0 for the RN baselines; must be 0 for
 *                the certbox rows.
 *   digest       a checksum of the row's output (the same inputs in every
 *                build): scripts/bench_table.py fails when a certbox row's
 *                output differs between the builds.
 */
#define _POSIX_C_SOURCE 200112L
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <gmp.h>
#include <mpfr.h>
#include "certbox.h"
#include "exact_util.h"
#include "bench_ref.h"

#ifndef BENCH_FLAGS
#define BENCH_FLAGS "(unknown)"
#endif
#ifndef BENCH_CC
#define BENCH_CC "cc"
#endif
#ifndef BENCH_LABEL /* the build's name in the merged table */
#define BENCH_LABEL "-O2"
#endif
#if defined(__VERSION__) && defined(__GNUC__) && !defined(__clang__)
#define BENCH_CC_VERSION "gcc " __VERSION__
#elif defined(__VERSION__)
#define BENCH_CC_VERSION __VERSION__
#else
#define BENCH_CC_VERSION "(unknown)"
#endif

#define MAXR 101    /* timed rounds                   */
#define MAXROWS 96  /* rows, hidden ones included     */
#define MAXG 20     /* rows per timing group          */
#define SPH_PREC 320

/* ---- defeating dead-code elimination --------------------------------- */

static void escape_impl(void *p) { (void)p; }
static void (*volatile bench_escape)(void *) = escape_impl;
static volatile uint64_t bench_sink;

static uint64_t checksum(const void *p, size_t bytes)
{
    const unsigned char *c = (const unsigned char *)p;
    uint64_t h = 1469598103934665603u, w;
    size_t i;
    for (i = 0; i + 8 <= bytes; i += 8) {
        memcpy(&w, c + i, 8);
        h = (h ^ w) * 1099511628211u;
    }
    return h;
}

/* ---- the cases ------------------------------------------------------- */

typedef struct ex_scratch { mpz_t gap, v, w, t; } ex_scratch;

typedef struct bench_ctx {
    size_t n;
    cbx_affine *a;            /* the N cases: maps and boxes              */
    cbx_box *in;
    cbx_prepared *pa, p0;     /* cbx_prepare(a[k]), cbx_prepare(a[0])     */
    cbx_imat *ia;             /* a[k] as a point interval matrix (lo = hi) */
    cbx_cbox *cin_cbx, *cin_rn; /* the boxes as cboxes: outward, RN       */
    cbx_affinef *af;          /* the N cases rounded to binary32          */
    cbx_boxf *inf;
    cbx_preparedf *paf, p0f;
    long bad;                 /* certbox calls that did not return CBX_OK */
    xu_exact x;
    ex_scratch e;
    uint64_t gmp_acc;
    /* throughput: NB cases (own map each) and 2 NB binary32 boxes (the
     * bytes of NB binary64 boxes) under the first case's map */
    cbx_affine *ta;
    cbx_box *tin, *tout;
    cbx_prepared tp0;
    cbx_affinef taf0;
    cbx_preparedf tpf0;
    cbx_boxf *tinf, *toutf;
    unsigned char *mdst;
    /* the scene: per instance its own map, box and stored class; q*: the
     * same instances sorted by class (rows S-ID .. S-GE) */
    size_t ns, ns_cnt[5], ns_off[6];
    cbx_affine *sa, *qa;
    cbx_box *sin, *qin, *qo;
    cbx_class *scls, *qcls;
    int cur;                  /* the class of the per-class kernels       */
    /* projective: N camera maps (perspective times a rigid view) and
     * boxes in front of each camera */
    cbx_proj *pm;
    cbx_box *pin;
    double *psc, *psr;        /* balls: the boxes' centres and half-sizes  */
    cbx_box *pcx;             /* boxes across the near plane               */
    double *pwn;              /* the near plane (the camera's near distance) */
    double *pxc, *pxr;        /* balls across the near plane: centres, radii */
    double *pes;              /* ellipsoids at the balls' centres: radii    */
    cbx_projf *pmf;           /* the same cameras, balls and boxes in float */
    cbx_boxf *pinf;           /* (each value rounded to nearest): the       */
    float *pscf, *psrf, *pwnf; /* binary32 twins' rows                      */
    float *pesf;              /* and the ellipsoids' radii and rotations    */
    float (*perf)[3][3];
    double (*per)[3][3];      /* and rotations                              */
    /* rotation motion: keyframe pairs (0 to 90 degrees apart) and boxes;
     * rpc: the 16 pieces of the first pair, prepared once (row R4p) */
    cbx_trs *rk0, *rk1;
    cbx_box *rin;
    cbx_imat rpc[16];
    size_t nrpc;
} bench_ctx;

static double urand(xu_rng *r, double lo, double hi)
{
    return lo + (hi - lo) * xu_rng_unit(r);
}

static void gen_box(xu_rng *r, cbx_box *b)
{
    int j;
    for (j = 0; j < 3; j++) {
        double c = urand(r, -1.0, 1.0) * ldexp(1.0, xu_rng_int(r, -4, 8));
        double h = xu_rng_int(r, 0, 19) == 0 ? 0.0 : pow(2.0, urand(r, -12.0, 6.0));
        b->lo[j] = c - h;
        b->hi[j] = c + h;
    }
}

static void gen_case(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    double R[3][3], s[3];
    int i, j;
    xu_rand_rotation(r, R);
    for (j = 0; j < 3; j++) {
        s[j] = pow(2.0, urand(r, -4.0, 4.0));
        if (xu_rng_int(r, 0, 9) == 0) s[j] = -s[j];
    }
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) a->m[i][j] = R[i][j] * s[j];
        a->m[i][3] = urand(r, -1.0, 1.0) * ldexp(1.0, xu_rng_int(r, -2, 10));
    }
    gen_box(r, b);
}

/* binary64 <-> binary32 (to: rounded to nearest; back: exact) */
static void affine_to_f(const cbx_affine *a, cbx_affinef *f)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) f->m[i][j] = (float)a->m[i][j];
}
static void affine_from_f(const cbx_affinef *f, cbx_affine *a)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) a->m[i][j] = f->m[i][j];
}
static void box_to_f(const cbx_box *b, cbx_boxf *f)
{
    int j;
    for (j = 0; j < 3; j++) {
        f->lo[j] = (float)b->lo[j];
        f->hi[j] = (float)b->hi[j];
    }
}
static void box_from_f(const cbx_boxf *f, cbx_box *b)
{
    int j;
    for (j = 0; j < 3; j++) {
        b->lo[j] = f->lo[j];
        b->hi[j] = f->hi[j];
    }
}

static const char *const scls_name[5] = { "GENERAL", "PERMUTE", "SCALE", "TRANSLATE", "IDENTITY" };
static const char *const scls_id[5] = { "S-GE", "S-PE", "S-SC", "S-TR", "S-ID" };

/* One scene instance: the box and the GENERAL map of gen_case, the map
 * replaced by one of the mix (20% IDENTITY, 35% TRANSLATE, 15% SCALE, 10%
 * PERMUTE, 20% GENERAL).  Returns the class meant. */
static cbx_class gen_scene_inst(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    /* the 5 non-identity permutations of the axes */
    static const int perm[5][3] = { { 1, 0, 2 }, { 2, 1, 0 }, { 0, 2, 1 }, { 1, 2, 0 }, { 2, 0, 1 } };
    cbx_affine g;
    int p = xu_rng_int(r, 0, 99), i, j;
    gen_case(r, &g, b);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) a->m[i][j] = 0.0;
    if (p < 20) {
        for (i = 0; i < 3; i++) a->m[i][i] = 1.0;
        return CBX_CLASS_IDENTITY;
    }
    if (p < 55) {
        for (i = 0; i < 3; i++) {
            a->m[i][i] = 1.0;
            a->m[i][3] = g.m[i][3];
        }
        return CBX_CLASS_TRANSLATE;
    }
    if (p < 70) {
        int uni = xu_rng_int(r, 0, 1);
        double s = pow(2.0, urand(r, -4.0, 4.0));
        for (i = 0; i < 3; i++) {
            a->m[i][i] = uni ? s : pow(2.0, urand(r, -4.0, 4.0));
            if (xu_rng_int(r, 0, 9) == 0) a->m[i][i] = -a->m[i][i];
            a->m[i][3] = g.m[i][3];
        }
        return CBX_CLASS_SCALE;
    }
    if (p < 80) {
        const int *q = perm[xu_rng_int(r, 0, 4)];
        double s = xu_rng_int(r, 0, 1) ? 1.0 : pow(2.0, urand(r, -4.0, 4.0));
        for (i = 0; i < 3; i++) {
            a->m[i][q[i]] = xu_rng_int(r, 0, 1) ? s : -s;
            a->m[i][3] = g.m[i][3];
        }
        return CBX_CLASS_PERMUTE;
    }
    *a = g;
    return CBX_CLASS_GENERAL;
}

static void *xmalloc(size_t bytes)
{
    void *p = malloc(bytes ? bytes : 1);
    if (!p) {
        fprintf(stderr, "bench: out of memory (%lu bytes)\n", (unsigned long)bytes);
        exit(2);
    }
    memset(p, 0, bytes); /* touch every page before timing */
    return p;
}

/* ---- kernels: one pass over the first n cases into out ---------------- */

typedef void (*kern_fn)(bench_ctx *b, size_t n, void *out);

/* A loop of a baseline (no status). */
#define REF_KERNEL(NAME, OUT_T, CALL)                          \
    static void NAME(bench_ctx *b, size_t n, void *out)        \
    {                                                          \
        OUT_T *o = (OUT_T *)out;                               \
        size_t i;                                              \
        for (i = 0; i < n; i++) CALL;                          \
    }
/* A loop of single certbox calls, counting those not CBX_OK. */
#define CBX_KERNEL(NAME, OUT_T, CALL)                          \
    static void NAME(bench_ctx *b, size_t n, void *out)        \
    {                                                          \
        OUT_T *o = (OUT_T *)out;                               \
        size_t i;                                              \
        long bad = 0;                                          \
        for (i = 0; i < n; i++) bad += (CALL) != CBX_OK;       \
        b->bad += bad;                                         \
    }
/* One batch call over all n boxes. */
#define BATCH_KERNEL(NAME, OUT_T, CALL)                        \
    static void NAME(bench_ctx *b, size_t n, void *out)        \
    {                                                          \
        OUT_T *o = (OUT_T *)out;                               \
        b->bad += (CALL) != CBX_OK;                            \
    }

static const cbx_box unit_box = {{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}};

/* the main rows: own map per box, one map (a[0]) for every box */
REF_KERNEL(k_naive, cbx_box, ref_naive8(&b->a[i], &b->in[i], &o[i]))
REF_KERNEL(k_arvo, cbx_box, ref_arvo_box(&b->a[i], &b->in[i], &o[i]))
CBX_KERNEL(k_cbx, cbx_box, cbx_transform_box(&b->a[i], &b->in[i], &o[i]))
CBX_KERNEL(k_prep, cbx_box, cbx_transform_box_prep(&b->pa[i], &b->in[i], &o[i]))
CBX_KERNEL(k_tight, cbx_box, cbx_transform_box_tight(&b->a[i], &b->in[i], &o[i]))
CBX_KERNEL(k_imat, cbx_box, cbx_transform_box_imat(&b->ia[i], &b->in[i], &o[i]))
REF_KERNEL(k_arvo1, cbx_box, ref_arvo_box(&b->a[0], &b->in[i], &o[i]))
CBX_KERNEL(k_cbx1, cbx_box, cbx_transform_box(&b->a[0], &b->in[i], &o[i]))
CBX_KERNEL(k_prep1, cbx_box, cbx_transform_box_prep(&b->p0, &b->in[i], &o[i]))
BATCH_KERNEL(k_batch, cbx_box, cbx_transform_boxes(&b->a[0], b->in, o, n))
BATCH_KERNEL(k_batchp, cbx_box, cbx_transform_boxes_prep(&b->p0, b->in, o, n))
/* binary32 */
REF_KERNEL(k_arvof, cbx_boxf, ref_arvo_boxf(&b->af[i], &b->inf[i], &o[i]))
CBX_KERNEL(k_cbxf, cbx_boxf, cbx_transform_boxf(&b->af[i], &b->inf[i], &o[i]))
CBX_KERNEL(k_prepf, cbx_boxf, cbx_transform_box_prepf(&b->paf[i], &b->inf[i], &o[i]))
REF_KERNEL(k_arvo1f, cbx_boxf, ref_arvo_boxf(&b->af[0], &b->inf[i], &o[i]))
CBX_KERNEL(k_cbx1f, cbx_boxf, cbx_transform_boxf(&b->af[0], &b->inf[i], &o[i]))
CBX_KERNEL(k_prep1f, cbx_boxf, cbx_transform_box_prepf(&b->p0f, &b->inf[i], &o[i]))
BATCH_KERNEL(k_batchf, cbx_boxf, cbx_transform_boxesf(&b->af[0], b->inf, o, n))
BATCH_KERNEL(k_batchpf, cbx_boxf, cbx_transform_boxes_prepf(&b->p0f, b->inf, o, n))
/* other forms */
CBX_KERNEL(k_cbxc, cbx_cbox, cbx_transform_cbox(&b->a[i], &b->cin_cbx[i], &o[i]))
REF_KERNEL(k_arvoc, cbx_cbox, ref_arvo_cbox(&b->a[i], &b->cin_rn[i], &o[i]))
CBX_KERNEL(k_sph, cbx_box, cbx_sphere_box(&b->a[i], &o[i]))
CBX_KERNEL(k_sphbox, cbx_box, cbx_transform_box(&b->a[i], &unit_box, &o[i]))
/* projective maps */
REF_KERNEL(k_proj_ref, cbx_box, ref_proj8(&b->pm[i], &b->pin[i], &o[i]))
CBX_KERNEL(k_proj, cbx_box, cbx_project_box(&b->pm[i], &b->pin[i], &o[i]))
REF_KERNEL(k_psph_ref, cbx_box, ref_psphere(&b->pm[i], b->psc + 3 * i, b->psr[i], &o[i]))
REF_KERNEL(k_psph_box, cbx_box, ref_psphere_box8(&b->pm[i], b->psc + 3 * i, b->psr[i], &o[i]))
CBX_KERNEL(k_psph, cbx_box, cbx_project_sphere(&b->pm[i], b->psc + 3 * i, b->psr[i], &o[i]))
REF_KERNEL(k_pnear_ref, cbx_box, ref_pnear(&b->pm[i], &b->pcx[i], b->pwn[i], &o[i]))
REF_KERNEL(k_pell_ref, cbx_box, ref_pell(&b->pm[i], b->psc + 3 * i, b->pes + 3 * i, (const double (*)[3])b->per[i], &o[i]))
REF_KERNEL(k_pell_obb, cbx_box, ref_pell_obb8(&b->pm[i], b->psc + 3 * i, b->pes + 3 * i, (const double (*)[3])b->per[i], &o[i]))
CBX_KERNEL(k_pell, cbx_box, cbx_project_ellipsoid(&b->pm[i], b->psc + 3 * i, b->pes + 3 * i, (const double (*)[3])b->per[i], &o[i]))
CBX_KERNEL(k_pellf, cbx_boxf, cbx_project_ellipsoidf(&b->pmf[i], b->pscf + 3 * i, b->pesf + 3 * i, (const float (*)[3])b->perf[i], &o[i]))
CBX_KERNEL(k_psphf, cbx_boxf, cbx_project_spheref(&b->pmf[i], b->pscf + 3 * i, b->psrf[i], &o[i]))
CBX_KERNEL(k_pnearf, cbx_boxf, cbx_project_box_nearf(&b->pmf[i], &b->pinf[i], b->pwnf[i], &o[i]))
CBX_KERNEL(k_pballf, cbx_boxf, cbx_project_sphere_nearf(&b->pmf[i], b->pscf + 3 * i, b->psrf[i], b->pwnf[i], &o[i]))
CBX_KERNEL(k_pnear_front, cbx_box, cbx_project_box_near(&b->pm[i], &b->pin[i], b->pwn[i], &o[i]))
CBX_KERNEL(k_pnear, cbx_box, cbx_project_box_near(&b->pm[i], &b->pcx[i], b->pwn[i], &o[i]))
CBX_KERNEL(k_pball_front, cbx_box, cbx_project_sphere_near(&b->pm[i], b->psc + 3 * i, b->psr[i], b->pwn[i], &o[i]))
REF_KERNEL(k_pball_ref, cbx_box, ref_pnear(&b->pm[i], &b->pcx[i], b->pwn[i], &o[i]))
CBX_KERNEL(k_pball, cbx_box, cbx_project_sphere_near(&b->pm[i], b->pxc + 3 * i, b->pxr[i], b->pwn[i], &o[i]))
static const double t_end[2] = { 0.0, 1.0 };
static double t_128[128];
REF_KERNEL(k_rot_end, cbx_box, ref_trs_samples(&b->rk0[i], &b->rk1[i], 0, t_end, 2, &b->rin[i], &o[i]))
REF_KERNEL(k_rot_128, cbx_box, ref_trs_samples(&b->rk0[i], &b->rk1[i], 0, t_128, 128, &b->rin[i], &o[i]))
CBX_KERNEL(k_rot4, cbx_box, cbx_motion_trs_box(&b->rk0[i], &b->rk1[i], CBX_SLERP, 0.0, 1.0, 4, &b->rin[i], &o[i]))
CBX_KERNEL(k_rot6, cbx_box, cbx_motion_trs_box(&b->rk0[i], &b->rk1[i], CBX_SLERP, 0.0, 1.0, 6, &b->rin[i], &o[i]))
CBX_KERNEL(k_rot4p, cbx_box, cbx_transform_box_pieces(b->rpc, b->nrpc, &b->rin[i], &o[i]))
/* throughput */
CBX_KERNEL(k_tp, cbx_box, cbx_transform_box(&b->ta[i], &b->tin[i], &o[i]))
REF_KERNEL(k_tp_arvo1, cbx_box, ref_arvo_box(&b->ta[0], &b->tin[i], &o[i]))
BATCH_KERNEL(k_tp_batch, cbx_box, cbx_transform_boxes(&b->ta[0], b->tin, o, n))
BATCH_KERNEL(k_tp_batchp, cbx_box, cbx_transform_boxes_prep(&b->tp0, b->tin, o, n))
BATCH_KERNEL(k_tp_batchf, cbx_boxf, cbx_transform_boxesf(&b->taf0, b->tinf, o, n))
/* the scene (every instance under its own map), and the instances of
 * class b->cur (sorted copy; out = that class's part of b->qo) */
REF_KERNEL(k_scene_arvo, cbx_box, ref_arvo_box(&b->sa[i], &b->sin[i], &o[i]))
CBX_KERNEL(k_scene_gen, cbx_box, cbx_transform_box(&b->sa[i], &b->sin[i], &o[i]))
CBX_KERNEL(k_scene_as, cbx_box, cbx_transform_box_as(&b->sa[i], b->scls[i], &b->sin[i], &o[i]))
#define QI (b->ns_off[b->cur] + i)
REF_KERNEL(k_cls_arvo, cbx_box, ref_arvo_box(&b->qa[QI], &b->qin[QI], &o[i]))
CBX_KERNEL(k_cls_gen, cbx_box, cbx_transform_box(&b->qa[QI], &b->qin[QI], &o[i]))
CBX_KERNEL(k_cls_as, cbx_box, cbx_transform_box_as(&b->qa[QI], b->qcls[QI], &b->qin[QI], &o[i]))
#undef QI

static void k_gmp(bench_ctx *b, size_t n, void *out)
{
    size_t i;
    int r;
    uint64_t acc = 0;
    (void)out;
    for (i = 0; i < n; i++)
        for (r = 0; r < 3; r++) {
            xu_row_bounds(&b->x, &b->a[i], &b->in[i], r);
            acc += (uint64_t)mpz_getlimbn(b->x.L, 0) + (uint64_t)mpz_getlimbn(b->x.H, 0);
        }
    b->gmp_acc += acc;
}
/* memcpy of the bytes of n cases: map, box in and box out (3), or the
 * two boxes only (2), into b->mdst */
static void k_memcpy3(bench_ctx *b, size_t n, void *out)
{
    unsigned char *d = (unsigned char *)out;
    size_t na = n * sizeof(cbx_affine), nb = n * sizeof(cbx_box);
    memcpy(d, b->ta, na);
    memcpy(d + na, b->tin, nb);
    memcpy(d + na + nb, b->tout, nb);
}
static void k_memcpy2(bench_ctx *b, size_t n, void *out)
{
    unsigned char *d = (unsigned char *)out;
    size_t nb = n * sizeof(cbx_box);
    memcpy(d, b->tin, nb);
    memcpy(d + nb, b->tout, nb);
}

/* ---- rows and their timing ------------------------------------------- */

typedef struct acc {
    long ends, fails, nc_ends, cancel;
    double max_u, sum_u, min_u, max_ulp, sum_ulp;
} acc;

typedef struct opt_acc { long ends, off; double max_off, sum_off; } opt_acc;

enum { SEC_MAIN, SEC_TP };
/* how a row's output is checked exactly */
enum {
    MK_NONE,
    MK_BOX, MK_BOX1,   /* binary64 boxes, own map / a[0]                */
    MK_BOXF, MK_BOXF1, /* binary32 boxes, own map / a[0]                */
    MK_CBOX,           /* cboxes, own map                               */
    MK_SPH,            /* rows 6a, 6b (measure_sphere)                  */
    MK_SCN,            /* scene outputs, own map                        */
    MK_GMP,            /* the exact reference                           */
    MK_TP, MK_TP1, MK_TPF /* throughput (verify_tp): own map, ta[0],
                             binary32 under taf0                       */
};

typedef struct row row;
struct row {
    const char *id, *name, *proven;
    int sec, grp, isbase, hidden, plot;
    int pcode;            /* 1 certbox, 0 RN baseline / memcpy, 2 exact   */
    /* timing: passes x f(n cases) into out (n elements of esz bytes) */
    kern_fn f;
    size_t n, esz;
    long passes;
    void *out;
    double unit;          /* the ratio is per case / unit (throughput:
                             bytes in + out per case)                   */
    int cur;
    const row *base;      /* the group's baseline                        */
    double ns, cpu;       /* medians, per case                           */
    double rw, rc;        /* medians of the per-round ratios to base     */
    /* checks */
    int mk;
    const row *same;      /* output must be bit-identical to this row's  */
    long diff;            /* cases that are not                          */
    long checked;         /* cases compared                              */
    int want_opt;
    acc ex;
    opt_acc opt;
    uint64_t digest;      /* of the output (0: none)                     */
    char note[600];       /* facts (the same in every build)             */
    char tnote[300];      /* timings (this build's)                      */
};

static row rows[MAXROWS];
static int nrows;

static void acc_init(acc *s)
{
    memset(s, 0, sizeof *s);
    s->max_u = -HUGE_VAL;
    s->min_u = HUGE_VAL;
    s->max_ulp = -HUGE_VAL;
}

/* A row of group grp (isbase: its baseline), timed as `passes` passes of
 * f over n cases into out (allocated here when 0); a certbox row unless
 * marked otherwise (unsound()). */
static row *add_row(int grp, int isbase, const char *id, const char *name, kern_fn f, size_t n,
                    long passes, void *out, size_t esz, int mk)
{
    row *w;
    if (nrows == MAXROWS) {
        fprintf(stderr, "bench: more than %d rows\n", MAXROWS);
        exit(2);
    }
    w = &rows[nrows++];
    memset(w, 0, sizeof *w);
    w->id = id;
    w->name = name;
    w->proven = "yes";
    w->pcode = 1;
    w->sec = SEC_MAIN;
    w->grp = grp;
    w->isbase = isbase;
    w->f = f;
    w->n = n;
    w->passes = passes;
    w->esz = esz;
    w->out = out ? out : xmalloc(n * esz);
    w->unit = 1.0;
    w->mk = mk;
    acc_init(&w->ex);
    return w;
}

static row *unsound(row *w)
{
    w->proven = "no";
    w->pcode = 0;
    return w;
}

/* A throughput row: ratio per byte (bpc bytes in + out per case). */
static row *add_tp(int grp, int isbase, const char *id, const char *name, kern_fn f, size_t n,
                   long passes, void *out, size_t esz, size_t bpc, int mk)
{
    row *w = add_row(grp, isbase, id, name, f, n, passes, out, esz, mk);
    w->sec = SEC_TP;
    w->unit = (double)bpc;
    if (mk == MK_NONE) unsound(w);
    return w;
}

static row *find_row(const char *id)
{
    int i;
    for (i = 0; i < nrows; i++)
        if (!strcmp(rows[i].id, id)) return &rows[i];
    return 0;
}

static double clock_ns(clockid_t id)
{
    struct timespec ts;
    clock_gettime(id, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}
static double now_ns(void) { return clock_ns(CLOCK_MONOTONIC); }
#ifdef CLOCK_THREAD_CPUTIME_ID
static double cpu_ns(void) { return clock_ns(CLOCK_THREAD_CPUTIME_ID); }
#else
static double cpu_ns(void) { return (double)clock() * (1e9 / CLOCKS_PER_SEC); }
#endif

static int cmp_double(const void *p, const void *q)
{
    double x = *(const double *)p, y = *(const double *)q;
    return (x > y) - (x < y);
}

static double median(const double *v, int R)
{
    double s[MAXR];
    memcpy(s, v, (size_t)R * sizeof s[0]);
    qsort(s, (size_t)R, sizeof s[0], cmp_double);
    return s[R / 2];
}

/* One run of a row: wall and CPU ns per case. */
static void run_once(bench_ctx *b, const row *w, double *wall, double *cpu)
{
    double c0, t0, t1, c1;
    long p;
    b->cur = w->cur;
    c0 = cpu_ns();
    t0 = now_ns();
    for (p = 0; p < w->passes; p++) {
        w->f(b, w->n, w->out);
        bench_escape(b);
    }
    t1 = now_ns();
    c1 = cpu_ns();
    *wall = (t1 - t0) / ((double)w->passes * (double)w->n);
    *cpu = (c1 - c0) / ((double)w->passes * (double)w->n);
    bench_sink ^= checksum(w->out, w->n * w->esz) ^ b->gmp_acc;
}

/* Time the rows of group g, interleaved: a warm-up round, then R rounds of
 * (the baseline, then every other row of the group once). */
static void time_group(bench_ctx *b, int g, int R)
{
    static double t[MAXG][MAXR], c[MAXG][MAXR];
    double q[MAXR], s[MAXR], w0, c0;
    row *m[MAXG];
    int nm = 0, i, j, r;
    for (i = 0; i < nrows; i++)
        if (rows[i].grp == g && rows[i].isbase) m[nm++] = &rows[i];
    if (nm != 1) {
        if (nm == 0) return;
        fprintf(stderr, "bench: group %d has %d baselines\n", g, nm);
        exit(2);
    }
    for (i = 0; i < nrows; i++) {
        if (rows[i].grp != g || rows[i].isbase) continue;
        if (nm == MAXG) {
            fprintf(stderr, "bench: group %d has more than %d rows\n", g, MAXG);
            exit(2);
        }
        m[nm++] = &rows[i];
    }
    for (j = 0; j < nm; j++) run_once(b, m[j], &w0, &c0);
    for (r = 0; r < R; r++)
        for (j = 0; j < nm; j++) run_once(b, m[j], &t[j][r], &c[j][r]);
    for (j = 0; j < nm; j++) {
        for (r = 0; r < R; r++) {
            q[r] = (t[j][r] / m[j]->unit) / (t[0][r] / m[0]->unit);
            s[r] = (c[j][r] / m[j]->unit) / (c[0][r] / m[0]->unit);
        }
        m[j]->base = m[0];
        m[j]->ns = median(t[j], R);
        m[j]->cpu = median(c[j], R);
        m[j]->rw = median(q, R);
        m[j]->rc = median(s, R);
    }
}

static long passes_for(long calls, size_t n)
{
    long p = n ? (long)(calls / (long)n) : 1;
    return p < 1 ? 1 : p;
}

/* ---- exact measurement ----------------------------------------------- */

static void acc_add(acc *s, double units, int fail, int nocancel, double ulps)
{
    s->ends++;
    s->fails += fail != 0;
    s->sum_u += units;
    if (units > s->max_u) s->max_u = units;
    if (units < s->min_u) s->min_u = units;
    if (nocancel) {
        s->nc_ends++;
        s->sum_ulp += ulps;
        if (ulps > s->max_ulp) s->max_ulp = ulps;
    } else {
        s->cancel++;
    }
}

/* gap (scaled by 2^XU_SHIFT) in ulps of the exact end E (scaled), in the
 * current format (xu_fmt). */
static double gap_ulps(const mpz_t gap, const mpz_t E)
{
    long ee, eg, ue;
    double fg;
    if (mpz_sgn(gap) == 0) return 0.0;
    if (mpz_sgn(E) == 0) {
        ue = -xu_fmt->emin;
    } else {
        (void)mpz_get_d_2exp(&ee, E); /* |E| in [2^(ee-1), 2^ee) */
        ue = ee - XU_SHIFT - xu_fmt->p;
        if (ue < -xu_fmt->emin) ue = -xu_fmt->emin;
    }
    fg = mpz_get_d_2exp(&eg, gap);
    return ldexp(fg, (int)(eg - XU_SHIFT - ue));
}

/* One end: gap already in e->gap, E the exact end, S the scale. */
static void record_end(xu_exact *x, ex_scratch *e, acc *s, const mpz_t E, const mpz_t S)
{
    double units = xu_units(x, e->gap, S);
    int nocancel;
    mpz_abs(e->t, E);
    mpz_mul_2exp(e->t, e->t, 2);
    nocancel = mpz_cmp(e->t, S) >= 0;
    acc_add(s, units, mpz_sgn(e->gap) < 0, nocancel, nocancel ? gap_ulps(e->gap, E) : 0.0);
}

/* A box output [lo, hi] on the axis of the last xu_row_bounds. */
static void record_box(xu_exact *x, ex_scratch *e, acc *s, double lo, double hi)
{
    xu_scaled_d(x, e->v, lo);
    mpz_sub(e->gap, x->L, e->v);
    record_end(x, e, s, x->L, x->S);
    xu_scaled_d(x, e->v, hi);
    mpz_sub(e->gap, e->v, x->H);
    record_end(x, e, s, x->H, x->S);
}

/* Distance, in doubles, of a finite end d from the tightest double: RD(E)
 * for a lower end, RU(E) for an upper one (E scaled by 2^XU_SHIFT), by
 * MPFR in binary64 (subnormals included); 0 = the tightest double. */
static double tightest_d(const mpz_t E, int up)
{
    mpfr_exp_t emin = mpfr_get_emin(), emax = mpfr_get_emax();
    mpfr_rnd_t rnd = up ? MPFR_RNDU : MPFR_RNDD;
    mpfr_t r;
    double d;
    int inex;
    mpfr_init2(r, 53);
    mpfr_set_emin(-1073);
    mpfr_set_emax(1024);
    inex = mpfr_set_z_2exp(r, E, -(mpfr_exp_t)XU_SHIFT, rnd);
    inex = mpfr_subnormalize(r, inex, rnd);
    (void)inex;
    d = mpfr_get_d(r, rnd);
    mpfr_set_emin(emin);
    mpfr_set_emax(emax);
    mpfr_clear(r);
    return d;
}

static int64_t ord_d(double d)
{
    int64_t w;
    memcpy(&w, &d, sizeof w);
    return w < 0 ? -(w & INT64_MAX) : w;
}

/* How far lo and hi of a box output are from RD(L) and RU(H) (the last
 * xu_row_bounds), in doubles. */
static void record_opt(xu_exact *x, opt_acc *o, double lo, double hi)
{
    int e;
    for (e = 0; e < 2; e++) {
        double d = e ? hi : lo, t = tightest_d(e ? x->H : x->L, e);
        int64_t k = ord_d(d) - ord_d(t);
        double off = (double)(k < 0 ? -k : k);
        o->ends++;
        o->sum_off += off;
        if (off > 0) o->off++;
        if (off > o->max_off) o->max_off = off;
    }
}

/* A center/half output: the real box [c - h, c + h], exactly. */
static void record_cbox(xu_exact *x, ex_scratch *e, acc *s, double c, double h)
{
    xu_scaled_d(x, e->v, c);
    xu_scaled_d(x, e->w, h);
    mpz_sub(e->gap, e->v, e->w);          /* c - h */
    mpz_sub(e->gap, x->L, e->gap);        /* L - (c - h) */
    record_end(x, e, s, x->L, x->S);
    mpz_add(e->gap, e->v, e->w);          /* c + h */
    mpz_sub(e->gap, e->gap, x->H);
    record_end(x, e, s, x->H, x->S);
}

/* The 3 axes of the box output o of map a and box in (opt: also the
 * distance of each finite end from the tightest double). */
static void measure_case(bench_ctx *b, const cbx_affine *a, const cbx_box *in, const cbx_box *o,
                         acc *s, opt_acc *opt)
{
    int r;
    for (r = 0; r < 3; r++) {
        xu_row_bounds(&b->x, a, in, r);
        record_box(&b->x, &b->e, s, o->lo[r], o->hi[r]);
        if (opt && isfinite(o->lo[r]) && isfinite(o->hi[r]))
            record_opt(&b->x, opt, o->lo[r], o->hi[r]);
    }
}

/* The first m outputs o[k] of boxes in[k] under maps[k] (one_map:
 * maps[0] for every box), binary64 or binary32 (units of that format). */
static void measure_boxes(bench_ctx *b, const cbx_affine *maps, int one_map, const cbx_box *in,
                          const cbx_box *o, size_t m, acc *s, opt_acc *opt)
{
    size_t k;
    for (k = 0; k < m; k++) measure_case(b, &maps[one_map ? 0 : k], &in[k], &o[k], s, opt);
}
static void measure_boxesf(bench_ctx *b, const cbx_affinef *maps, int one_map, const cbx_boxf *in,
                           const cbx_boxf *o, size_t m, acc *s)
{
    size_t k;
    cbx_affine a;
    cbx_box bi, bo;
    xu_set_format(&xu_binary32);
    for (k = 0; k < m; k++) {
        affine_from_f(&maps[one_map ? 0 : k], &a);
        box_from_f(&in[k], &bi);
        box_from_f(&o[k], &bo);
        measure_case(b, &a, &bi, &bo, s, 0);
    }
    xu_set_format(&xu_binary64);
}

typedef struct sph_scratch { mpz_t s, m; mpfr_t R, T, E, D, G, U; } sph_scratch;

/* One end of a sphere output against t -+ sqrt(s) (s exact, scaled by
 * 2^(2*1074)); upper = 0: lower end. */
static void record_sph_end(xu_exact *x, sph_scratch *k, acc *s, double t, double v, int upper)
{
    int ok;
    double units, ulps = 0.0;
    int nocancel;
    if (upper) {
        mpfr_add(k->E, k->T, k->R, MPFR_RNDN);
        mpfr_set_d(k->G, v, MPFR_RNDN);
        mpfr_sub(k->G, k->G, k->E, MPFR_RNDN);       /* hi - E */
        ok = xu_sqrt_hi_ok(x, k->s, 1074, t, v);
    } else {
        mpfr_sub(k->E, k->T, k->R, MPFR_RNDN);
        mpfr_set_d(k->G, v, MPFR_RNDN);
        mpfr_sub(k->G, k->E, k->G, MPFR_RNDN);       /* E - lo */
        ok = xu_sqrt_lo_ok(x, k->s, 1074, t, v);
    }
    mpfr_div(k->U, k->G, k->D, MPFR_RNDN);
    units = mpfr_get_d(k->U, MPFR_RNDN);
    /* |E| * 4 >= |t| + sqrt(s) (D = u (|t| + sqrt s) + eta, so compare
     * with the scale directly) */
    mpfr_abs(k->U, k->T, MPFR_RNDN);
    mpfr_add(k->U, k->U, k->R, MPFR_RNDN);
    mpfr_div_2ui(k->U, k->U, 2, MPFR_RNDN);
    nocancel = mpfr_cmpabs(k->E, k->U) >= 0;
    if (nocancel && !mpfr_zero_p(k->G)) {
        long ue = mpfr_zero_p(k->E) ? -1074 : (long)mpfr_get_exp(k->E) - 53;
        if (ue < -1074) ue = -1074;
        mpfr_div_2si(k->U, k->G, ue, MPFR_RNDN);
        ulps = mpfr_get_d(k->U, MPFR_RNDN);
    }
    acc_add(s, units, !ok, nocancel, ulps);
}

/* Rows 6a (o_sph) and 6b (o_sphbox) against the exact sphere bound. */
static void measure_sphere(bench_ctx *b, size_t ne, const cbx_box *o_sph, const cbx_box *o_sphbox,
                           acc *sph, acc *sphbox, double *volratio)
{
    sph_scratch k;
    size_t i;
    int r, j;
    double vsum = 0.0;
    mpz_inits(k.s, k.m, (mpz_ptr)0);
    mpfr_inits2(SPH_PREC, k.R, k.T, k.E, k.D, k.G, k.U, (mpfr_ptr)0);
    for (i = 0; i < ne; i++) {
        const cbx_affine *a = &b->a[i];
        double v = 1.0;
        for (r = 0; r < 3; r++) {
            double t = a->m[r][3];
            mpz_set_ui(k.s, 0);
            for (j = 0; j < 3; j++) {
                xu_scaled_mul(&b->x, k.m, a->m[r][j], a->m[r][j]);
                mpz_add(k.s, k.s, k.m);
            }
            mpfr_set_z(k.R, k.s, MPFR_RNDN);
            mpfr_div_2ui(k.R, k.R, 2 * 1074, MPFR_RNDN);
            mpfr_sqrt(k.R, k.R, MPFR_RNDN);
            mpfr_set_d(k.T, t, MPFR_RNDN);
            /* D = u (|t| + R) + eta */
            mpfr_abs(k.D, k.T, MPFR_RNDN);
            mpfr_add(k.D, k.D, k.R, MPFR_RNDN);
            mpfr_div_2ui(k.D, k.D, 53, MPFR_RNDN);
            mpfr_set_ui_2exp(k.U, 1, -1074, MPFR_RNDN);
            mpfr_add(k.D, k.D, k.U, MPFR_RNDN);
            record_sph_end(&b->x, &k, sph, t, o_sph[i].lo[r], 0);
            record_sph_end(&b->x, &k, sph, t, o_sph[i].hi[r], 1);
            record_sph_end(&b->x, &k, sphbox, t, o_sphbox[i].lo[r], 0);
            record_sph_end(&b->x, &k, sphbox, t, o_sphbox[i].hi[r], 1);
            v *= (o_sphbox[i].hi[r] - o_sphbox[i].lo[r]) / (o_sph[i].hi[r] - o_sph[i].lo[r]);
        }
        vsum += v;
    }
    *volratio = ne ? vsum / (double)ne : 0.0;
    mpz_clears(k.s, k.m, (mpz_ptr)0);
    mpfr_clears(k.R, k.T, k.E, k.D, k.G, k.U, (mpfr_ptr)0);
}

/* A throughput row's output, untimed: one more run of its kernel, every
 * case compared bit for bit with a single cbx_transform_box(f) call on the
 * same map and box, and the first ne cases measured exactly. */
static void verify_tp(bench_ctx *b, row *w, size_t ne)
{
    size_t k, m = ne < w->n ? ne : w->n;
    w->f(b, w->n, w->out);
    w->digest = checksum(w->out, w->n * w->esz);
    w->checked = (long)w->n;
    if (w->mk == MK_TPF) {
        const cbx_boxf *o = (const cbx_boxf *)w->out;
        for (k = 0; k < w->n; k++) {
            cbx_boxf r;
            b->bad += cbx_transform_boxf(&b->taf0, &b->tinf[k], &r) != CBX_OK;
            w->diff += memcmp(&r, &o[k], sizeof r) != 0;
        }
        measure_boxesf(b, &b->taf0, 1, b->tinf, o, m, &w->ex);
    } else {
        const cbx_box *o = (const cbx_box *)w->out;
        int one = w->mk == MK_TP1;
        for (k = 0; k < w->n; k++) {
            cbx_box r;
            b->bad += cbx_transform_box(&b->ta[one ? 0 : k], &b->tin[k], &r) != CBX_OK;
            w->diff += memcmp(&r, &o[k], sizeof r) != 0;
        }
        measure_boxes(b, b->ta, one, b->tin, o, m, &w->ex, 0);
    }
}

/* The exact checks of one row on its first ne cases. */
static void measure_row(bench_ctx *b, row *w, size_t ne)
{
    size_t k, m = ne < w->n ? ne : w->n;
    opt_acc *opt = w->want_opt ? &w->opt : 0;
    switch (w->mk) {
    case MK_BOX: case MK_BOX1:
        measure_boxes(b, b->a, w->mk == MK_BOX1, b->in, (const cbx_box *)w->out, m, &w->ex, opt);
        break;
    case MK_BOXF: case MK_BOXF1:
        measure_boxesf(b, b->af, w->mk == MK_BOXF1, b->inf, (const cbx_boxf *)w->out, m, &w->ex);
        break;
    case MK_SCN:
        measure_boxes(b, b->sa, 0, b->sin, (const cbx_box *)w->out, m, &w->ex, opt);
        break;
    case MK_CBOX:
        for (k = 0; k < m; k++) {
            const cbx_cbox *o = (const cbx_cbox *)w->out + k;
            int r;
            for (r = 0; r < 3; r++) {
                xu_row_bounds(&b->x, &b->a[k], &b->in[k], r);
                record_cbox(&b->x, &b->e, &w->ex, o->c[r], o->h[r]);
            }
        }
        break;
    case MK_TP: case MK_TP1: case MK_TPF:
        verify_tp(b, w, ne);
        break;
    default:
        break;
    }
}

/* The scene's extra checks: every finite Sc end no looser than S's and
 * infinite ends identical (all NS), the mpq corners of Sc (first ng), and
 * the excess of both per class (first ne). */
typedef struct scene_check {
    long looser, tighter, fin, infdiff, corner_fail, corner_checked, mismatch;
    acc pg[5], pc[5];   /* general / class kernel, per class */
} scene_check;

static void check_scene(bench_ctx *b, const cbx_box *so_g, const cbx_box *so_c, size_t ne,
                        size_t ng, scene_check *sc)
{
    size_t k, m = ne < b->ns ? ne : b->ns;
    int c, j, r;
    for (c = 0; c < 5; c++) {
        acc_init(&sc->pg[c]);
        acc_init(&sc->pc[c]);
    }
    for (k = 0; k < b->ns; k++)
        for (j = 0; j < 6; j++) {
            double eg = j < 3 ? so_g[k].lo[j] : so_g[k].hi[j - 3];
            double ec = j < 3 ? so_c[k].lo[j] : so_c[k].hi[j - 3];
            if (!isfinite(eg) || !isfinite(ec)) {
                sc->infdiff += memcmp(&eg, &ec, sizeof eg) != 0;
            } else {
                sc->fin++;
                if (j < 3 ? ec < eg : ec > eg) sc->looser++;
                else if (ec != eg) sc->tighter++;
            }
        }
    for (k = 0; k < m; k++) {
        c = (int)b->scls[k];
        measure_case(b, &b->sa[k], &b->sin[k], &so_g[k], &sc->pg[c], 0);
        measure_case(b, &b->sa[k], &b->sin[k], &so_c[k], &sc->pc[c], 0);
        if (k < ng)
            for (r = 0; r < 3; r++) {
                sc->corner_checked++;
                sc->corner_fail += xu_corner_failures(&b->x, &b->sa[k], &b->sin[k], r,
                                                      so_c[k].lo[r], so_c[k].hi[r]) != 0;
            }
    }
}

/* ---- the rows -------------------------------------------------------- */

typedef struct sizes {
    size_t n, ne, ng, nc, nb, nsc;
    long calls;
    int R;
    unsigned long seed;
} sizes;

/* the timing groups: a baseline and the rows timed against it */
enum { G_BOX, G_ONE, G_F, G_F1, G_P, G_R, G_TC3, G_TB3, G_TC2, G_TB2, G_S, G_SC, G_CLS, NGRP = G_CLS + 5 };

static const char *const cls_row_name[5] = {
    "scene, GENERAL instances: `cbx_transform_box_as`",
    "scene, PERMUTE instances: `cbx_transform_box_as`",
    "scene, SCALE instances: `cbx_transform_box_as`",
    "scene, TRANSLATE instances: `cbx_transform_box_as`",
    "scene, IDENTITY instances: `cbx_transform_box_as`" };
static const char *const cls_arvo_id[5] = { "S-GE-A", "S-PE-A", "S-SC-A", "S-TR-A", "S-ID-A" };
static const char *const cls_gen_id[5] = { "S-GE-g", "S-PE-g", "S-SC-g", "S-TR-g", "S-ID-g" };

static row *hide(row *w)
{
    w->hidden = 1;
    return w;
}

static void define_rows(bench_ctx *b, const sizes *z)
{
    size_t n = z->n, bsz = sizeof(cbx_box), fsz = sizeof(cbx_boxf), csz = sizeof(cbx_cbox);
    long P = passes_for(z->calls, n);
    row *r3, *r3a, *r3f, *r3af, *w;
    int c;

    /* each box under its own map, against row 2 */
    unsound(add_row(G_BOX, 0, "1", "naive 8 corners, RN (pbrt, Embree)", k_naive, n, P, 0, bsz, MK_BOX));
    unsound(add_row(G_BOX, 1, "2", "Arvo interval, RN (cglm, Godot), own map per box", k_arvo, n, P, 0,
                    bsz, MK_BOX));
    r3 = add_row(G_BOX, 0, "3", "certbox `cbx_transform_box`, own map per box", k_cbx, n, P, 0, bsz,
                 MK_BOX);
    r3->want_opt = 1;
    add_row(G_BOX, 0, "3p", "certbox `cbx_transform_box_prep`, own prepared map per box", k_prep, n,
            P, 0, bsz, MK_BOX)->same = r3;
    w = add_row(G_BOX, 0, "3t", "certbox tight `cbx_transform_box_tight`, own map per box", k_tight,
                n, P, 0, bsz, MK_BOX);
    w->want_opt = 1;
    w->proven = "yes (EFTs trusted)";
    add_row(G_BOX, 0, "3i", "certbox `cbx_transform_box_imat`, own map per box as a point interval matrix",
            k_imat, n, P, 0, bsz, MK_BOX);
    /* one map for every box, against row 2a */
    unsound(add_row(G_ONE, 1, "2a", "Arvo interval, RN, one map for every box", k_arvo1, n, P, 0, bsz,
                    MK_BOX1));
    r3a = add_row(G_ONE, 0, "3a", "certbox `cbx_transform_box`, one map for every box", k_cbx1, n, P,
                  0, bsz, MK_BOX1);
    add_row(G_ONE, 0, "3ap", "certbox `cbx_transform_box_prep`, one prepared map", k_prep1, n, P, 0,
            bsz, MK_BOX1)->same = r3a;
    add_row(G_ONE, 0, "3b", "certbox batch `cbx_transform_boxes`, one map", k_batch, n, P, 0, bsz,
            MK_BOX1)->same = r3a;
    add_row(G_ONE, 0, "3bp", "certbox batch `cbx_transform_boxes_prep`, one prepared map", k_batchp,
            n, P, 0, bsz, MK_BOX1)->same = r3a;
    /* binary32, against rows 2f and 2af */
    unsound(add_row(G_F, 1, "2f", "binary32 Arvo interval, RN (`ref_arvo_boxf`), own map per box",
                    k_arvof, n, P, 0, fsz, MK_BOXF));
    r3f = add_row(G_F, 0, "3f", "binary32 certbox `cbx_transform_boxf`, own map per box", k_cbxf, n, P,
                  0, fsz, MK_BOXF);
    add_row(G_F, 0, "3fp", "binary32 certbox `cbx_transform_box_prepf`, own prepared map per box",
            k_prepf, n, P, 0, fsz, MK_BOXF)->same = r3f;
    unsound(add_row(G_F1, 1, "2af", "binary32 Arvo interval, RN, one map for every box", k_arvo1f, n,
                    P, 0, fsz, MK_BOXF1));
    r3af = add_row(G_F1, 0, "3af", "binary32 certbox `cbx_transform_boxf`, one map for every box",
                   k_cbx1f, n, P, 0, fsz, MK_BOXF1);
    add_row(G_F1, 0, "3afp", "binary32 certbox `cbx_transform_box_prepf`, one prepared map", k_prep1f,
            n, P, 0, fsz, MK_BOXF1)->same = r3af;
    add_row(G_F1, 0, "3bf", "binary32 certbox batch `cbx_transform_boxesf`, one map", k_batchf, n, P,
            0, fsz, MK_BOXF1)->same = r3af;
    add_row(G_F1, 0, "3bfp", "binary32 certbox batch `cbx_transform_boxes_prepf`, one prepared map",
            k_batchpf, n, P, 0, fsz, MK_BOXF1)->same = r3af;
    /* the other forms, against row 2 */
    add_row(G_BOX, 0, "4", "certbox `cbx_transform_cbox`", k_cbxc, n, P, 0, csz, MK_CBOX);
    unsound(add_row(G_BOX, 0, "5", "Arvo center/half, RN", k_arvoc, n, P, 0, csz, MK_CBOX));
    add_row(G_BOX, 0, "6a", "sphere: certbox `cbx_sphere_box`", k_sph, n, P, 0, bsz, MK_SPH);
    add_row(G_BOX, 0, "6b", "sphere: Arvo on [-1,1]^3 (`cbx_transform_box`)", k_sphbox, n, P, 0, bsz,
            MK_SPH);
    if (z->ng > 0) {
        w = add_row(G_BOX, 0, "7", "GMP exact (`xu_row_bounds` x 3)", k_gmp, z->ng, 1, 0, 0, MK_GMP);
        w->proven = "n/a (exact)";
        w->pcode = 2;
    }

    /* projective maps (a camera), against the 8 corners divided by w */
    unsound(add_row(G_P, 1, "P-R", "projective: 8 corners divided by w, RN (pbrt, three.js)", k_proj_ref,
                    n, P, 0, bsz, MK_NONE));
    add_row(G_P, 0, "P", "projective: certbox `cbx_project_box`", k_proj, n, P, 0, bsz, MK_NONE);
    unsound(add_row(G_P, 0, "PS-R", "projected ball: closed form (Mara and McGuire), RN", k_psph_ref,
                    n, P, 0, bsz, MK_NONE));
    unsound(add_row(G_P, 0, "PS-8", "projected ball: its box's 8 corners divided by w, RN (looser)", k_psph_box,
                    n, P, 0, bsz, MK_NONE));
    add_row(G_P, 0, "PS", "projected ball: certbox `cbx_project_sphere` (certified closed form)", k_psph,
            n, P, 0, bsz, MK_NONE);
    unsound(add_row(G_P, 0, "PE-R", "projected ellipsoid: the ball's closed form on the rows M^T a, RN", k_pell_ref,
                    n, P, 0, bsz, MK_NONE));
    unsound(add_row(G_P, 0, "PE-8", "projected ellipsoid: its oriented box's 8 corners divided by w, RN (looser)",
                    k_pell_obb, n, P, 0, bsz, MK_NONE));
    add_row(G_P, 0, "PE", "projected ellipsoid: certbox `cbx_project_ellipsoid` (certified closed form)", k_pell,
            n, P, 0, bsz, MK_NONE);
    add_row(G_P, 0, "PN", "box in front, clipped at the near plane: certbox `cbx_project_box_near`",
            k_pnear_front, n, P, 0, bsz, MK_NONE);
    unsound(add_row(G_P, 0, "PN-XR", "box across the near plane: its clipped vertices divided by w, RN",
                    k_pnear_ref, n, P, 0, bsz, MK_NONE));
    add_row(G_P, 0, "PN-X", "box across the near plane: certbox `cbx_project_box_near`", k_pnear,
            n, P, 0, bsz, MK_NONE);
    add_row(G_P, 0, "PB", "ball in front, clipped at the near plane: certbox `cbx_project_sphere_near`",
            k_pball_front, n, P, 0, bsz, MK_NONE);
    add_row(G_P, 0, "PSf", "projected ball, binary32: certbox `cbx_project_spheref` (the binary64 bound, rounded out)",
            k_psphf, n, P, 0, fsz, MK_NONE);
    add_row(G_P, 0, "PEf", "projected ellipsoid, binary32: certbox `cbx_project_ellipsoidf`", k_pellf,
            n, P, 0, fsz, MK_NONE);
    add_row(G_P, 0, "PNf", "box in front, clipped, binary32: certbox `cbx_project_box_nearf`", k_pnearf,
            n, P, 0, fsz, MK_NONE);
    add_row(G_P, 0, "PBf", "ball in front, clipped, binary32: certbox `cbx_project_sphere_nearf`", k_pballf,
            n, P, 0, fsz, MK_NONE);
    unsound(add_row(G_P, 0, "PB-XR", "ball across the near plane: its cube's clipped vertices divided by w, RN (looser)",
                    k_pball_ref, n, P, 0, bsz, MK_NONE));
    add_row(G_P, 0, "PB-X", "ball across the near plane: certbox `cbx_project_sphere_near`", k_pball,
            n, P, 0, bsz, MK_NONE);

    /* motion with rotation (keyframes 0 to 90 degrees apart), against the
     * union of the endpoint boxes (pbrt-style) */
    unsound(add_row(G_R, 1, "R-E", "rotation motion: union of the 8-corner boxes at s = 0 and 1, RN (pbrt-style)",
                    k_rot_end, n, P, 0, bsz, MK_NONE));
    unsound(add_row(G_R, 0, "R-C", "rotation motion: 8 corners at 128 samples, RN (Cycles)", k_rot_128, n, P, 0,
                    bsz, MK_NONE));
    add_row(G_R, 0, "R4", "rotation motion: certbox `cbx_motion_trs_box`, slerp, 16 cells", k_rot4, n, P, 0, bsz,
            MK_NONE)->proven = "no: tested (`test_trs`)";
    add_row(G_R, 0, "R6", "rotation motion: certbox `cbx_motion_trs_box`, slerp, 64 cells", k_rot6, n, P, 0, bsz,
            MK_NONE)->proven = "no: tested (`test_trs`)";
    add_row(G_R, 0, "R4p", "rotation motion: `cbx_transform_box_pieces`, 16 cells prepared once (one motion)",
            k_rot4p, n, P, 0, bsz, MK_NONE)->proven = "no: tested (`test_trs`)";

    /* throughput, against memcpy of the same bytes */
    if (z->nb > 0) {
        size_t nc = z->nc, nb = z->nb, pb3 = sizeof(cbx_affine) + 2 * bsz, pb2 = 2 * bsz;
        long Pc = passes_for(z->calls, nc), Pb = passes_for(z->calls, nb);
        add_tp(G_TC3, 1, "M1", "memcpy, in cache", k_memcpy3, nc, Pc, b->mdst, pb3, pb3, MK_NONE);
        add_tp(G_TC3, 0, "T1", "`cbx_transform_box`, own map per case, in cache", k_tp, nc, Pc,
               b->tout, bsz, pb3, MK_TP);
        add_tp(G_TB3, 1, "M2", "memcpy, large array", k_memcpy3, nb, Pb, b->mdst, pb3, pb3, MK_NONE);
        add_tp(G_TB3, 0, "T2", "`cbx_transform_box`, own map per case, large array", k_tp, nb, Pb,
               b->tout, bsz, pb3, MK_TP);
        add_tp(G_TC2, 1, "M1b", "memcpy, boxes only, in cache", k_memcpy2, nc, Pc, b->mdst, pb2, pb2,
               MK_NONE);
        add_tp(G_TC2, 0, "T1a", "Arvo interval, RN, one map, in cache", k_tp_arvo1, nc, Pc, b->tout,
               bsz, pb2, MK_NONE);
        add_tp(G_TC2, 0, "T1b", "batch `cbx_transform_boxes`, one map, in cache", k_tp_batch, nc, Pc,
               b->tout, bsz, pb2, MK_TP1);
        add_tp(G_TC2, 0, "T1p", "batch `cbx_transform_boxes_prep`, one map, in cache", k_tp_batchp,
               nc, Pc, b->tout, bsz, pb2, MK_TP1);
        add_tp(G_TC2, 0, "T1f", "binary32 batch `cbx_transform_boxesf`, one map, in cache",
               k_tp_batchf, 2 * nc, Pc, b->toutf, fsz, 2 * fsz, MK_TPF);
        add_tp(G_TB2, 1, "M2b", "memcpy, boxes only, large array", k_memcpy2, nb, Pb, b->mdst, pb2,
               pb2, MK_NONE);
        add_tp(G_TB2, 0, "T2a", "Arvo interval, RN, one map, large array", k_tp_arvo1, nb, Pb,
               b->tout, bsz, pb2, MK_NONE);
        add_tp(G_TB2, 0, "T2b", "batch `cbx_transform_boxes`, one map, large array", k_tp_batch, nb,
               Pb, b->tout, bsz, pb2, MK_TP1);
        add_tp(G_TB2, 0, "T2p", "batch `cbx_transform_boxes_prep`, one map, large array",
               k_tp_batchp, nb, Pb, b->tout, bsz, pb2, MK_TP1);
        add_tp(G_TB2, 0, "T2f", "binary32 batch `cbx_transform_boxesf`, one map, large array",
               k_tp_batchf, 2 * nb, Pb, b->toutf, fsz, 2 * fsz, MK_TPF);
        for (c = 0; c < nrows; c++)
            if (rows[c].f == k_memcpy2 || rows[c].f == k_memcpy3) rows[c].proven = "-";
    }

    /* the scene, against Arvo on the same instances */
    if (b->ns > 0) {
        size_t ns = b->ns, nsc = z->nsc;
        long Ps = passes_for(z->calls, ns), Psc = passes_for(z->calls, nsc);
        unsound(add_row(G_S, 1, "S-A", "scene: Arvo interval, RN, on every instance", k_scene_arvo, ns,
                        Ps, 0, bsz, MK_SCN));
        add_row(G_S, 0, "S", "scene: `cbx_transform_box` on every instance (general kernel)",
                k_scene_gen, ns, Ps, 0, bsz, MK_SCN);
        add_row(G_S, 0, "Sc", "scene: `cbx_transform_box_as`, class stored at build time", k_scene_as,
                ns, Ps, 0, bsz, MK_SCN);
        /* the first nsc instances, in cache (notes of S and Sc) */
        hide(unsound(add_row(G_SC, 1, "S-A'", "in cache: Arvo", k_scene_arvo, nsc, Psc, 0, bsz,
                             MK_NONE)));
        hide(add_row(G_SC, 0, "S'", "in cache: S", k_scene_gen, nsc, Psc, 0, bsz, MK_NONE));
        hide(add_row(G_SC, 0, "Sc'", "in cache: Sc", k_scene_as, nsc, Psc, 0, bsz, MK_NONE));
        for (c = 4; c >= 0; c--) {
            size_t m = b->ns_cnt[c];
            long Pm = passes_for(z->calls, m);
            cbx_box *o = b->qo + b->ns_off[c];
            if (m == 0) continue;
            hide(unsound(add_row(G_CLS + c, 1, cls_arvo_id[c], "Arvo, RN, on them",
                                 k_cls_arvo, m, Pm, o, bsz, MK_NONE)))->cur = c;
            hide(add_row(G_CLS + c, 0, cls_gen_id[c], "`cbx_transform_box` on them", k_cls_gen, m, Pm, o,
                         bsz, MK_NONE))->cur = c;
            add_row(G_CLS + c, 0, scls_id[c], cls_row_name[c], k_cls_as, m, Pm, o, bsz, MK_NONE)->cur = c;
        }
    }
}

/* ---- notes ----------------------------------------------------------- */

static void note_add(char *s, size_t sz, const char *fmt, ...)
{
    va_list ap;
    size_t l = strlen(s);
    if (l && l + 2 < sz) {
        strcpy(s + l, "; ");
        l += 2;
    }
    va_start(ap, fmt);
    if (l < sz) vsnprintf(s + l, sz - l, fmt, ap);
    va_end(ap);
}
#define NOTE(w, ...) note_add((w)->note, sizeof (w)->note, __VA_ARGS__)
#define TNOTE(w, ...) note_add((w)->tnote, sizeof (w)->tnote, __VA_ARGS__)

static void fmt_num(char *s, size_t sz, double v)
{
    if (v != v) snprintf(s, sz, "-");
    else if (v == 0.0) snprintf(s, sz, "0");
    else if (fabs(v) >= 1e5 || fabs(v) < 1e-2) snprintf(s, sz, "%.3g", v);
    else snprintf(s, sz, "%.2f", v);
}

static void set_notes(const bench_ctx *b, const sizes *z, const scene_check *sc, double volratio)
{
    row *w, *v;
    int c, i;
    if ((w = find_row("3")))
        NOTE(w, "%ld of %ld ends not the tightest double: max %.0f, mean %.2f doubles away",
             w->opt.off, w->opt.ends, w->opt.max_off,
             w->opt.ends ? w->opt.sum_off / (double)w->opt.ends : 0.0);
    if ((w = find_row("3p"))) NOTE(w, "maps prepared by `cbx_prepare` (untimed)");
    if ((w = find_row("3t")))
        NOTE(w, "%s%ld of %ld ends not the tightest double (RD/RU of the exact end)%s: max %.0f, "
                "mean %.2f ulps beyond it", w->opt.off ? "**" : "", w->opt.off, w->opt.ends,
             w->opt.off ? "**" : "", w->opt.max_off,
             w->opt.ends ? w->opt.sum_off / (double)w->opt.ends : 0.0);
    if ((w = find_row("2a"))) NOTE(w, "`ref_arvo_box` with the first case's map for every box");
    if ((w = find_row("3ap"))) NOTE(w, "that map prepared once by `cbx_prepare` (untimed)");
    if ((w = find_row("2f")))
        NOTE(w, "the %lu cases rounded to binary32 (untimed); binary32 rows: units of u S + eta "
                "with u = 2^-24, eta = 2^-149, ulps of binary32", (unsigned long)z->n);
    if ((w = find_row("3fp"))) NOTE(w, "maps prepared by `cbx_preparef` (untimed)");
    if ((w = find_row("3afp"))) NOTE(w, "that map prepared once by `cbx_preparef` (untimed)");
    for (i = 0; i < nrows; i++) {
        w = &rows[i];
        if (w->f == k_batch || w->f == k_batchp || w->f == k_batchf || w->f == k_batchpf)
            NOTE(w, "one call over the %lu boxes", (unsigned long)w->n);
    }
    if ((w = find_row("4"))) {
        NOTE(w, "input from `cbx_box_to_cbox` (untimed); excess against the original box, so it "
                "includes the conversion's widening");
        if ((v = find_row("5"))) TNOTE(w, "%.2fx row 5's time", w->ns / v->ns);
    }
    if ((w = find_row("5"))) NOTE(w, "input (lo+hi)/2, (hi-lo)/2 in RN (untimed)");
    if ((w = find_row("6a")))
        NOTE(w, "exact dual-quadric bound; units u(\\|t\\|+sqrt s)+eta");
    if ((w = find_row("6b")))
        NOTE(w, "vs the exact sphere bound; mean volume ratio to 6a: %.3f", volratio);
    if ((w = find_row("7")))
        NOTE(w, "first %lu cases; the reference", (unsigned long)w->n);
    for (i = 0; i < nrows; i++) {
        w = &rows[i];
        if (w->sec != SEC_TP) continue;
        if (w->f == k_memcpy3) NOTE(w, "memcpy of the bytes of map + box in + box out per case");
        if (w->f == k_memcpy2) NOTE(w, "memcpy of the bytes of box in + box out per case");
        if (w->f == k_tp_batchf)
            NOTE(w, "2 x %lu binary32 boxes: the bytes of the binary64 rows", (unsigned long)(w->n / 2));
        if (w->grp == G_TB3 || w->grp == G_TB2)
            NOTE(w, "out of cache when above the L3 size in the header");
    }
    if (b->ns > 0) {
        row *s = find_row("S"), *sc_ = find_row("Sc"), *sa1 = find_row("S-A'");
        row *s1 = find_row("S'"), *sc1 = find_row("Sc'");
        char mix[160];
        size_t l = 0;
        mix[0] = 0;
        for (c = 4; c >= 0; c--) {
            snprintf(mix + l, sizeof mix - l, "%s%s %.1f%%", c == 4 ? "" : ", ", scls_name[c],
                     100.0 * (double)b->ns_cnt[c] / (double)b->ns);
            l = strlen(mix);
        }
        NOTE(s, "%lu instances, own map and box each, random order: %s", (unsigned long)b->ns, mix);
        TNOTE(s, "in cache (first %lu): %.2f ns/instance, Arvo %.2f", (unsigned long)s1->n, s1->ns,
              sa1->ns);
        NOTE(sc_, "%s%ld of %ld finite ends looser than S%s, %ld tighter, %ld infinite ends differ; "
                  "mpq corners: %ld of %ld axes fail; %ld classes differ from the one meant",
             sc->looser ? "**" : "", sc->looser, sc->fin, sc->looser ? "**" : "", sc->tighter,
             sc->infdiff, sc->corner_fail, sc->corner_checked, sc->mismatch);
        TNOTE(sc_, "**speed-up S/Sc %.2fx** (CPU %.2fx); in cache, repeated passes over %lu "
                   "instances: %.2f ns/instance, %.2fx", s->ns / sc_->ns, s->cpu / sc_->cpu,
              (unsigned long)sc1->n, sc1->ns, s1->ns / sc1->ns);
        for (c = 4; c >= 0; c--) {
            row *g = find_row(cls_gen_id[c]);
            if (!(w = find_row(scls_id[c]))) continue;
            w->ex = sc->pc[c];
            NOTE(w, "%lu instances (contiguous); the general kernel's excess there: max %.3g, "
                    "mean %.3g", (unsigned long)w->n, sc->pg[c].ends ? sc->pg[c].max_u : 0.0,
                 sc->pg[c].ends ? sc->pg[c].sum_u / (double)sc->pg[c].ends : 0.0);
            TNOTE(w, "`cbx_transform_box` on them: %.2f ns/instance (CPU %.2f), **speed-up %.2fx**",
                  g->ns, g->cpu, g->ns / w->ns);
        }
    }
}

/* The notes every row gets from its checks. */
static void check_notes(row *w)
{
    if (w->same)
        NOTE(w, w->diff ? "**output differs from row %s's in %ld of %ld boxes**"
                        : "output bit-identical to row %s's (%ld of %ld boxes)",
             w->same->id, w->diff ? w->diff : w->checked, w->checked);
    if (w->mk == MK_TP || w->mk == MK_TP1 || w->mk == MK_TPF)
        NOTE(w, w->diff ? "**output differs from single `%s` calls in %ld of %ld cases**"
                        : "output bit-identical to single `%s` calls (%ld of %ld cases)",
             w->mk == MK_TPF ? "cbx_transform_boxf" : "cbx_transform_box",
             w->diff ? w->diff : w->checked, w->checked);
    if (w->ex.ends && w->ex.fails) {
        char c[32];
        fmt_num(c, sizeof c, w->ex.min_u);
        NOTE(w, "worst end %s units inside", c);
    }
    if (w->ex.cancel) NOTE(w, "%ld ends with \\|end\\| < S/4 left out of ulps", w->ex.cancel);
}

/* ---- output ---------------------------------------------------------- */

static void machine_line(char *model, size_t msz, int *cores)
{
    FILE *f = fopen("/proc/cpuinfo", "r");
    char line[512];
    snprintf(model, msz, "(unknown)");
    *cores = 0;
    if (!f) return;
    while (fgets(line, sizeof line, f)) {
        if (strncmp(line, "model name", 10) == 0 && !strcmp(model, "(unknown)")) {
            char *p = strchr(line, ':');
            if (p) {
                size_t l;
                p++;
                while (*p == ' ' || *p == '\t') p++;
                snprintf(model, msz, "%s", p);
                l = strlen(model);
                while (l && (model[l - 1] == '\n' || model[l - 1] == ' ')) model[--l] = 0;
            }
        }
        if (strncmp(line, "processor", 9) == 0) (*cores)++;
    }
    fclose(f);
}

/* "L1d 48K, L2 2048K, L3 ..." from sysfs (cpu0), or "" */
static void cache_line(char *s, size_t sz)
{
    int idx;
    size_t l = 0;
    s[0] = 0;
    for (idx = 0; idx < 8; idx++) {
        char p[128], level[32] = "", type[32] = "", size[32] = "";
        FILE *f;
        snprintf(p, sizeof p, "/sys/devices/system/cpu/cpu0/cache/index%d/level", idx);
        if (!(f = fopen(p, "r"))) break;
        if (!fgets(level, sizeof level, f)) level[0] = 0;
        fclose(f);
        snprintf(p, sizeof p, "/sys/devices/system/cpu/cpu0/cache/index%d/type", idx);
        if ((f = fopen(p, "r"))) { if (!fgets(type, sizeof type, f)) type[0] = 0; fclose(f); }
        snprintf(p, sizeof p, "/sys/devices/system/cpu/cpu0/cache/index%d/size", idx);
        if ((f = fopen(p, "r"))) { if (!fgets(size, sizeof size, f)) size[0] = 0; fclose(f); }
        level[strcspn(level, "\n")] = 0;
        type[strcspn(type, "\n")] = 0;
        size[strcspn(size, "\n")] = 0;
        if (!strcmp(type, "Instruction")) continue;
        if (l + 1 < sz)
            l += (size_t)snprintf(s + l, sz - l, "%sL%s%s %s", l ? ", " : "", level,
                                  !strcmp(type, "Data") ? "d" : "", size);
        if (l >= sz) { s[sz - 1] = 0; break; }
    }
}

static void first_line(const char *path, char *s, size_t sz)
{
    FILE *f = fopen(path, "r");
    if (!f) return;
    if (fgets(s, (int)sz, f)) s[strcspn(s, "\n")] = 0;
    fclose(f);
}

static void mkdir_p(const char *dir)
{
    char buf[1024];
    size_t i, l = strlen(dir);
    if (l >= sizeof buf) return;
    strcpy(buf, dir);
    for (i = 1; i <= l; i++) {
        if (buf[i] == '/' || buf[i] == 0) {
            char c = buf[i];
            buf[i] = 0;
            if (mkdir(buf, 0777) != 0 && errno != EEXIST) {
                fprintf(stderr, "bench: cannot create %s\n", buf);
                return;
            }
            buf[i] = c;
        }
    }
}

/* DIR/bench.tsv: "#meta" lines, a header, one line per visible row. */
static int write_tsv(const char *dir, const sizes *z, const bench_ctx *b, const char *status)
{
    char path[1200], model[256], caches[200], load[128] = "(unknown)", when[64];
    int cores, i;
    time_t tt = time(0);
    FILE *f;
    mkdir_p(dir);
    snprintf(path, sizeof path, "%s/bench.tsv", dir);
    if (!(f = fopen(path, "w"))) {
        fprintf(stderr, "bench: cannot write %s\n", path);
        return -1;
    }
    machine_line(model, sizeof model, &cores);
    cache_line(caches, sizeof caches);
    first_line("/proc/loadavg", load, sizeof load);
    strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S UTC", gmtime(&tt));
    fprintf(f, "# certbox bench (bench/bench.c): one build's rows; scripts/bench_table.py renders them\n");
    fprintf(f, "#meta\tlabel\t%s\n#meta\tcc\t%s\n#meta\tcc_version\t%s\n#meta\tflags\t%s\n",
            BENCH_LABEL, BENCH_CC, BENCH_CC_VERSION, BENCH_FLAGS);
    fprintf(f, "#meta\tmachine\t%s\n#meta\tcores\t%d\n#meta\tcaches\t%s\n#meta\tloadavg\t%s\n", model,
            cores, caches, load);
    fprintf(f, "#meta\tdate\t%s\n#meta\tversion\t%s\n#meta\tseed\t%lu\n#meta\tstatus\t%s\n", when,
            CBX_VERSION_STRING, z->seed, status);
    fprintf(f, "#meta\trounds\t%d\n#meta\tn\t%lu\n#meta\tpasses\t%ld\n#meta\tne\t%lu\n#meta\tng\t%lu\n",
            z->R, (unsigned long)z->n, passes_for(z->calls, z->n), (unsigned long)z->ne,
            (unsigned long)z->ng);
    fprintf(f, "#meta\tnc\t%lu\n#meta\tpasses_c\t%ld\n#meta\tnb\t%lu\n#meta\tpasses_b\t%ld\n",
            (unsigned long)z->nc, passes_for(z->calls, z->nc), (unsigned long)z->nb,
            passes_for(z->calls, z->nb));
    fprintf(f, "#meta\tns\t%lu\n#meta\tpasses_s\t%ld\n#meta\tnsc\t%lu\n#meta\tcalls\t%ld\n",
            (unsigned long)b->ns, passes_for(z->calls, b->ns), (unsigned long)z->nsc, z->calls);
    fprintf(f, "sec\tid\tname\tbase\tproven\tpcode\tplot\tns\tcpu\trw\trc\tends\tex_max\tex_mean\t"
               "ulp_max\tulp_mean\tfails\tdigest\tcases\tunit\tnote\ttnote\n");
    for (i = 0; i < nrows; i++) {
        const row *w = &rows[i];
        const acc *s = &w->ex;
        if (w->hidden) continue;
        fprintf(f, "%s\t%s\t%s\t%s\t%s\t%d\t%d\t%.6g\t%.6g\t%.6g\t%.6g\t", w->sec == SEC_TP ? "tp" : "main",
                w->id, w->name, w->base ? (w->base->hidden ? w->base->name : w->base->id) : "-",
                w->proven, w->pcode, w->plot, w->ns, w->cpu, w->rw, w->rc);
        if (s->ends)
            fprintf(f, "%ld\t%.6g\t%.6g\t%.6g\t%.6g\t%ld\t", s->ends, s->max_u, s->sum_u / (double)s->ends,
                    s->nc_ends ? s->max_ulp : NAN, s->nc_ends ? s->sum_ulp / (double)s->nc_ends : NAN,
                    s->fails);
        else
            fprintf(f, "0\tnan\tnan\tnan\tnan\t0\t");
        fprintf(f, "%016llx\t%lu\t%g\t%s\t%s\n", (unsigned long long)w->digest, (unsigned long)w->n,
                w->unit, w->note, w->tnote);
    }
    fclose(f);
    fprintf(stderr, "bench: wrote %s (sink %llx)\n", path, (unsigned long long)bench_sink);
    return 0;
}

/* The summary on stdout: one line per visible row. */
static void print_summary(void)
{
    int i;
    printf("bench (%s): ns per box, median of the rounds; x: vs the baseline (median of the "
           "per-round ratios; throughput: per byte, memcpy = 1)\n", BENCH_LABEL);
    for (i = 0; i < nrows; i++) {
        const row *w = &rows[i];
        char t[32], r[32], rc[32], cont[48];
        if (w->hidden) continue;
        fmt_num(t, sizeof t, w->ns);
        fmt_num(r, sizeof r, w->rw);
        fmt_num(rc, sizeof rc, w->rc);
        if (w->ex.ends) snprintf(cont, sizeof cont, "%ld / %ld ends outside", w->ex.fails, w->ex.ends);
        else snprintf(cont, sizeof cont, "-");
        printf("  %-6s %9s ns  %6s x %-6s (CPU %6s x)  %-26s %s%s\n", w->id, t, r,
               w->base ? w->base->hidden ? "Arvo" : w->base->id : "-", rc, cont, w->name,
               w->diff ? "  **OUTPUT DIFFERS**" : "");
    }
}

/* ---- inputs ---------------------------------------------------------- */

/* The N cases, their cbox forms, binary32 copies and prepared maps. */
static void gen_rot(bench_ctx *b, size_t n, uint64_t seed);

static void setup_cases(bench_ctx *b, size_t n, unsigned long seed)
{
    xu_rng rng;
    size_t k;
    b->n = n;
    b->a = xmalloc(n * sizeof *b->a);
    b->in = xmalloc(n * sizeof *b->in);
    b->pa = xmalloc(n * sizeof *b->pa);
    b->ia = xmalloc(n * sizeof *b->ia);
    b->cin_cbx = xmalloc(n * sizeof *b->cin_cbx);
    b->cin_rn = xmalloc(n * sizeof *b->cin_rn);
    b->af = xmalloc(n * sizeof *b->af);
    b->inf = xmalloc(n * sizeof *b->inf);
    b->paf = xmalloc(n * sizeof *b->paf);
    rng.s = seed;
    for (k = 0; k < n; k++) {
        gen_case(&rng, &b->a[k], &b->in[k]);
        if (cbx_box_to_cbox(&b->in[k], &b->cin_cbx[k]) != CBX_OK) b->bad++;
        ref_box_to_cbox(&b->in[k], &b->cin_rn[k]);
        cbx_prepare(&b->a[k], &b->pa[k]);
        memcpy(b->ia[k].lo, b->a[k].m, sizeof b->a[k].m);
        memcpy(b->ia[k].hi, b->a[k].m, sizeof b->a[k].m);
        affine_to_f(&b->a[k], &b->af[k]);
        box_to_f(&b->in[k], &b->inf[k]);
        cbx_preparef(&b->af[k], &b->paf[k]);
    }
    b->p0 = b->pa[0];
    b->p0f = b->paf[0];
    /* projective: a perspective camera (field of view 30 to 120 degrees,
     * near 2^-4 .. 1, far 2^8 .. 2^12 times near) times a rigid view; a box
     * of size 2^-6 .. 2^2 in front of it (view depth 2 .. 2^10) */
    b->pm = xmalloc(n * sizeof *b->pm);
    b->pin = xmalloc(n * sizeof *b->pin);
    b->psc = xmalloc(3 * n * sizeof *b->psc);
    b->psr = xmalloc(n * sizeof *b->psr);
    b->pcx = xmalloc(n * sizeof *b->pcx);
    b->pwn = xmalloc(n * sizeof *b->pwn);
    b->pxc = xmalloc(3 * n * sizeof *b->pxc);
    b->pxr = xmalloc(n * sizeof *b->pxr);
    b->pes = xmalloc(3 * n * sizeof *b->pes);
    b->per = xmalloc(n * sizeof *b->per);
    b->pmf = xmalloc(n * sizeof *b->pmf);
    b->pinf = xmalloc(n * sizeof *b->pinf);
    b->pscf = xmalloc(3 * n * sizeof *b->pscf);
    b->psrf = xmalloc(n * sizeof *b->psrf);
    b->pwnf = xmalloc(n * sizeof *b->pwnf);
    b->pesf = xmalloc(3 * n * sizeof *b->pesf);
    b->perf = xmalloc(n * sizeof *b->perf);
    rng.s = seed + 7;
    for (k = 0; k < n; k++) {
        double R[3][3], T[3], f, asp, nr, fr, vc[3], h, pr[4][4], v[4][4];
        int i, j, l;
        xu_rand_rotation(&rng, R);
        for (i = 0; i < 3; i++) T[i] = urand(&rng, -10, 10);
        f = 1.0 / tan(urand(&rng, 0.26, 1.05));
        asp = urand(&rng, 1, 2);
        nr = ldexp(1.0, xu_rng_int(&rng, -4, 0));
        fr = nr * ldexp(1.0, xu_rng_int(&rng, 8, 12));
        memset(pr, 0, sizeof pr);
        pr[0][0] = f / asp; pr[1][1] = f;
        pr[2][2] = (fr + nr) / (nr - fr); pr[2][3] = 2 * fr * nr / (nr - fr); pr[3][2] = -1;
        memset(v, 0, sizeof v);
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) v[i][j] = R[i][j];
            v[i][3] = T[i];
        }
        v[3][3] = 1;
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++) {
                double acc = 0;
                for (l = 0; l < 4; l++) acc += pr[i][l] * v[l][j];
                b->pm[k].m[i][j] = acc;
            }
        vc[2] = -ldexp(1.0, xu_rng_int(&rng, 1, 10));
        vc[0] = urand(&rng, -0.5, 0.5) * vc[2];
        vc[1] = urand(&rng, -0.5, 0.5) * vc[2];
        h = ldexp(1.0, xu_rng_int(&rng, -6, 2)) * 0.5;
        if (h > -vc[2] / 4) h = -vc[2] / 4;
        for (i = 0; i < 3; i++) {
            double c = 0;
            for (j = 0; j < 3; j++) c += R[j][i] * (vc[j] - T[j]);
            b->pin[k].lo[i] = c - h;
            b->pin[k].hi[i] = c + h;
            b->psc[3 * k + i] = c;
        }
        b->psr[k] = h;
        b->pwn[k] = nr;
        /* across the near plane: the box around view depth nr .. 4 nr,
         * half-size 2 nr .. 8 nr (always cut) */
        vc[2] = -nr * urand(&rng, 1, 4);
        h = nr * urand(&rng, 2, 8);
        for (i = 0; i < 3; i++) {
            double c = 0;
            for (j = 0; j < 3; j++) c += R[j][i] * (vc[j] - T[j]);
            b->pcx[k].lo[i] = c - h;
            b->pcx[k].hi[i] = c + h;
            b->pxc[3 * k + i] = c;    /* the ball inscribed in that cube */
        }
        b->pxr[k] = h;
    }
    /* ellipsoids at the balls' centres (their own generator, so that the
     * other rows' cases stay the same): a random rotation, radii the ball's
     * radius times 1, 1/4 .. 1 and 1/16 .. 1 (inside the ball) */
    rng.s = seed + 11;
    for (k = 0; k < n; k++) {
        xu_rand_rotation(&rng, b->per[k]);
        b->pes[3 * k] = b->psr[k];
        b->pes[3 * k + 1] = b->psr[k] * urand(&rng, 0.25, 1);
        b->pes[3 * k + 2] = b->psr[k] * urand(&rng, 0.0625, 1);
    }
    /* the binary32 twins' inputs: each value rounded to nearest float */
    for (k = 0; k < n; k++) {
        int i, j;
        for (i = 0; i < 4; i++)
            for (j = 0; j < 4; j++)
                b->pmf[k].m[i][j] = (float)b->pm[k].m[i][j];
        for (i = 0; i < 3; i++) {
            b->pinf[k].lo[i] = (float)b->pin[k].lo[i];
            b->pinf[k].hi[i] = (float)b->pin[k].hi[i];
            b->pscf[3 * k + i] = (float)b->psc[3 * k + i];
            b->pesf[3 * k + i] = (float)b->pes[3 * k + i];
            for (j = 0; j < 3; j++)
                b->perf[k][i][j] = (float)b->per[k][i][j];
        }
        b->psrf[k] = (float)b->psr[k];
        b->pwnf[k] = (float)b->pwn[k];
    }
    gen_rot(b, n, seed);
}

/* Rotation motion: a keyframe pair per case (random orientation, a turn
 * of 0 to 90 degrees about a random axis, translations within 10 moving
 * by up to 2, scales 0.5 to 2 per axis, changing in half of the cases) and
 * a box (centre within 4, half-size 2^-6 .. 2). */
/* v: a random unit vector of R^n (rejection from the cube). */
static void rand_dir(xu_rng *rng, double *v, int n)
{
    double nn;
    int i;
    do {
        nn = 0;
        for (i = 0; i < n; i++) {
            v[i] = urand(rng, -1, 1);
            nn += v[i] * v[i];
        }
    } while (nn < 0.01 || nn > 1);
    nn = sqrt(nn);
    for (i = 0; i < n; i++) v[i] /= nn;
}

static void gen_rot(bench_ctx *b, size_t n, uint64_t seed)
{
    xu_rng rng;
    size_t k;
    b->rk0 = xmalloc(n * sizeof *b->rk0);
    b->rk1 = xmalloc(n * sizeof *b->rk1);
    b->rin = xmalloc(n * sizeof *b->rin);
    rng.s = seed + 11;
    for (k = 0; k < 128; k++) t_128[k] = (double)k / 128.0;
    for (k = 0; k < n; k++) {
        double q[4], ax[3], h = urand(&rng, 0, 0.7853981633974483);
        int i;
        rand_dir(&rng, q, 4);
        rand_dir(&rng, ax, 3);
        for (i = 0; i < 4; i++) b->rk0[k].q[i] = q[i];
        {   /* q1 = q0 * (axis sin h, cos h) */
            double d[4] = { sin(h) * ax[0], sin(h) * ax[1], sin(h) * ax[2], cos(h) };
            const double *a = b->rk0[k].q;
            b->rk1[k].q[0] = a[3] * d[0] + a[0] * d[3] + a[1] * d[2] - a[2] * d[1];
            b->rk1[k].q[1] = a[3] * d[1] - a[0] * d[2] + a[1] * d[3] + a[2] * d[0];
            b->rk1[k].q[2] = a[3] * d[2] + a[0] * d[1] - a[1] * d[0] + a[2] * d[3];
            b->rk1[k].q[3] = a[3] * d[3] - a[0] * d[0] - a[1] * d[1] - a[2] * d[2];
        }
        for (i = 0; i < 3; i++) {
            double c = urand(&rng, -4, 4), hh = ldexp(1.0, xu_rng_int(&rng, -6, 1));
            b->rk0[k].t[i] = urand(&rng, -10, 10);
            b->rk1[k].t[i] = b->rk0[k].t[i] + urand(&rng, -2, 2);
            b->rk0[k].s[i] = urand(&rng, 0.5, 2);
            b->rk1[k].s[i] = (k & 1) ? urand(&rng, 0.5, 2) : b->rk0[k].s[i];
            b->rin[k].lo[i] = c - hh;
            b->rin[k].hi[i] = c + hh;
        }
    }
    if (cbx_trs_pieces(&b->rk0[0], &b->rk1[0], CBX_SLERP, 0.0, 1.0, 4, b->rpc, 16, &b->nrpc) != CBX_OK) {
        fprintf(stderr, "bench: cbx_trs_pieces failed on the first pair\n");
        exit(1);
    }
}

/* The throughput arrays: nb cases, and 2 nb binary32 boxes. */
static void setup_throughput(bench_ctx *b, size_t nb, unsigned long seed)
{
    xu_rng rng;
    size_t k;
    if (nb == 0) return;
    b->ta = xmalloc(nb * sizeof *b->ta);
    b->tin = xmalloc(nb * sizeof *b->tin);
    b->tout = xmalloc(nb * sizeof *b->tout);
    b->tinf = xmalloc(2 * nb * sizeof *b->tinf);
    b->toutf = xmalloc(2 * nb * sizeof *b->toutf);
    b->mdst = xmalloc(nb * (sizeof(cbx_affine) + 2 * sizeof(cbx_box)));
    rng.s = seed + 1;
    for (k = 0; k < nb; k++) gen_case(&rng, &b->ta[k], &b->tin[k]);
    rng.s = seed + 3;
    for (k = 0; k < 2 * nb; k++) {
        cbx_box t;
        gen_box(&rng, &t);
        box_to_f(&t, &b->tinf[k]);
    }
    cbx_prepare(&b->ta[0], &b->tp0);
    affine_to_f(&b->ta[0], &b->taf0);
    cbx_preparef(&b->taf0, &b->tpf0);
}

/* The scene: ns instances, classified here (untimed), and their copy
 * sorted by class.  Returns the number of classes that differ from the
 * one meant. */
static long setup_scene(bench_ctx *b, size_t ns, unsigned long seed)
{
    xu_rng rng;
    size_t k, fill[5];
    long mismatch = 0;
    int c;
    b->ns = ns;
    if (ns == 0) return 0;
    b->sa = xmalloc(ns * sizeof *b->sa);
    b->sin = xmalloc(ns * sizeof *b->sin);
    b->scls = xmalloc(ns * sizeof *b->scls);
    b->qa = xmalloc(ns * sizeof *b->qa);
    b->qin = xmalloc(ns * sizeof *b->qin);
    b->qo = xmalloc(ns * sizeof *b->qo);
    b->qcls = xmalloc(ns * sizeof *b->qcls);
    rng.s = seed + 2;
    for (k = 0; k < ns; k++) {
        cbx_class meant = gen_scene_inst(&rng, &b->sa[k], &b->sin[k]);
        b->scls[k] = cbx_classify(&b->sa[k]);
        mismatch += b->scls[k] != meant;
        b->ns_cnt[b->scls[k]]++;
    }
    b->ns_off[0] = 0;
    for (c = 0; c < 5; c++) {
        b->ns_off[c + 1] = b->ns_off[c] + b->ns_cnt[c];
        fill[c] = b->ns_off[c];
    }
    for (k = 0; k < ns; k++) {
        size_t d = fill[b->scls[k]]++;
        b->qa[d] = b->sa[k];
        b->qin[d] = b->sin[k];
        b->qcls[d] = b->scls[k];
    }
    return mismatch;
}

static void usage(void)
{
    fprintf(stderr, "usage: bench [-n N] [-r R] [-calls C] [-exact NE] [-gmp NG] "
                    "[-cache NC] [-big NB] [-scene NS] [-seed S] [-o DIR]\n");
    exit(2);
}

int main(int argc, char **argv)
{
    sizes z;
    size_t nscene = (size_t)-1;
    const char *dir = "build/bench-out";
    static const char *const plotted[] = { "1", "2", "3", "3p", "3t", "3b", "2f", "3f",
                                           "4", "5", "6a", "6b", "7" };
    bench_ctx b;
    scene_check sc;
    double volratio = 0.0;
    long conv_bad, fails = 0, diffs = 0, tight_off = 0, scene_fails;
    char status[300];
    row *w;
    int i;

    z.n = 20000; z.ne = 20000; z.ng = 2000; z.nc = 1000; z.nb = 4000000;
    z.calls = 200000; z.R = 11; z.seed = 20240501;
    for (i = 1; i < argc; i++) {
        const char *o = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : 0;
        if (!v) usage();
        if (!strcmp(o, "-n")) z.n = strtoul(v, 0, 10);
        else if (!strcmp(o, "-r")) z.R = atoi(v);
        else if (!strcmp(o, "-calls")) z.calls = atol(v);
        else if (!strcmp(o, "-exact")) z.ne = strtoul(v, 0, 10);
        else if (!strcmp(o, "-gmp")) z.ng = strtoul(v, 0, 10);
        else if (!strcmp(o, "-cache")) z.nc = strtoul(v, 0, 10);
        else if (!strcmp(o, "-big")) z.nb = strtoul(v, 0, 10);
        else if (!strcmp(o, "-scene")) nscene = strtoul(v, 0, 10);
        else if (!strcmp(o, "-seed")) z.seed = strtoul(v, 0, 10);
        else if (!strcmp(o, "-o")) dir = v;
        else usage();
        i++;
    }
    if (z.n < 1 || z.R < 1 || z.R > MAXR || z.calls < 1) usage();
    if (z.ne > z.n) z.ne = z.n;
    if (z.ng > z.n) z.ng = z.n;
    if (z.nb > 0 && z.nc > z.nb) z.nc = z.nb;
    if (z.nb > 0 && z.nc == 0) z.nc = 1;

    /* ---- inputs (untimed) ---- */
    memset(&b, 0, sizeof b);
    memset(&sc, 0, sizeof sc);
    xu_init(&b.x);
    mpz_inits(b.e.gap, b.e.v, b.e.w, b.e.t, (mpz_ptr)0);
    setup_cases(&b, z.n, z.seed);
    setup_throughput(&b, z.nb, z.seed);
    if (nscene == (size_t)-1) nscene = z.nb > 0 ? z.nb / 4 : z.n;
    sc.mismatch = setup_scene(&b, nscene, z.seed);
    z.nsc = z.nc < b.ns ? z.nc : b.ns;
    if (z.nsc == 0) z.nsc = b.ns < 1000 ? b.ns : 1000;
    conv_bad = b.bad;
    b.bad = 0;

    /* ---- the rows, timed group by group ---- */
    define_rows(&b, &z);
    for (i = 0; i < (int)(sizeof plotted / sizeof plotted[0]); i++)
        if ((w = find_row(plotted[i]))) w->plot = 1;
    for (i = 0; i < NGRP; i++) time_group(&b, i, z.R);

    /* ---- checks (untimed): bit identity, then exact, on the first ne ---- */
    for (i = 0; i < nrows; i++) {
        w = &rows[i];
        if (w->mk != MK_NONE && w->mk < MK_TP && w->esz) w->digest = checksum(w->out, w->n * w->esz);
        if (w->same) {
            const unsigned char *p = (const unsigned char *)w->out;
            const unsigned char *q = (const unsigned char *)w->same->out;
            size_t k;
            w->checked = (long)w->n;
            for (k = 0; k < w->n; k++) w->diff += memcmp(p + k * w->esz, q + k * w->esz, w->esz) != 0;
        }
        measure_row(&b, w, z.ne);
    }
    if (find_row("6a") && find_row("6b"))
        measure_sphere(&b, z.ne, (const cbx_box *)find_row("6a")->out,
                       (const cbx_box *)find_row("6b")->out, &find_row("6a")->ex,
                       &find_row("6b")->ex, &volratio);
    if (b.ns > 0)
        check_scene(&b, (const cbx_box *)find_row("S")->out, (const cbx_box *)find_row("Sc")->out,
                    z.ne, z.ng, &sc);
    set_notes(&b, &z, &sc, volratio);
    for (i = 0; i < nrows; i++) {
        w = &rows[i];
        check_notes(w);
        if (w->pcode == 1) fails += w->ex.fails;
        diffs += w->diff;
    }
    if ((w = find_row("3t"))) tight_off = w->opt.off;
    scene_fails = sc.looser + sc.infdiff + sc.corner_fail;

    /* ---- output ---- */
    if (fails || diffs || tight_off || scene_fails || b.bad || conv_bad)
        snprintf(status, sizeof status, "FAILED: %ld containment failures in certbox rows, %ld "
                 "outputs not bit-identical, %ld tight ends not the tightest, %ld scene check "
                 "failures, %ld calls not CBX_OK", fails, diffs, tight_off, scene_fails,
                 b.bad + conv_bad);
    else
        snprintf(status, sizeof status, "ok");
    print_summary();
    fflush(stdout);
    if (write_tsv(dir, &z, &b, status) != 0) return 2;
    xu_clear(&b.x);
    mpz_clears(b.e.gap, b.e.v, b.e.w, b.e.t, (mpz_ptr)0);
    if (strcmp(status, "ok")) {
        fprintf(stderr, "bench: %s\n", status);
        return 1;
    }
    return 0;
}
