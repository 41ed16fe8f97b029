/*
 * bench: the benchmark table of issue 5 (`make bench`, `make bench-smoke`).
 *
 * Usage: bench [-n N] [-r R] [-calls C] [-exact NE] [-gmp NG] [-cache NC]
 *              [-big NB] [-scene NS] [-seed S] [-o DIR]
 *   N   cases of rows 1-6 (default 20000)      R   timed runs (11, odd)
 *   C   calls per run (200000)                  NE  exactly measured (20000)
 *   NG  cases of the GMP row (2000)             NC  in-cache throughput (1000)
 *   NB  large-array throughput (4000000; 0: no throughput rows)
 *   S   seed (20240501)                         DIR output (build/bench-out)
 * Prints one markdown table to stdout and writes DIR/bench.md (the same
 * table) and DIR/bench.dat (one block per plotted row, for scripts/bench.gp,
 * which scripts/bench_plot.sh runs).  Exit status 1 if a certbox row has a
 * containment failure, a call that does not return CBX_OK, a batch
 * output (row 3b) that is not bit-identical to the loop of single calls,
 * or a class-kernel end (row Sc) looser than the general kernel's.
 *   make bench        -n 20000 -r 11 -calls 200000 -exact 20000 -gmp 2000
 *                     -cache 1000 -big 4000000 (about 1.5 GB of memory)
 *   make bench-smoke  -n 2000 -r 5 -calls 20000 -exact 2000 -gmp 200
 *                     -cache 1000 -big 100000 (about a second)
 *
 * Inputs (fixed seed S): N random affine maps M = R diag(s) with T (R a
 * rotation from a uniform random unit quaternion, s_j = +-2^[-4,4] with 10%
 * reflections, T_i = +-[0,1) * 2^[-2,10]) and N boxes of mixed sizes
 * (center +-[0,1) * 2^[-4,8], half-width 2^[-12,6] per axis, 5% of the
 * axes flat: lo = hi).  Every row below runs on these same N cases.
 *
 * Rows
 *   1  naive 8 corners, RN: each corner transformed as a point, min / max
 *      (pbrt, Embree); tests/bench_ref.h ref_naive8, not in the library.
 *   2  classic Arvo interval form, RN (cglm, Godot): ref_arvo_box; the
 *      baseline of the "vs row 2" column.  Unsound (no widening).
 *   3  certbox cbx_transform_box (interval form, outward, proven).
 *   3t certbox tight: cbx_transform_box_tight (every finite end the
 *      tightest double, RD / RU of the exact end); its notes give, exactly
 *      (GMP, MPFR), how many ends are not the tightest double and by how
 *      many ulps (should be 0).
 *   3b certbox batch: cbx_transform_boxes(&a[0], in, out, N), one call over
 *      the same N boxes, all under the first map (the batch form takes one
 *      map); excess measured against that map; the notes give a loop of
 *      cbx_transform_box over the same boxes and map (untabled timing) and
 *      check that the batch output is bit-identical to it.
 *   4  certbox cbx_transform_cbox; its inputs are converted with
 *      cbx_box_to_cbox (outward) before the timed loops.
 *   5  classic Arvo center/half form, RN: ref_arvo_cbox on inputs converted
 *      with c = (lo+hi)/2, h = (hi-lo)/2 in RN, before the timed loops.
 *   6a sphere: cbx_sphere_box (exact dual-quadric bound t -+ sqrt(sum m^2),
 *      outward) of the unit ball under the same N maps.
 *   6b sphere by Arvo: cbx_transform_box of the ball's box [-1,1]^3 under
 *      the same maps (sound, but the box of a rotated box); the notes give
 *      the mean of vol(6b) / vol(6a) over the exact subset.
 *   7  GMP exact: xu_row_bounds (tests/exact_util.c, fixed-point mpz) for
 *      the 3 rows of each of the first NG cases: the exact L, H, S.
 *   T1 throughput of cbx_transform_box over NC cases (in cache) and
 *   T2 over NB cases (a large array, out of cache when above the L3 size
 *      printed in the header; 192 bytes per case: map 96, box in 48,
 *      box out 48); the same cases' map and box arrays and a memcpy of the
 *      same number of bytes (in + out) are timed in the same run.
 *   T1b, T2b the same boxes through cbx_transform_boxes under one map (the
 *      first case's): 96 bytes per case (box in 48, box out 48), against a
 *      memcpy of those bytes.
 *   S  scene: NS instances (default NB / 4: 10^6 under make bench, 25000
 *      under make bench-smoke; N when NB is 0), each with its own map and
 *      box, in random order, with a mix of transform classes: 20% IDENTITY,
 *      35% TRANSLATE, 15% SCALE (+ translation), 10% PERMUTE (a 90-degree
 *      rotation, times a uniform scale half of the time, + translation),
 *      20% GENERAL (a random rotation with scales, as rows 1-6); boxes as
 *      rows 1-6.  Each instance is classified once (cbx_classify) when the
 *      scene is built (untimed) and its class stored.  Row S: the general
 *      kernel cbx_transform_box on every instance.
 *   Sc the same scene through cbx_transform_box_as with the stored class;
 *      its notes give the speed-up S / Sc (wall and CPU), the same two on
 *      the first NC instances (in cache; the many passes over the same
 *      NC instances let the branch predictor learn their class sequence,
 *      so that figure is optimistic: the NS figure, one pass over a large
 *      scene in random order, is the realistic one), and the check that no
 *      finite end is looser than row S's (infinite ends identical) over
 *      all NS.
 *   S-ID, S-TR, S-SC, S-PE, S-GE  the instances of one class, copied
 *      contiguously (untimed), through cbx_transform_box_as with the stored
 *      class; the notes give cbx_transform_box on the same instances and
 *      the speed-up.
 *      Checked (untimed): every scene output (S, Sc) exactly against the
 *      exact image on the first NE instances (excess, containment), the 8
 *      corners in mpq on the first NG instances for Sc, and no Sc end looser
 *      than S's; any violation fails the run (make bench-smoke included).
 *
 * Timing: clock_gettime(CLOCK_MONOTONIC) around one run; a run is P passes
 * over the whole array (P = max(1, C / N): a run makes about C calls, so
 * that it lasts milliseconds even for a small array).  One untimed warm-up
 * run, then R timed runs; ns per box = median run time / (P N).  The
 * baselines are static inline (as in the header-only libraries they stand
 * for) and compiled with the library's flags (-std=c99 -ffp-contract=off
 * -fno-fast-math -O2); certbox is an out-of-line call into libcertbox.a.
 * Dead-code elimination is defeated by writing every result to an output
 * array, by an opaque call (a volatile function pointer) after each pass,
 * and by checksumming the output array after each run into a volatile sink
 * (outside the timed region).
 *
 * Columns
 *   ns/box       median over R runs (see above); "vs row 2" is its ratio
 *                to row 2's; "M boxes/s" is 1000 / (ns/box).
 *   CPU ns/box   the same median in the thread's CPU time
 *                (CLOCK_THREAD_CPUTIME_ID): it leaves out the time the
 *                thread was descheduled, so on a loaded machine it is the
 *                figure to trust; on an idle one the two agree.
 *   excess       for each end of each axis of the first NE cases, computed
 *                exactly with GMP (exact_util): lower end L - lo, upper end
 *                hi - H, with L, H the exact bounds of the image of the
 *                original box, in units of u S + eta (u = 2^-53,
 *                eta = 2^-1074, S = |t| + sum_j |m_j| max(|lo_j|, |hi_j|)
 *                from xu_row_bounds); max and mean over all ends.  A
 *                center/half output (c, h) is the real box [c - h, c + h],
 *                taken exactly.  Negative = the end is inside the exact
 *                image.  For the sphere rows the exact ends are
 *                t -+ sqrt(sum_j m_j^2) (MPFR, 320 bits) and the unit is
 *                u (|t| + sqrt(sum_j m_j^2)) + eta.
 *   ulps         the same gaps in ulps of the exact end (the spacing of
 *                binary64 at |L| or |H|), max and mean over the ends with
 *                no cancellation, |end| >= S / 4 as in test_sphere (where
 *                the end is small against S its ulp is small and the count
 *                grows like S / |end|, measuring the cancellation rather
 *                than the method); the number of ends left out is in the
 *                notes when nonzero.
 *   containment  ends that are NOT outside-or-equal the exact bound
 *                (lo > L or hi < H, decided exactly), out of all ends
 *                measured.  May be > 0 for rows 1, 2, 5; must be 0 for the
 *                certbox rows.
 *   proven       yes only for certbox functions (Frama-C/WP contract).
 *   vs memcpy    throughput rows: time / time of memcpy of the same bytes.
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
#ifdef __VERSION__
#define BENCH_CC_VERSION __VERSION__
#else
#define BENCH_CC_VERSION "(unknown)"
#endif

#define MAXR 101
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

typedef struct bench_ctx {
    size_t n, ngmp;
    cbx_affine *a;
    cbx_box *in;
    cbx_cbox *cin_cbx, *cin_rn;
    cbx_box *o_naive, *o_arvo, *o_cbx, *o_sph, *o_sphbox;
    cbx_box *o_tight, *o_batch, *o_cbx1;  /* rows 3t, 3b and 3b's loop    */
    cbx_cbox *co_cbx, *co_rn;
    long bad;               /* certbox calls that did not return CBX_OK  */
    xu_exact x;
    uint64_t gmp_acc;
    /* throughput arrays */
    size_t nt;
    cbx_affine *ta;
    cbx_box *tin, *tout;
    unsigned char *mdst;
    /* the scene rows (S): per instance its own map, box and stored class;
     * p*: the same instances sorted by class (S-ID .. S-GE) */
    size_t ns, ns_cnt[5], ns_off[6];
    cbx_affine *sa, *pa;
    cbx_box *sin, *so_g, *so_c, *pin, *po;
    cbx_class *scls, *pcls;
    int cur;                /* the class timed by k_cls_gen / k_cls_as    */
} bench_ctx;

static double urand(xu_rng *r, double lo, double hi)
{
    return lo + (hi - lo) * xu_rng_unit(r);
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
    for (j = 0; j < 3; j++) {
        double c = urand(r, -1.0, 1.0) * ldexp(1.0, xu_rng_int(r, -4, 8));
        double h = xu_rng_int(r, 0, 19) == 0 ? 0.0 : pow(2.0, urand(r, -12.0, 6.0));
        b->lo[j] = c - h;
        b->hi[j] = c + h;
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

/* ---- kernels: one pass over the first n cases ------------------------ */

typedef void (*kern_fn)(bench_ctx *b, size_t n);

static void k_naive(bench_ctx *b, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) ref_naive8(&b->a[i], &b->in[i], &b->o_naive[i]);
}
static void k_arvo(bench_ctx *b, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) ref_arvo_box(&b->a[i], &b->in[i], &b->o_arvo[i]);
}
static void k_cbx(bench_ctx *b, size_t n)
{
    size_t i;
    long bad = 0;
    for (i = 0; i < n; i++) bad += cbx_transform_box(&b->a[i], &b->in[i], &b->o_cbx[i]) != CBX_OK;
    b->bad += bad;
}
static void k_tight(bench_ctx *b, size_t n)
{
    size_t i;
    long bad = 0;
    for (i = 0; i < n; i++)
        bad += cbx_transform_box_tight(&b->a[i], &b->in[i], &b->o_tight[i]) != CBX_OK;
    b->bad += bad;
}
/* one map (the first case's) for the whole array: the batch form */
static void k_batch(bench_ctx *b, size_t n)
{
    b->bad += cbx_transform_boxes(&b->a[0], b->in, b->o_batch, n) != CBX_OK;
}
static void k_cbx1(bench_ctx *b, size_t n)
{
    size_t i;
    long bad = 0;
    for (i = 0; i < n; i++) bad += cbx_transform_box(&b->a[0], &b->in[i], &b->o_cbx1[i]) != CBX_OK;
    b->bad += bad;
}
static void k_cbxc(bench_ctx *b, size_t n)
{
    size_t i;
    long bad = 0;
    for (i = 0; i < n; i++) bad += cbx_transform_cbox(&b->a[i], &b->cin_cbx[i], &b->co_cbx[i]) != CBX_OK;
    b->bad += bad;
}
static void k_arvoc(bench_ctx *b, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) ref_arvo_cbox(&b->a[i], &b->cin_rn[i], &b->co_rn[i]);
}
static void k_sph(bench_ctx *b, size_t n)
{
    size_t i;
    long bad = 0;
    for (i = 0; i < n; i++) bad += cbx_sphere_box(&b->a[i], &b->o_sph[i]) != CBX_OK;
    b->bad += bad;
}
static const cbx_box unit_box = {{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}};
static void k_sphbox(bench_ctx *b, size_t n)
{
    size_t i;
    long bad = 0;
    for (i = 0; i < n; i++) bad += cbx_transform_box(&b->a[i], &unit_box, &b->o_sphbox[i]) != CBX_OK;
    b->bad += bad;
}
static void k_gmp(bench_ctx *b, size_t n)
{
    size_t i;
    int r;
    uint64_t acc = 0;
    for (i = 0; i < n; i++)
        for (r = 0; r < 3; r++) {
            xu_row_bounds(&b->x, &b->a[i], &b->in[i], r);
            acc += (uint64_t)mpz_getlimbn(b->x.L, 0) + (uint64_t)mpz_getlimbn(b->x.H, 0);
        }
    b->gmp_acc += acc;
}
static void k_tp(bench_ctx *b, size_t n)
{
    size_t i;
    long bad = 0;
    for (i = 0; i < n; i++) bad += cbx_transform_box(&b->ta[i], &b->tin[i], &b->tout[i]) != CBX_OK;
    b->bad += bad;
}
static void k_tp_batch(bench_ctx *b, size_t n)
{
    b->bad += cbx_transform_boxes(&b->ta[0], b->tin, b->tout, n) != CBX_OK;
}
/* the scene: every instance under its own map, general kernel / class kernel */
static void k_scene_gen(bench_ctx *b, size_t n)
{
    size_t i;
    long bad = 0;
    for (i = 0; i < n; i++) bad += cbx_transform_box(&b->sa[i], &b->sin[i], &b->so_g[i]) != CBX_OK;
    b->bad += bad;
}
static void k_scene_as(bench_ctx *b, size_t n)
{
    size_t i;
    long bad = 0;
    for (i = 0; i < n; i++)
        bad += cbx_transform_box_as(&b->sa[i], b->scls[i], &b->sin[i], &b->so_c[i]) != CBX_OK;
    b->bad += bad;
}
/* the instances of class b->cur only (sorted copy) */
static void k_cls_gen(bench_ctx *b, size_t n)
{
    size_t i, o = b->ns_off[b->cur];
    long bad = 0;
    for (i = o; i < o + n; i++) bad += cbx_transform_box(&b->pa[i], &b->pin[i], &b->po[i]) != CBX_OK;
    b->bad += bad;
}
static void k_cls_as(bench_ctx *b, size_t n)
{
    size_t i, o = b->ns_off[b->cur];
    long bad = 0;
    for (i = o; i < o + n; i++)
        bad += cbx_transform_box_as(&b->pa[i], b->pcls[i], &b->pin[i], &b->po[i]) != CBX_OK;
    b->bad += bad;
}
static void k_memcpy_boxes(bench_ctx *b, size_t n)
{
    size_t nb = n * sizeof(cbx_box);
    memcpy(b->mdst, b->tin, nb);
    memcpy(b->mdst + nb, b->tout, nb);
}
static void k_memcpy(bench_ctx *b, size_t n)
{
    size_t na = n * sizeof(cbx_affine), nb = n * sizeof(cbx_box);
    memcpy(b->mdst, b->ta, na);
    memcpy(b->mdst + na, b->tin, nb);
    memcpy(b->mdst + na + nb, b->tout, nb);
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

/* Median ns per case of R runs of `passes` passes over n cases (wall
 * clock, CLOCK_MONOTONIC); *cpu: the same with the thread's CPU time.
 * out/bytes: the output to checksum after each run. */
static double time_kernel(bench_ctx *b, kern_fn f, size_t n, long passes, int R,
                          const void *out, size_t bytes, double *cpu)
{
    double t[MAXR], c[MAXR];
    int r;
    long p;
    *cpu = -1.0;
    if (n == 0) return -1.0;
    for (p = 0; p < passes; p++) { /* warm-up run */
        f(b, n);
        bench_escape(b);
    }
    for (r = 0; r < R; r++) {
        double c0 = cpu_ns(), t0 = now_ns(), t1, c1;
        for (p = 0; p < passes; p++) {
            f(b, n);
            bench_escape(b);
        }
        t1 = now_ns();
        c1 = cpu_ns();
        t[r] = (t1 - t0) / ((double)passes * (double)n);
        c[r] = (c1 - c0) / ((double)passes * (double)n);
        bench_sink ^= checksum(out, bytes) ^ b->gmp_acc;
    }
    qsort(t, (size_t)R, sizeof t[0], cmp_double);
    qsort(c, (size_t)R, sizeof c[0], cmp_double);
    *cpu = c[R / 2];
    return t[R / 2];
}

static long passes_for(long calls, size_t n)
{
    long p = n ? (long)(calls / (long)n) : 1;
    return p < 1 ? 1 : p;
}

/* ---- exact measurement ----------------------------------------------- */

typedef struct acc {
    long ends, fails, nc_ends, cancel;
    double max_u, sum_u, min_u, max_ulp, sum_ulp;
} acc;

static void acc_init(acc *s)
{
    memset(s, 0, sizeof *s);
    s->max_u = -HUGE_VAL;
    s->min_u = HUGE_VAL;
    s->max_ulp = -HUGE_VAL;
}

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

typedef struct ex_scratch { mpz_t gap, v, w, t; } ex_scratch;

/* gap (scaled by 2^XU_SHIFT) in ulps of the exact end E (scaled). */
static double gap_ulps(const mpz_t gap, const mpz_t E)
{
    long ee, eg, ue;
    double fg;
    if (mpz_sgn(gap) == 0) return 0.0;
    if (mpz_sgn(E) == 0) {
        ue = -1074;
    } else {
        (void)mpz_get_d_2exp(&ee, E); /* |E| in [2^(ee-1), 2^ee) */
        ue = ee - XU_SHIFT - 53;
        if (ue < -1074) ue = -1074;
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

typedef struct opt_acc { long ends, off; double max_off, sum_off; } opt_acc;

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

static void measure_sphere(bench_ctx *b, size_t ne, acc *sph, acc *sphbox, double *volratio)
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
            record_sph_end(&b->x, &k, sph, t, b->o_sph[i].lo[r], 0);
            record_sph_end(&b->x, &k, sph, t, b->o_sph[i].hi[r], 1);
            record_sph_end(&b->x, &k, sphbox, t, b->o_sphbox[i].lo[r], 0);
            record_sph_end(&b->x, &k, sphbox, t, b->o_sphbox[i].hi[r], 1);
            v *= (b->o_sphbox[i].hi[r] - b->o_sphbox[i].lo[r])
                 / (b->o_sph[i].hi[r] - b->o_sph[i].lo[r]);
        }
        vsum += v;
    }
    *volratio = ne ? vsum / (double)ne : 0.0;
    mpz_clears(k.s, k.m, (mpz_ptr)0);
    mpfr_clears(k.R, k.T, k.E, k.D, k.G, k.U, (mpfr_ptr)0);
}

/* ---- output ---------------------------------------------------------- */

static FILE *md_file;

static void out(const char *fmt, ...)
{
    va_list ap, aq;
    va_start(ap, fmt);
    va_copy(aq, ap);
    vprintf(fmt, ap);
    if (md_file) vfprintf(md_file, fmt, aq);
    va_end(aq);
    va_end(ap);
}

typedef struct row {
    const char *id, *name, *proven;
    double ns;           /* < 0: not timed */
    double cpu;          /* the same in thread CPU time */
    const acc *ex;       /* 0: no excess measured */
    int exact_ref;       /* the GMP reference: excess 0 by definition */
    double vs_memcpy;    /* < 0: none */
    char note[512];
    int proven_code;     /* for the plot: 1 proven, 0 not, 2 exact */
    int plot;
    int novs;            /* no "vs row 2" (other inputs than row 2's) */
} row;

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

static void fmt_num(char *s, size_t sz, double v)
{
    if (v != v) snprintf(s, sz, "-");
    else if (v == 0.0) snprintf(s, sz, "0");
    else if (fabs(v) >= 1e5 || fabs(v) < 1e-2) snprintf(s, sz, "%.3g", v);
    else snprintf(s, sz, "%.2f", v);
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

static void usage(void)
{
    fprintf(stderr, "usage: bench [-n N] [-r R] [-calls C] [-exact NE] [-gmp NG] "
                    "[-cache NC] [-big NB] [-scene NS] [-seed S] [-o DIR]\n");
    exit(2);
}

int main(int argc, char **argv)
{
    size_t n = 20000, ne = 20000, ng = 2000, nc = 1000, nb = 4000000, nscene = (size_t)-1;
    long calls = 200000;
    int R = 11, i, cores;
    unsigned long seed = 20240501;
    const char *dir = "build/bench-out";
    bench_ctx b;
    xu_rng rng;
    size_t k;
    char model[256], path[1200], loadavg[128] = "(unknown)";
    row rows[32];
    /* the scene rows */
    acc ex_sg, ex_sc, ex_pc[5], ex_pg[5];
    long sc_looser = 0, sc_tighter = 0, sc_fin = 0, sc_infdiff = 0, sc_corner_fail = 0;
    long sc_corner_checked = 0, sc_mismatch = 0;
    size_t nse = 0, nsc = 0;
    double t_sg = -1, t_sc = -1, c_sg = -1, c_sc = -1, t_sgc = -1, t_scc = -1, c_sgc = -1, c_scc = -1;
    double t_pg[5], t_pc[5], c_pg[5], c_pc[5];
    int nrows = 0;
    acc ex_box[7], ex_sph, ex_sphbox;   /* ex_box[5] tight, [6] batch */
    opt_acc opt_tight, opt_cbx;
    long batch_diff = 0;
    double volratio = 0.0;
    double ns_arvo;
    long bad_timed, conv_bad;
    FILE *f;

    for (i = 1; i < argc; i++) {
        const char *o = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : 0;
        if (!v) usage();
        if (!strcmp(o, "-n")) n = strtoul(v, 0, 10);
        else if (!strcmp(o, "-r")) R = atoi(v);
        else if (!strcmp(o, "-calls")) calls = atol(v);
        else if (!strcmp(o, "-exact")) ne = strtoul(v, 0, 10);
        else if (!strcmp(o, "-gmp")) ng = strtoul(v, 0, 10);
        else if (!strcmp(o, "-cache")) nc = strtoul(v, 0, 10);
        else if (!strcmp(o, "-big")) nb = strtoul(v, 0, 10);
        else if (!strcmp(o, "-scene")) nscene = strtoul(v, 0, 10);
        else if (!strcmp(o, "-seed")) seed = strtoul(v, 0, 10);
        else if (!strcmp(o, "-o")) dir = v;
        else usage();
        i++;
    }
    if (n < 1 || R < 1 || R > MAXR || calls < 1) usage();
    if (ne > n) ne = n;
    if (ng > n) ng = n;
    if (nb > 0 && nc > nb) nc = nb;

    /* ---- inputs ---- */
    memset(&b, 0, sizeof b);
    b.n = n;
    b.ngmp = ng;
    b.a = xmalloc(n * sizeof *b.a);
    b.in = xmalloc(n * sizeof *b.in);
    b.cin_cbx = xmalloc(n * sizeof *b.cin_cbx);
    b.cin_rn = xmalloc(n * sizeof *b.cin_rn);
    b.o_naive = xmalloc(n * sizeof(cbx_box));
    b.o_arvo = xmalloc(n * sizeof(cbx_box));
    b.o_cbx = xmalloc(n * sizeof(cbx_box));
    b.o_sph = xmalloc(n * sizeof(cbx_box));
    b.o_sphbox = xmalloc(n * sizeof(cbx_box));
    b.o_tight = xmalloc(n * sizeof(cbx_box));
    b.o_batch = xmalloc(n * sizeof(cbx_box));
    b.o_cbx1 = xmalloc(n * sizeof(cbx_box));
    b.co_cbx = xmalloc(n * sizeof(cbx_cbox));
    b.co_rn = xmalloc(n * sizeof(cbx_cbox));
    rng.s = seed;
    for (k = 0; k < n; k++) {
        gen_case(&rng, &b.a[k], &b.in[k]);
        if (cbx_box_to_cbox(&b.in[k], &b.cin_cbx[k]) != CBX_OK) b.bad++;
        ref_box_to_cbox(&b.in[k], &b.cin_rn[k]);
    }
    xu_init(&b.x);
    b.nt = nb;
    if (nb > 0) {
        b.ta = xmalloc(nb * sizeof *b.ta);
        b.tin = xmalloc(nb * sizeof *b.tin);
        b.tout = xmalloc(nb * sizeof *b.tout);
        b.mdst = xmalloc(nb * (sizeof(cbx_affine) + 2 * sizeof(cbx_box)));
        rng.s = seed + 1;
        for (k = 0; k < nb; k++) gen_case(&rng, &b.ta[k], &b.tin[k]);
    }
    /* the scene (rows S): classified here, untimed */
    if (nscene == (size_t)-1) nscene = nb > 0 ? nb / 4 : n;
    b.ns = nscene;
    if (b.ns > 0) {
        size_t fill[5];
        int c;
        b.sa = xmalloc(b.ns * sizeof *b.sa);
        b.sin = xmalloc(b.ns * sizeof *b.sin);
        b.so_g = xmalloc(b.ns * sizeof *b.so_g);
        b.so_c = xmalloc(b.ns * sizeof *b.so_c);
        b.scls = xmalloc(b.ns * sizeof *b.scls);
        b.pa = xmalloc(b.ns * sizeof *b.pa);
        b.pin = xmalloc(b.ns * sizeof *b.pin);
        b.po = xmalloc(b.ns * sizeof *b.po);
        b.pcls = xmalloc(b.ns * sizeof *b.pcls);
        rng.s = seed + 2;
        for (k = 0; k < b.ns; k++) {
            cbx_class meant = gen_scene_inst(&rng, &b.sa[k], &b.sin[k]);
            b.scls[k] = cbx_classify(&b.sa[k]);
            sc_mismatch += b.scls[k] != meant;
            b.ns_cnt[b.scls[k]]++;
        }
        b.ns_off[0] = 0;
        for (c = 0; c < 5; c++) {
            b.ns_off[c + 1] = b.ns_off[c] + b.ns_cnt[c];
            fill[c] = b.ns_off[c];
        }
        for (k = 0; k < b.ns; k++) {
            size_t d = fill[b.scls[k]]++;
            b.pa[d] = b.sa[k];
            b.pin[d] = b.sin[k];
            b.pcls[d] = b.scls[k];
        }
    }
    conv_bad = b.bad;
    b.bad = 0;

    /* ---- timed rows ---- */
    {
        long P = passes_for(calls, n);
        double t_naive, t_arvo, t_cbx, t_cbxc, t_arvoc, t_sph, t_sphbox, t_gmp;
        double t_tight, t_batch, t_cbx1;
        double t_tc = -1, t_mc = -1, t_tb = -1, t_mb = -1;
        double t_tcb = -1, t_mcb = -1, t_tbb = -1, t_mbb = -1;
        double c_naive, c_arvo, c_cbx, c_cbxc, c_arvoc, c_sph, c_sphbox, c_gmp;
        double c_tight, c_batch, c_cbx1;
        double c_tc = -1, c_mc = -1, c_tb = -1, c_mb = -1;
        double c_tcb = -1, c_mcb = -1, c_tbb = -1, c_mbb = -1;
        t_naive = time_kernel(&b, k_naive, n, P, R, b.o_naive, n * sizeof(cbx_box), &c_naive);
        t_arvo = time_kernel(&b, k_arvo, n, P, R, b.o_arvo, n * sizeof(cbx_box), &c_arvo);
        t_cbx = time_kernel(&b, k_cbx, n, P, R, b.o_cbx, n * sizeof(cbx_box), &c_cbx);
        t_tight = time_kernel(&b, k_tight, n, P, R, b.o_tight, n * sizeof(cbx_box), &c_tight);
        t_batch = time_kernel(&b, k_batch, n, P, R, b.o_batch, n * sizeof(cbx_box), &c_batch);
        t_cbx1 = time_kernel(&b, k_cbx1, n, P, R, b.o_cbx1, n * sizeof(cbx_box), &c_cbx1);
        t_cbxc = time_kernel(&b, k_cbxc, n, P, R, b.co_cbx, n * sizeof(cbx_cbox), &c_cbxc);
        t_arvoc = time_kernel(&b, k_arvoc, n, P, R, b.co_rn, n * sizeof(cbx_cbox), &c_arvoc);
        t_sph = time_kernel(&b, k_sph, n, P, R, b.o_sph, n * sizeof(cbx_box), &c_sph);
        t_sphbox = time_kernel(&b, k_sphbox, n, P, R, b.o_sphbox, n * sizeof(cbx_box), &c_sphbox);
        t_gmp = time_kernel(&b, k_gmp, ng, 1, R, b.o_arvo, 0, &c_gmp);
        if (nb > 0) {
            long Pc = passes_for(calls, nc), Pb = passes_for(calls, nb);
            size_t pb = sizeof(cbx_affine) + 2 * sizeof(cbx_box);
            t_tc = time_kernel(&b, k_tp, nc, Pc, R, b.tout, nc * sizeof(cbx_box), &c_tc);
            t_mc = time_kernel(&b, k_memcpy, nc, Pc, R, b.mdst, nc * pb, &c_mc);
            t_tb = time_kernel(&b, k_tp, nb, Pb, R, b.tout, nb * sizeof(cbx_box), &c_tb);
            t_mb = time_kernel(&b, k_memcpy, nb, Pb, R, b.mdst, nb * pb, &c_mb);
            t_tcb = time_kernel(&b, k_tp_batch, nc, Pc, R, b.tout, nc * sizeof(cbx_box), &c_tcb);
            t_mcb = time_kernel(&b, k_memcpy_boxes, nc, Pc, R, b.mdst, nc * 2 * sizeof(cbx_box), &c_mcb);
            t_tbb = time_kernel(&b, k_tp_batch, nb, Pb, R, b.tout, nb * sizeof(cbx_box), &c_tbb);
            t_mbb = time_kernel(&b, k_memcpy_boxes, nb, Pb, R, b.mdst, nb * 2 * sizeof(cbx_box), &c_mbb);
        }
        if (b.ns > 0) {
            long Ps = passes_for(calls, b.ns);
            int c;
            nsc = nc < b.ns ? nc : b.ns;
            t_sg = time_kernel(&b, k_scene_gen, b.ns, Ps, R, b.so_g, b.ns * sizeof(cbx_box), &c_sg);
            t_sc = time_kernel(&b, k_scene_as, b.ns, Ps, R, b.so_c, b.ns * sizeof(cbx_box), &c_sc);
            t_sgc = time_kernel(&b, k_scene_gen, nsc, passes_for(calls, nsc), R, b.so_g,
                                nsc * sizeof(cbx_box), &c_sgc);
            t_scc = time_kernel(&b, k_scene_as, nsc, passes_for(calls, nsc), R, b.so_c,
                                nsc * sizeof(cbx_box), &c_scc);
            for (c = 0; c < 5; c++) {
                size_t m = b.ns_cnt[c];
                b.cur = c;
                t_pg[c] = time_kernel(&b, k_cls_gen, m, passes_for(calls, m), R,
                                      b.po + b.ns_off[c], m * sizeof(cbx_box), &c_pg[c]);
                t_pc[c] = time_kernel(&b, k_cls_as, m, passes_for(calls, m), R,
                                      b.po + b.ns_off[c], m * sizeof(cbx_box), &c_pc[c]);
            }
            /* the last full runs wrote every output: S into so_g, Sc into so_c
             * (the in-cache runs rewrote the first nsc with the same values) */
        }
        bad_timed = b.bad;
        ns_arvo = t_arvo;

        /* ---- exact measurement (untimed), on the first ne cases ---- */
        {
            ex_scratch e;
            int r;
            mpz_inits(e.gap, e.v, e.w, e.t, (mpz_ptr)0);
            for (i = 0; i < 7; i++) acc_init(&ex_box[i]);
            memset(&opt_tight, 0, sizeof opt_tight);
            memset(&opt_cbx, 0, sizeof opt_cbx);
            for (k = 0; k < ne; k++)
                for (r = 0; r < 3; r++) {
                    xu_row_bounds(&b.x, &b.a[k], &b.in[k], r);
                    record_box(&b.x, &e, &ex_box[0], b.o_naive[k].lo[r], b.o_naive[k].hi[r]);
                    record_box(&b.x, &e, &ex_box[1], b.o_arvo[k].lo[r], b.o_arvo[k].hi[r]);
                    record_box(&b.x, &e, &ex_box[2], b.o_cbx[k].lo[r], b.o_cbx[k].hi[r]);
                    record_cbox(&b.x, &e, &ex_box[3], b.co_cbx[k].c[r], b.co_cbx[k].h[r]);
                    record_cbox(&b.x, &e, &ex_box[4], b.co_rn[k].c[r], b.co_rn[k].h[r]);
                    record_box(&b.x, &e, &ex_box[5], b.o_tight[k].lo[r], b.o_tight[k].hi[r]);
                    if (isfinite(b.o_tight[k].lo[r]) && isfinite(b.o_tight[k].hi[r]))
                        record_opt(&b.x, &opt_tight, b.o_tight[k].lo[r], b.o_tight[k].hi[r]);
                    record_opt(&b.x, &opt_cbx, b.o_cbx[k].lo[r], b.o_cbx[k].hi[r]);
                    /* the batch row: the first map for every box */
                    xu_row_bounds(&b.x, &b.a[0], &b.in[k], r);
                    record_box(&b.x, &e, &ex_box[6], b.o_batch[k].lo[r], b.o_batch[k].hi[r]);
                }
            for (k = 0; k < n; k++) /* bit-identical to the loop of row 3b's note */
                batch_diff += memcmp(&b.o_batch[k], &b.o_cbx1[k], sizeof(cbx_box)) != 0;
            /* the scene: never looser than the general kernel (all), exact
             * excess and containment (first ne), mpq corners (first ng) */
            acc_init(&ex_sg);
            acc_init(&ex_sc);
            for (i = 0; i < 5; i++) {
                acc_init(&ex_pc[i]);
                acc_init(&ex_pg[i]);
            }
            for (k = 0; k < b.ns; k++) {
                int j;
                for (j = 0; j < 6; j++) {
                    double eg = j < 3 ? b.so_g[k].lo[j] : b.so_g[k].hi[j - 3];
                    double ec = j < 3 ? b.so_c[k].lo[j] : b.so_c[k].hi[j - 3];
                    if (!isfinite(eg) || !isfinite(ec)) {
                        sc_infdiff += memcmp(&eg, &ec, sizeof eg) != 0;
                    } else {
                        sc_fin++;
                        if (j < 3 ? ec < eg : ec > eg) sc_looser++;
                        else if (ec != eg) sc_tighter++;
                    }
                }
            }
            nse = ne < b.ns ? ne : b.ns;
            for (k = 0; k < nse; k++) {
                int c = (int)b.scls[k];
                for (r = 0; r < 3; r++) {
                    xu_row_bounds(&b.x, &b.sa[k], &b.sin[k], r);
                    record_box(&b.x, &e, &ex_sg, b.so_g[k].lo[r], b.so_g[k].hi[r]);
                    record_box(&b.x, &e, &ex_sc, b.so_c[k].lo[r], b.so_c[k].hi[r]);
                    record_box(&b.x, &e, &ex_pg[c], b.so_g[k].lo[r], b.so_g[k].hi[r]);
                    record_box(&b.x, &e, &ex_pc[c], b.so_c[k].lo[r], b.so_c[k].hi[r]);
                    if (k < ng) {
                        sc_corner_checked++;
                        sc_corner_fail += xu_corner_failures(&b.x, &b.sa[k], &b.sin[k], r,
                                                             b.so_c[k].lo[r], b.so_c[k].hi[r]) != 0;
                    }
                }
            }
            mpz_clears(e.gap, e.v, e.w, e.t, (mpz_ptr)0);
            acc_init(&ex_sph);
            acc_init(&ex_sphbox);
            measure_sphere(&b, ne, &ex_sph, &ex_sphbox, &volratio);
        }

#define ADDROW(ID, NAME, NS, EX, PROV, PCODE) do { \
            row *w_ = &rows[nrows++]; memset(w_, 0, sizeof *w_); \
            w_->id = ID; w_->name = NAME; w_->ns = t_##NS; w_->cpu = c_##NS; w_->ex = EX; \
            w_->proven = PROV; w_->proven_code = PCODE; w_->vs_memcpy = -1.0; \
            w_->plot = 1; } while (0)
        ADDROW("1", "naive 8 corners, RN (pbrt, Embree)", naive, &ex_box[0], "no", 0);
        ADDROW("2", "Arvo interval, RN (cglm, Godot)", arvo, &ex_box[1], "no", 0);
        ADDROW("3", "certbox `cbx_transform_box`", cbx, &ex_box[2], "yes", 1);
        snprintf(rows[nrows - 1].note, sizeof rows[0].note,
                 "%ld of %ld ends not the tightest double: max %.0f, mean %.2f doubles away",
                 opt_cbx.off, opt_cbx.ends, opt_cbx.max_off,
                 opt_cbx.ends ? opt_cbx.sum_off / (double)opt_cbx.ends : 0.0);
        ADDROW("3t", "certbox tight `cbx_transform_box_tight`", tight, &ex_box[5], "yes (EFTs trusted)", 1);
        snprintf(rows[nrows - 1].note, sizeof rows[0].note,
                 "%s%ld of %ld ends not the tightest double (RD/RU of the exact end): max %.0f, "
                 "mean %.2f ulps beyond it", opt_tight.off ? "**" : "", opt_tight.off,
                 opt_tight.ends, opt_tight.max_off,
                 opt_tight.ends ? opt_tight.sum_off / (double)opt_tight.ends : 0.0);
        if (opt_tight.off) strcat(rows[nrows - 1].note, "**");
        ADDROW("3b", "certbox batch `cbx_transform_boxes`", batch, &ex_box[6], "yes", 1);
        snprintf(rows[nrows - 1].note, sizeof rows[0].note,
                 "one call over the %lu boxes, all under the first map; a loop of "
                 "`cbx_transform_box` over the same boxes and map: %.2f ns/box; output %s",
                 (unsigned long)n, t_cbx1,
                 batch_diff ? "DIFFERS from that loop's" : "bit-identical to that loop's");
        (void)c_cbx1;
        ADDROW("4", "certbox `cbx_transform_cbox`", cbxc, &ex_box[3], "yes", 1);
        snprintf(rows[nrows - 1].note, sizeof rows[0].note,
                 "input from `cbx_box_to_cbox` (untimed); excess against the original box, "
                 "so it includes the conversion's widening");
        ADDROW("5", "Arvo center/half, RN", arvoc, &ex_box[4], "no", 0);
        snprintf(rows[nrows - 1].note, sizeof rows[0].note,
                 "input (lo+hi)/2, (hi-lo)/2 in RN (untimed)");
        ADDROW("6a", "sphere: certbox `cbx_sphere_box`", sph, &ex_sph, "yes", 1);
        snprintf(rows[nrows - 1].note, sizeof rows[0].note,
                 "exact dual-quadric bound; units u(\\|t\\|+sqrt s)+eta");
        ADDROW("6b", "sphere: Arvo on [-1,1]^3 (`cbx_transform_box`)", sphbox, &ex_sphbox, "yes", 1);
        snprintf(rows[nrows - 1].note, sizeof rows[0].note,
                 "vs the exact sphere bound; mean volume ratio to 6a: %.3f", volratio);
        ADDROW("7", "GMP exact (`xu_row_bounds` x 3)", gmp, (const acc *)0, "n/a (exact)", 2);
        rows[nrows - 1].exact_ref = 1;
        snprintf(rows[nrows - 1].note, sizeof rows[0].note, "first %lu cases; the reference",
                 (unsigned long)ng);
        if (nb > 0) {
            size_t pb = sizeof(cbx_affine) + 2 * sizeof(cbx_box);
            ADDROW("T1", "throughput `cbx_transform_box`, in cache", tc, (const acc *)0, "yes", 1);
            rows[nrows - 1].plot = 0;
            rows[nrows - 1].vs_memcpy = t_tc / t_mc;
            snprintf(rows[nrows - 1].note, sizeof rows[0].note,
                     "%lu cases, %.0f KB in+out; memcpy %.2f ns/case (%.1f GB/s)",
                     (unsigned long)nc, (double)(nc * pb) / 1e3, t_mc, (double)pb / t_mc);
            (void)c_mc;
            ADDROW("T2", "throughput `cbx_transform_box`, large array", tb, (const acc *)0, "yes", 1);
            rows[nrows - 1].plot = 0;
            rows[nrows - 1].vs_memcpy = t_tb / t_mb;
            snprintf(rows[nrows - 1].note, sizeof rows[0].note,
                     "%lu cases, %.0f MB in+out (out of cache if above L3); memcpy %.2f ns/case (%.1f GB/s)",
                     (unsigned long)nb, (double)(nb * pb) / 1e6, t_mb, (double)pb / t_mb);
            (void)c_mb;
            ADDROW("T1b", "throughput `cbx_transform_boxes`, in cache", tcb, (const acc *)0, "yes", 1);
            rows[nrows - 1].plot = 0;
            rows[nrows - 1].vs_memcpy = t_tcb / t_mcb;
            snprintf(rows[nrows - 1].note, sizeof rows[0].note,
                     "one call over the T1 boxes under one map; %lu cases, %.0f KB in+out; "
                     "memcpy %.2f ns/case (%.1f GB/s)", (unsigned long)nc,
                     (double)(nc * 2 * sizeof(cbx_box)) / 1e3, t_mcb,
                     (double)(2 * sizeof(cbx_box)) / t_mcb);
            (void)c_mcb;
            ADDROW("T2b", "throughput `cbx_transform_boxes`, large array", tbb, (const acc *)0, "yes", 1);
            rows[nrows - 1].plot = 0;
            rows[nrows - 1].vs_memcpy = t_tbb / t_mbb;
            snprintf(rows[nrows - 1].note, sizeof rows[0].note,
                     "one call over the T2 boxes under one map; %lu cases, %.0f MB in+out; "
                     "memcpy %.2f ns/case (%.1f GB/s)", (unsigned long)nb,
                     (double)(nb * 2 * sizeof(cbx_box)) / 1e6, t_mbb,
                     (double)(2 * sizeof(cbx_box)) / t_mbb);
            (void)c_mbb;
        }
        if (b.ns > 0) {
            row *w;
            int c;
            char mix[160];
            size_t l = 0;
            mix[0] = 0;
            for (c = 4; c >= 0; c--) {
                snprintf(mix + l, sizeof mix - l, "%s%s %.1f%%", c == 4 ? "" : ", ", scls_name[c],
                         100.0 * (double)b.ns_cnt[c] / (double)b.ns);
                l = strlen(mix);
            }
            w = &rows[nrows++];
            memset(w, 0, sizeof *w);
            w->id = "S";
            w->name = "scene: `cbx_transform_box` on every instance (general kernel)";
            w->ns = t_sg; w->cpu = c_sg; w->ex = &ex_sg; w->proven = "yes"; w->proven_code = 1;
            w->vs_memcpy = -1.0; w->novs = 1;
            snprintf(w->note, sizeof w->note, "%lu instances, own map and box each, random order: "
                     "%s; in cache (first %lu): %.2f ns/instance", (unsigned long)b.ns, mix,
                     (unsigned long)nsc, t_sgc);
            w = &rows[nrows++];
            memset(w, 0, sizeof *w);
            w->id = "Sc";
            w->name = "scene: `cbx_transform_box_as`, class stored at build time";
            w->ns = t_sc; w->cpu = c_sc; w->ex = &ex_sc; w->proven = "yes"; w->proven_code = 1;
            w->vs_memcpy = -1.0; w->novs = 1;
            snprintf(w->note, sizeof w->note, "**speed-up S/Sc %.2fx** (CPU %.2fx; in cache, "
                     "repeated passes over %lu instances: %.2f ns/instance, %.2fx); %s%ld of %ld finite ends looser than S%s, %ld tighter, "
                     "%ld infinite ends differ; mpq corners: %ld of %ld axes fail; %ld classes "
                     "differ from the one meant", t_sg / t_sc, c_sg / c_sc, (unsigned long)nsc, t_scc,
                     t_sgc / t_scc,
                     sc_looser ? "**" : "", sc_looser, sc_fin, sc_looser ? "**" : "", sc_tighter,
                     sc_infdiff, sc_corner_fail, sc_corner_checked, sc_mismatch);
            for (c = 4; c >= 0; c--) {
                static char names[5][96];
                acc *pg = &ex_pg[c];
                if (b.ns_cnt[c] == 0) continue;
                w = &rows[nrows++];
                memset(w, 0, sizeof *w);
                snprintf(names[c], sizeof names[c], "scene, %s instances: `cbx_transform_box_as`",
                         scls_name[c]);
                w->id = scls_id[c];
                w->name = names[c];
                w->ns = t_pc[c]; w->cpu = c_pc[c]; w->ex = &ex_pc[c]; w->proven = "yes";
                w->proven_code = 1; w->vs_memcpy = -1.0; w->novs = 1;
                snprintf(w->note, sizeof w->note, "%lu instances (contiguous); `cbx_transform_box` "
                         "on them: %.2f ns/instance (CPU %.2f), **speed-up %.2fx**; general "
                         "kernel's excess there: max %.3g, mean %.3g", (unsigned long)b.ns_cnt[c],
                         t_pg[c], c_pg[c], t_pg[c] / t_pc[c], pg->ends ? pg->max_u : 0.0,
                         pg->ends ? pg->sum_u / (double)pg->ends : 0.0);
            }
        }
#undef ADDROW

        /* ---- the table ---- */
        mkdir_p(dir);
        snprintf(path, sizeof path, "%s/bench.md", dir);
        md_file = fopen(path, "w");
        if (!md_file) fprintf(stderr, "bench: cannot write %s\n", path);
        machine_line(model, sizeof model, &cores);
        f = fopen("/proc/loadavg", "r");
        if (f) {
            if (fgets(loadavg, sizeof loadavg, f)) {
                size_t l = strlen(loadavg);
                if (l && loadavg[l - 1] == '\n') loadavg[l - 1] = 0;
            }
            fclose(f);
        }
        {
            time_t tt = time(0);
            char when[64];
            strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S UTC", gmtime(&tt));
            out("# certbox benchmark (tests/bench.c)\n\n");
            char caches[200];
            cache_line(caches, sizeof caches);
            out("- machine: %s, %d cores%s%s; load average at the end: %s\n", model, cores,
                caches[0] ? "; " : "", caches, loadavg);
            out("- compiler: %s (%s), flags: `%s`\n", BENCH_CC, BENCH_CC_VERSION, BENCH_FLAGS);
            out("- certbox %s; %s; seed %lu\n", CBX_VERSION_STRING, when, seed);
            out("- timing: median of %d runs (after one warm-up run); a run = %ld passes over "
                "%lu cases (throughput: %ld passes over %lu, %ld over %lu); rows 1-6 on the same "
                "%lu random cases, row 7 on the first %lu\n",
                R, P, (unsigned long)n, passes_for(calls, nc), (unsigned long)nc,
                passes_for(calls, nb), (unsigned long)nb, (unsigned long)n, (unsigned long)ng);
            if (b.ns > 0)
                out("- scene rows S*: %lu instances (own map and box each, classified at build "
                    "time, untimed); a run = %ld pass(es) over them (per-class rows: max(1, %ld / "
                    "count) passes over that class's instances; in cache: %ld over the first %lu); "
                    "excess on the first %lu instances, mpq corners of Sc on the first %lu\n",
                    (unsigned long)b.ns, passes_for(calls, b.ns), calls, passes_for(calls, nsc),
                    (unsigned long)nsc, (unsigned long)nse,
                    (unsigned long)(ng < b.ns ? ng : b.ns));
            out("- excess and containment: exact (GMP, MPFR for spheres) on the first %lu cases "
                "(%lu ends per row); units of u S + eta (u = 2^-53, eta = 2^-1074); ulps of the "
                "exact end on the ends with \\|end\\| >= S/4\n\n", (unsigned long)ne,
                (unsigned long)(6 * ne));
        }
        out("| # | method | ns/box | vs row 2 | M boxes/s | CPU ns/box | max excess | mean excess "
            "| max ulps | mean ulps | containment failures | proven | vs memcpy | notes |\n");
        out("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---|\n");
        for (i = 0; i < nrows; i++) {
            row *w = &rows[i];
            char c1[32], c2[32], c3[32], c4[32], c5[32], c6[32], c7[32], c8[32], c9[64], c10[32];
            char note[800];
            fmt_num(c1, sizeof c1, w->ns);
            if (w->ns > 0 && ns_arvo > 0 && !(w->id[0] == 'T') && !w->novs) fmt_num(c2, sizeof c2, w->ns / ns_arvo);
            else snprintf(c2, sizeof c2, "-");
            fmt_num(c3, sizeof c3, w->ns > 0 ? 1e3 / w->ns : NAN);
            fmt_num(c8, sizeof c8, w->cpu > 0 ? w->cpu : NAN);
            snprintf(note, sizeof note, "%s", w->note);
            if (w->ex && w->ex->ends) {
                const acc *s = w->ex;
                fmt_num(c4, sizeof c4, s->max_u);
                fmt_num(c5, sizeof c5, s->sum_u / (double)s->ends);
                fmt_num(c6, sizeof c6, s->nc_ends ? s->max_ulp : NAN);
                fmt_num(c7, sizeof c7, s->nc_ends ? s->sum_ulp / (double)s->nc_ends : NAN);
                snprintf(c9, sizeof c9, "%ld / %ld", s->fails, s->ends);
                if (s->fails) {
                    char c[32];
                    size_t l = strlen(note);
                    fmt_num(c, sizeof c, s->min_u);
                    snprintf(note + l, sizeof note - l, "%sworst end %s units inside",
                             l ? "; " : "", c);
                }
                if (s->cancel) {
                    size_t l = strlen(note);
                    snprintf(note + l, sizeof note - l, "%s%ld ends with \\|end\\| < S/4 left out of ulps",
                             l ? "; " : "", s->cancel);
                }
            } else if (w->exact_ref) {
                snprintf(c4, sizeof c4, "0");
                snprintf(c5, sizeof c5, "0");
                snprintf(c6, sizeof c6, "0");
                snprintf(c7, sizeof c7, "0");
                snprintf(c9, sizeof c9, "0 (exact)");
            } else {
                snprintf(c4, sizeof c4, "-");
                snprintf(c5, sizeof c5, "-");
                snprintf(c6, sizeof c6, "-");
                snprintf(c7, sizeof c7, "-");
                snprintf(c9, sizeof c9, "-");
            }
            if (w->vs_memcpy > 0) snprintf(c10, sizeof c10, "%.2f", w->vs_memcpy);
            else snprintf(c10, sizeof c10, "-");
            out("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n",
                w->id, w->name, c1, c2, c3, c8, c4, c5, c6, c7, c9, w->proven, c10, note);
        }
        if (conv_bad)
            out("\n**%ld `cbx_box_to_cbox` calls did not return CBX_OK**\n", conv_bad);
        if (bad_timed)
            out("\n**%ld certbox calls did not return CBX_OK** (inputs should all be in the domain)\n",
                bad_timed);
        out("\nmax / mean excess: signed (negative = inside the exact image); a proven row "
            "must have 0 containment failures.  Measured once; timings vary with load.\n\n");
        if (md_file) fclose(md_file);

        /* ---- bench.dat for scripts/bench.gp ---- */
        snprintf(path, sizeof path, "%s/bench.dat", dir);
        f = fopen(path, "w");
        if (!f) {
            fprintf(stderr, "bench: cannot write %s\n", path);
        } else {
            fprintf(f, "# certbox bench (tests/bench.c), for scripts/bench.gp: one data block\n"
                       "# per plotted row (blocks separated by two blank lines), each a header\n"
                       "# line (its 6th field is the row's title) and one data line.\n");
            fprintf(f, "# machine: %s, %d cores; %s\n", model, cores, BENCH_CC_VERSION);
            fprintf(f, "# columns: row ns_per_box max_excess y_plotted proven(1 yes, 0 no, 2 exact) label\n");
            fprintf(f, "# y_plotted: max excess, floored at 0.01 for the log scale (exact: 0)\n");
            for (i = 0; i < nrows; i++) {
                row *w = &rows[i];
                double mx = w->ex && w->ex->ends ? w->ex->max_u : 0.0;
                double y = mx < 0.01 ? 0.01 : mx;
                char lab[200];
                size_t p = 0;
                const char *q;
                if (!w->plot) continue;
                for (q = w->name; *q && p + 1 < sizeof lab; q++)
                    if (*q != '`' && *q != '"') lab[p++] = *q;
                lab[p] = 0;
                fprintf(f, "\n\nrow ns_per_box max_excess y_plotted proven \"%s: %s%s\"\n", w->id, lab,
                        w->proven_code == 1 ? " [proven]" : w->proven_code == 2 ? " [exact]" : "");
                fprintf(f, "%s %.6g %.6g %.6g %d \"%s\"\n", w->id, w->ns, mx, y, w->proven_code, w->id);
            }
            fclose(f);
        }
        fprintf(stderr, "bench: wrote %s/bench.md and %s/bench.dat (sink %llx)\n", dir, dir,
                (unsigned long long)bench_sink);
    }
    xu_clear(&b.x);
    {
        long fails = ex_box[2].fails + ex_box[3].fails + ex_sph.fails + ex_sphbox.fails
                     + ex_box[5].fails + ex_box[6].fails;
        long sfails = ex_sg.fails + ex_sc.fails + sc_corner_fail + sc_looser + sc_infdiff;
        if (sfails) {
            fprintf(stderr, "bench: FAILED (scene rows): %ld containment failures (S %ld, Sc %ld), "
                            "%ld axes failing the mpq corners, %ld class-kernel ends looser than "
                            "the general kernel's, %ld infinite ends differing\n",
                    ex_sg.fails + ex_sc.fails, ex_sg.fails, ex_sc.fails, sc_corner_fail,
                    sc_looser, sc_infdiff);
            return 1;
        }
        if (fails || bad_timed || conv_bad || batch_diff) {
            fprintf(stderr, "bench: FAILED: %ld containment failures in certbox rows, "
                            "%ld calls not CBX_OK, %ld batch outputs not bit-identical\n",
                    fails, bad_timed, batch_diff);
            return 1;
        }
    }
    return 0;
}
