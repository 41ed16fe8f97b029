/*
 * The scene tool against exact rational arithmetic (GMP).
 *   test_scene FILE...
 * For every leaf of every scene: the exact product (mpq) of the given
 * double matrices from the leaf's node to the root, at several times s for
 * motion nodes (the same s everywhere, and independent s per node; a
 * keyframes node's slerp in MPFR at 300 bits, as a rational), maps
 *   - every corner of a box leaf inside the world box;
 *   - a sphere or ellipsoid leaf to c' + A p, |p| <= 1, whose exact extent
 *     c'_i -+ sqrt(sum_j A_ij^2) must lie inside the world box (checked
 *     without square roots: d = c'_i - lo_i >= 0 and d^2 >= sum_j A_ij^2).
 * Tightness: world width / exact width (doubles), max and median.
 * Then the error handling: broken scenes must be rejected with the right
 * line number, and the printed %.17g values must parse back exactly.
 * Exit 1 on any failure.
 * This file is the driver (the checks that need the tool's scene.h, main,
 * the order of the suites, the summary); its parts are scene_exact.c (the
 * exact maps) and scene_gen.c (the generated scenes), declared in
 * scene_parts.h and built into build/libtestutil.a.
 */
#include <gmp.h>
#include <mpfr.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scene.h"
#include "exact_util.h"
#include "scene_parts.h"

/* Check one leaf under the exact world map W. */
static void check_leaf(const sc_leaf *L, const qmap *W, stats *st, const char *file, int tight)
{
    mpq_t v, t, lo, hi, d, sum;
    mpq_inits(v, t, lo, hi, d, sum, NULL);
    for (int i = 0; i < 3; i++) {
        mpq_set_d(lo, L->world.lo[i]);
        mpq_set_d(hi, L->world.hi[i]);
        int lofin = isfinite(L->world.lo[i]), hifin = isfinite(L->world.hi[i]);
        if (L->kind == SC_BOX) {
            double emin = HUGE_VAL, emax = -HUGE_VAL;
            for (int c = 0; c < 8; c++) {
                mpq_set(v, W->m[i][3]);
                for (int j = 0; j < 3; j++) {
                    mpq_set_d(t, L->v[((c >> j) & 1) ? 3 + j : j]);
                    mpq_mul(t, t, W->m[i][j]);
                    mpq_add(v, v, t);
                }
                st->checks++;
                if ((lofin && mpq_cmp(v, lo) < 0) || (hifin && mpq_cmp(v, hi) > 0)) {
                    st->fails++;
                    fprintf(stderr, "FAIL %s: leaf %s axis %d corner %d outside [%a, %a]\n",
                            file, L->name, i, c, L->world.lo[i], L->world.hi[i]);
                }
                double vd = mpq_get_d(v);
                if (vd < emin) emin = vd;
                if (vd > emax) emax = vd;
            }
            if (tight && lofin && hifin && emax > emin)
                sct_add_ratio(st, (L->world.hi[i] - L->world.lo[i]) / (emax - emin));
        } else {
            /* A = W_lin R diag(r); c' = W c + T */
            double r[3], R[3][3];
            if (L->kind == SC_SPHERE) {
                r[0] = r[1] = r[2] = L->v[3];
                for (int a = 0; a < 3; a++)
                    for (int b = 0; b < 3; b++)
                        R[a][b] = a == b;
            } else {
                for (int a = 0; a < 3; a++) r[a] = L->v[3 + a];
                for (int a = 0; a < 3; a++)
                    for (int b = 0; b < 3; b++)
                        R[a][b] = L->v[6 + 3 * a + b];
            }
            mpq_set_ui(sum, 0, 1);
            for (int j = 0; j < 3; j++) {
                mpq_set_ui(v, 0, 1);
                for (int k = 0; k < 3; k++) {
                    mpq_set_d(t, R[k][j]);
                    mpq_mul(t, t, W->m[i][k]);
                    mpq_add(v, v, t);
                }
                mpq_set_d(t, r[j]);
                mpq_mul(v, v, t);
                mpq_mul(v, v, v);
                mpq_add(sum, sum, v);
            }
            mpq_set(v, W->m[i][3]);
            for (int j = 0; j < 3; j++) {
                mpq_set_d(t, L->v[j]);
                mpq_mul(t, t, W->m[i][j]);
                mpq_add(v, v, t);
            }
            st->checks++;
            int bad = 0;
            if (lofin) {
                mpq_sub(d, v, lo);
                if (mpq_sgn(d) < 0) bad = 1;
                mpq_mul(d, d, d);
                if (mpq_cmp(d, sum) < 0) bad = 1;
            }
            if (hifin) {
                mpq_sub(d, hi, v);
                if (mpq_sgn(d) < 0) bad = 1;
                mpq_mul(d, d, d);
                if (mpq_cmp(d, sum) < 0) bad = 1;
            }
            if (bad) {
                st->fails++;
                fprintf(stderr, "FAIL %s: leaf %s axis %d: exact ellipsoid extent outside [%a, %a]\n",
                        file, L->name, i, L->world.lo[i], L->world.hi[i]);
            }
            double ew = 2.0 * sqrt(mpq_get_d(sum));
            if (tight && lofin && hifin && ew > 0)
                sct_add_ratio(st, (L->world.hi[i] - L->world.lo[i]) / ew);
        }
    }
    mpq_clears(v, t, lo, hi, d, sum, NULL);
}


/* The exact map of node n (its operations composed, motion at time s). */
static void node_map(const scene *s, int n, const mpq_t tm, qmap *out)
{
    const sc_node *N = &s->nodes[n];
    qmap a, r;
    sct_qm_init(&a);
    sct_qm_init(&r);
    if (N->trs) {
        sct_trs_map(&s->keys[N->trs - 1], &s->keys[N->trs], N->nlerp, tm, out);
    } else if (N->motion) {
        sct_qm_from(out, &s->ops[N->first].a, &s->ops[N->first + 1].a, tm);
    } else {
        mpq_t zero;
        mpq_init(zero);
        sct_qm_ident(out);
        for (int q = N->first; q < N->first + N->n; q++) {   /* out = out o op */
            sct_qm_from(&a, &s->ops[q].a, NULL, zero);
            sct_qm_compose(&r, out, &a);
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 4; j++)
                    mpq_set(out->m[i][j], r.m[i][j]);
        }
        mpq_clear(zero);
    }
    sct_qm_clear(&a);
    sct_qm_clear(&r);
}

/* The exact world map of node n at the times tm (its ancestors' maps
 * composed with its own: world[n] = world[parent] o map(n)), computed once
 * per node and time sample (done[m]: world[m] holds this sample's map).
 * The same exact product as composing from the leaf's node up to the root
 * (rational matrix products are associative), without recomposing the
 * shared part of every leaf's path (2026-11-30: the deep generated scenes
 * spent most of test_scene's time there). */
static const qmap *world_map(const scene *s, int n, mpq_t *tm, qmap *world,
                             char *done, int *path, qmap *N)
{
    int top = 0;
    for (int m = n; m >= 0 && !done[m]; m = s->nodes[m].parent)
        path[top++] = m;
    while (top > 0) {
        int m = path[--top], p = s->nodes[m].parent;
        if (p < 0) {
            node_map(s, m, tm[m], &world[m]);
        } else {
            node_map(s, m, tm[m], N);
            sct_qm_compose(&world[m], &world[p], N);
        }
        done[m] = 1;
    }
    return &world[n];
}

static xu_rng rng = {88172645463325252u};
static int collect_tightness = 1;   /* 0: generated scenes (no tightness figure) */

/* Check a parsed scene (file: its name in messages); frees it. */
static int check_scene(scene *sp, const char *file, stats *st, long *times_total)
{
    scene s = *sp;
    scene_eval(&s);
    int has_motion = 0;
    for (int n = 0; n < s.nn; n++) has_motion |= s.nodes[n].motion;
    /* time samples: shared s in {0, 1/4, 1/3, 1/2, 1}, then 8 draws with an
     * independent random s per node */
    static const long num[5] = {0, 1, 1, 1, 1}, den[5] = {1, 4, 3, 2, 1};
    int ntimes = has_motion ? 13 : 1;
    mpq_t *tm = malloc((size_t)(s.nn > 0 ? s.nn : 1) * sizeof *tm);
    for (int n = 0; n < s.nn; n++) mpq_init(tm[n]);
    size_t nn = (size_t)(s.nn > 0 ? s.nn : 1);
    qmap *world = malloc(nn * sizeof *world), N;
    char *done = malloc(nn);
    int *path = malloc(nn * sizeof *path);
    if (!world || !done || !path) {
        fprintf(stderr, "FAIL %s: out of memory\n", file);
        exit(1);
    }
    for (int n = 0; n < s.nn; n++) sct_qm_init(&world[n]);
    sct_qm_init(&N);
    for (int k = 0; k < ntimes; k++) {
        for (int n = 0; n < s.nn; n++) {
            if (k < 5) mpq_set_si(tm[n], num[k], (unsigned long)den[k]);
            else mpq_set_ui(tm[n], (unsigned long)xu_rng_int(&rng, 0, 1000), 1000);
            mpq_canonicalize(tm[n]);
        }
        (*times_total)++;
        memset(done, 0, nn);
        for (int l = 0; l < s.nl; l++) {
            const sc_leaf *L = &s.leaves[l];
            check_leaf(L, world_map(&s, L->node, tm, world, done, path, &N),
                       st, file, collect_tightness && k == 0 && !has_motion);
        }
    }
    st->leaves += s.nl;
    for (int n = 0; n < s.nn; n++) mpq_clear(tm[n]);
    free(tm);
    for (int n = 0; n < s.nn; n++) sct_qm_clear(&world[n]);
    free(world); free(done); free(path);
    sct_qm_clear(&N);
    /* every leaf proven, and the scene box the union */
    int bad = 0;
    for (int l = 0; l < s.nl; l++) {
        if (s.leaves[l].st != CBX_OK) {
            fprintf(stderr, "FAIL %s: leaf %s status %s\n", file, s.leaves[l].name,
                    cbx_status_name(s.leaves[l].st));
            bad = 1;
        }
        for (int j = 0; j < 3; j++)
            if (s.leaves[l].world.lo[j] < s.world.lo[j] || s.leaves[l].world.hi[j] > s.world.hi[j]) {
                fprintf(stderr, "FAIL %s: scene box does not hold leaf %s\n", file, s.leaves[l].name);
                bad = 1;
            }
        /* the tool prints %.17g: it must parse back to the same double */
        for (int j = 0; j < 3; j++) {
            char b[64];
            double x[2] = {s.leaves[l].world.lo[j], s.leaves[l].world.hi[j]};
            for (int e = 0; e < 2; e++) {
                snprintf(b, sizeof b, "%.17g", x[e]);
                if (strtod(b, NULL) != x[e]) {
                    fprintf(stderr, "FAIL %s: %.17g does not round-trip\n", file, x[e]);
                    bad = 1;
                }
            }
        }
    }
    scene_free(&s);
    return bad;
}

static int check_file(const char *file, stats *st, long *times_total)
{
    scene s;
    char err[512];
    if (scene_load(&s, file, err, sizeof err) != 0) {
        fprintf(stderr, "FAIL %s: %s\n", err, "scene not loaded");
        return 1;
    }
    return check_scene(&s, file, st, times_total);
}

/* Parse a scene from text and check it like a file. */
static int check_text(const char *text, const char *name, stats *st, long *times_total)
{
    scene s;
    char err[512];
    if (scene_parse(&s, text, name, err, sizeof err) != 0) {
        fprintf(stderr, "FAIL %s: %s\n", err, "scene not parsed");
        return 1;
    }
    return check_scene(&s, name, st, times_total);
}


/* The level-by-level evaluation (each leaf walked to the root through the
 * kernels, as the tool did before it composed deep chains): quadratic, so
 * for the random deep scenes only.  The tool's boxes must lie inside. */
static void ref_eval(const scene *s, cbx_box *out)
{
    for (int k = 0; k < s->nl; k++) {
        const sc_leaf *L = &s->leaves[k];
        cbx_box b;
        if (L->kind == SC_BOX) {
            for (int j = 0; j < 3; j++) { b.lo[j] = L->v[j]; b.hi[j] = L->v[3 + j]; }
        } else {
            double c[3], rr[3], R[3][3];
            for (int j = 0; j < 3; j++) c[j] = L->v[j];
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    R[i][j] = L->kind == SC_SPHERE ? i == j : L->v[6 + 3 * i + j];
            for (int j = 0; j < 3; j++) rr[j] = L->kind == SC_SPHERE ? L->v[3] : L->v[3 + j];
            (void)cbx_ellipsoid_box(c, rr, (const double (*)[3])R, &b);
        }
        for (int n = L->node; n >= 0; n = s->nodes[n].parent) {
            const sc_node *N = &s->nodes[n];
            if (N->trs) {
                cbx_box o;
                (void)cbx_motion_trs_box(&s->keys[N->trs - 1], &s->keys[N->trs], N->nlerp ? CBX_NLERP : CBX_SLERP,
                                         0.0, 1.0, SC_TRS_DEPTH, &b, &o);
                b = o;
            } else if (N->motion) {
                cbx_box o;
                (void)cbx_motion_box(&s->ops[N->first].a, &s->ops[N->first + 1].a, &b, &o);
                b = o;
            } else {
                for (int q = N->first + N->n - 1; q >= N->first; q--)
                    (void)cbx_transform_box_as(&s->ops[q].a, (cbx_class)s->ops[q].cls, &b, &b);
            }
        }
        out[k] = b;
    }
}

/* Deep scenes: beyond 64 kernel steps a leaf goes on by composed segment
 * maps (and past 64 more motion nodes by a world map).  Each scene: the
 * exact check, and each box against the level-by-level one: identical,
 * tighter, or looser.  Looser fails, except past 128 nested motion nodes
 * (the world map's hull of M0 and M1, the price of linear time there:
 * counted and its largest width ratio printed). */
static int check_deep(stats *st, long *times_total, int *count, long *same, long *tighter,
                      long *looser_hull, double *worst_hull)
{
    /* pm: motion node percentage, or -1 - the gen_tight kind; pb: branch percentage */
    static const struct { int nn, nl, pm, pb, hull, reps; } shape[] = {
        {40, 20, 10, 7, 0, 4},      /* within 64 steps mostly: the level-by-level path */
        {150, 25, 0, 2, 0, 4},      /* no motion: segments only */
        {300, 25, 10, 2, 0, 4},     /* segments and motion nodes */
        {200, 10, 100, 0, 1, 2},    /* a chain of motion nodes: past 128 of them, the world map */
        {6, 40, -1, 0, 0, 4},       /* gen_tight kind 0: nodes of 65 to 90 operations */
        {200, 20, -2, 0, 1, 2},     /* gen_tight kind 1: 200 nested moving translations */
        {3, 100, -3, 0, 0, 6},      /* gen_tight kind 2: nodes of 70 nearly exact operations */
    };
    xu_rng r = {0x5eed5ce7e5ull};
    sbuf b = {NULL, 0, 0};
    int fails = 0;
    char name[64], err[512];
    for (size_t k = 0; k < sizeof shape / sizeof shape[0]; k++)
        for (int rep = 0; rep < shape[k].reps; rep++) {
            if (shape[k].pm >= 0) sct_gen_deep(&r, &b, shape[k].nn, shape[k].nl, shape[k].pm, shape[k].pb);
            else sct_gen_tight(&r, &b, -1 - shape[k].pm, shape[k].nn, shape[k].nl);
            snprintf(name, sizeof name, "deep-%d-%d-%d#%d", shape[k].nn, shape[k].nl, shape[k].pm, rep);
            scene s;
            if (scene_parse(&s, b.p, name, err, sizeof err) != 0) {
                fprintf(stderr, "FAIL %s\n", err);
                fails++;
                continue;
            }
            scene_eval(&s);
            cbx_box *ref = malloc((size_t)s.nl * sizeof *ref);
            if (!ref) { fprintf(stderr, "out of memory\n"); exit(2); }
            ref_eval(&s, ref);
            for (int l = 0; l < s.nl; l++)
                for (int j = 0; j < 3; j++) {
                    double lo = s.leaves[l].world.lo[j], hi = s.leaves[l].world.hi[j];
                    if (lo == ref[l].lo[j] && hi == ref[l].hi[j]) (*same)++;
                    else if (lo >= ref[l].lo[j] && hi <= ref[l].hi[j]) (*tighter)++;
                    else if (shape[k].hull) {
                        double w = (hi - lo) / (ref[l].hi[j] - ref[l].lo[j]);
                        (*looser_hull)++;
                        if (w > *worst_hull) *worst_hull = w;
                    } else {
                        fprintf(stderr, "FAIL %s: leaf %s axis %d [%a, %a] looser than level by level [%a, %a]\n",
                                name, s.leaves[l].name, j, lo, hi, ref[l].lo[j], ref[l].hi[j]);
                        fails++;
                    }
                }
            free(ref);
            fails += check_scene(&s, name, st, times_total);
            (*count)++;
        }
    free(b.p);
    return fails;
}

/* Linear time: the chain of issue 18 (100,000 nodes of translate 1 0 0,
 * 10,000 boxes on the deepest node) took 31 s; it must now simply finish
 * (the time is the bench's business) with every box exactly checked. */
static int check_long_chain(stats *st, long *times_total, int nodes, int leaves)
{
    sbuf b = {NULL, 0, 0};
    sct_sb_add(&b, "certbox-scene 1\nnode n0\n  translate 1 0 0\n");
    for (int i = 1; i < nodes; i++)
        sct_sb_add(&b, "node n%d n%d\n  translate 1 0 0\n", i, i - 1);
    for (int k = 0; k < leaves; k++)
        sct_sb_add(&b, "box b%d n%d %d 0 0 %d 1 1\n", k, nodes - 1, k, k + 1);
    long c0 = st->checks;
    int fails = check_text(b.p, "chain", st, times_total);
    printf("test_scene: linear time: a %d-node chain of `translate 1 0 0` with %d boxes on its deepest node "
           "evaluated, %ld exact checks, %d failed\n", nodes, leaves, st->checks - c0, fails);
    free(b.p);
    return fails;
}

/* Tiny and huge rotation axes act like the same axis at normal scale: an
 * axis scaled by a power of two gives the same matrix, bit for bit (it was
 * a non-rotation for 2e-162 0 2e-162 and NaN for 1e-170 0 0), and the
 * leaf's box passes the exact containment check. */
static int check_axes(stats *st, long *times_total, int *count)
{
    static const struct { const char *axis, *ref; } ax[] = {
        {"2e-162 0 2e-162", "1 0 1"},
        {"1e-170 0 0", "1 0 0"},
        {"1e300 0 1e300", "1 0 1"},
        {"0 -0x1p-1074 0", "0 -1 0"},
        {"0x1.8p-900 0x1p-899 0", "3 4 0"},
        {"0x1.8p+900 0x1p+901 0", "3 4 0"},
        {"-0x1p-1060 0x1p-1060 0x1p-1061", "-2 2 1"},
    };
    static const char *deg[] = {"30", "-17.5", "90", "1e-300", "123456.789"};
    int fails = 0;
    char text[2][256], err[512];
    for (size_t k = 0; k < sizeof ax / sizeof ax[0]; k++)
        for (size_t d = 0; d < sizeof deg / sizeof deg[0]; d++) {
            scene s[2];
            int ok = 1;
            for (int r = 0; r < 2; r++) {
                snprintf(text[r], sizeof text[r], "certbox-scene 1\nnode a\n  rotate %s %s\nbox b a -1 0.5 2 3 4 5.25\n",
                         r ? ax[k].ref : ax[k].axis, deg[d]);
                if (scene_parse(&s[r], text[r], "axis.scene", err, sizeof err) != 0) {
                    fprintf(stderr, "FAIL axis %s: %s\n", r ? ax[k].ref : ax[k].axis, err);
                    return fails + 1;
                }
                scene_eval(&s[r]);
            }
            ok = memcmp(&s[0].ops[0].a, &s[1].ops[0].a, sizeof s[0].ops[0].a) == 0
                 && memcmp(&s[0].leaves[0].world, &s[1].leaves[0].world, sizeof s[0].leaves[0].world) == 0
                 && s[0].leaves[0].st == CBX_OK;
            if (!ok) {
                fprintf(stderr, "FAIL rotate %s %s: not the matrix and box of rotate %s %s\n",
                        ax[k].axis, deg[d], ax[k].ref, deg[d]);
                fails++;
            }
            scene_free(&s[1]);
            fails += check_scene(&s[0], text[0], st, times_total);
            (*count)++;
        }
    return fails;
}

static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Broken scenes: each must be rejected, naming the expected line. */
static int check_errors(int *count)
{
    static const struct { const char *text; int line; } bad[] = {
        {"", 0},
        {"# only a comment\n", 1},
        {"certbox-scene 2\n", 1},
        {"node a\nbox b a 0 0 0 1 1 1\n", 1},
        {"certbox-scene 1\nnode a\nbox b a 0 0 0 1 1\n", 3},
        {"certbox-scene 1\nnode a\n  translate 1 2\nbox b a 0 0 0 1 1 1\n", 3},
        {"certbox-scene 1\nnode a b\nbox b a 0 0 0 1 1 1\n", 2},
        {"certbox-scene 1\nnode a\nnode a\nbox b a 0 0 0 1 1 1\n", 3},
        {"certbox-scene 1\nnode a\nbox b a 0 0 0 1 1 1\nbox b a 0 0 0 1 1 1\n", 4},
        {"certbox-scene 1\nnode a\nbox b a 1 0 0 0 1 1\n", 3},
        {"certbox-scene 1\nnode a\nbox b a 0 0 0 1 1 1x\n", 3},
        {"certbox-scene 1\nnode a\nbox b a 0 0 0 1 1 inf\n", 3},
        {"certbox-scene 1\nnode a\nbox b a 0 0 0 1 1 nan\n", 3},
        {"certbox-scene 1\nnode a\nsphere b a 0 0 0 -1\n", 3},
        {"certbox-scene 1\nnode a\n  rotate 0 0 0 30\nbox b a 0 0 0 1 1 1\n", 3},
        {"certbox-scene 1\nnode a\n  rotate 1 0 0 1e15\nbox b a 0 0 0 1 1 1\n", 3},
        {"certbox-scene 1\nnode a\n  translate 1 0 0\n  translate 1 0 0\n  motion\n  translate 2 0 0\nbox b a 0 0 0 1 1 1\n", 2},
        {"certbox-scene 1\nnode a\n  motion\n  motion\nbox b a 0 0 0 1 1 1\n", 4},
        {"certbox-scene 1\nnode a\n  translate 1 0 0\n  keyframes 0 0 0 0 0 0 1 1 1 1 0 0 0 0 0 0 1 1 1 1\n", 4},
        {"certbox-scene 1\nnode a\n  keyframes 0 0 0 0 0 0 1 1 1 1 0 0 0 0 0 0 1 1 1 1\n  scale 2 2 2\n", 4},
        {"certbox-scene 1\nnode a\n  keyframes 0 0 0 0 0 0 0 1 1 1 0 0 0 0 0 0 1 1 1 1\n", 3},
        {"certbox-scene 1\nnode a\n  keyframes 0 0 0 0 0 0 1 1 1 1 0 0 0 0 0 0 1 1 1 1 cubic\n", 3},
        {"certbox-scene 1\nnode a\n  keyframes 0 0 0 0 0 0 1 1 1 1 0 0 0 0 0 0 1 1 1 1\n  motion\n", 4},
        {"certbox-scene 1\ntranslate 1 0 0\n", 2},
        {"certbox-scene 1\nnode a\nbox b a 0 0 0 1 1 1\n  translate 1 0 0\n", 4},
        {"certbox-scene 1\nnode a\nfrobnicate\n", 3},
        {"certbox-scene 1\nnode a\nbox b zz 0 0 0 1 1 1\n", 3},
        {"certbox-scene 1\nnode a$\nbox b a 0 0 0 1 1 1\n", 2},
        {"certbox-scene 1\nnode a\n", 2},
        {"certbox-scene 1\nnode a\nellipsoid e a 0 0 0 1 1\n", 3},
    };
    int fails = 0;
    char err[512], want[32];
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        scene s;
        int rc = scene_parse(&s, bad[k].text, "t.scene", err, sizeof err);
        snprintf(want, sizeof want, "t.scene:%d:", bad[k].line);
        if (rc == 0) {
            fprintf(stderr, "FAIL error case %zu accepted\n", k);
            scene_free(&s);
            fails++;
        } else if (strncmp(err, want, strlen(want)) != 0) {
            fprintf(stderr, "FAIL error case %zu: message '%s', expected line %d\n", k, err, bad[k].line);
            fails++;
        } else if (s.nl != 0 || s.nn != 0) {
            fprintf(stderr, "FAIL error case %zu: scene kept after an error\n", k);
            fails++;
        }
        (*count)++;
    }
    /* a long line is refused, not overflowed */
    size_t n = SC_LINE_MAX + 100;
    char *t = malloc(n + 64);
    strcpy(t, "certbox-scene 1\nnode a\n");
    size_t at = strlen(t);
    memset(t + at, ' ', n);
    strcpy(t + at + n, "\n");
    scene s;
    if (scene_parse(&s, t, "t.scene", err, sizeof err) == 0 || strncmp(err, "t.scene:3:", 10) != 0) {
        fprintf(stderr, "FAIL long line not refused at line 3: %s\n", err);
        fails++;
    }
    free(t);
    (*count)++;
    /* a NUL byte is refused naming its line and column (it was "FILE:0:") */
#define NUL_CASE(text, want) {text, sizeof text - 1, want}
    static const struct { const char *text; size_t n; const char *want; } nul[] = {
        NUL_CASE("certbox-scene 1\nnode a\nbox b a\0 0 0 0 1 1 1\n", "t.scene:3: the file contains a NUL byte (column 8)"),
        NUL_CASE("\0certbox-scene 1\n", "t.scene:1: the file contains a NUL byte (column 1)"),
        NUL_CASE("certbox-scene 1\nnode a\nbox b a 0 0 0 1 1 1\n\0", "t.scene:4: the file contains a NUL byte (column 1)"),
    };
#undef NUL_CASE
    for (size_t k = 0; k < sizeof nul / sizeof nul[0]; k++) {
        err[0] = '\0';
        if (scene_parse_buf(&s, nul[k].text, nul[k].n, "t.scene", err, sizeof err) == 0
            || strcmp(err, nul[k].want) != 0) {
            fprintf(stderr, "FAIL NUL case %zu: '%s', expected '%s'\n", k, err, nul[k].want);
            fails++;
        }
        (*count)++;
    }
    return fails;
}

int main(int argc, char **argv)
{
    stats st;
    memset(&st, 0, sizeof st);
    long times = 0;
    int bad = 0;
    if (argc < 2) {
        fprintf(stderr, "usage: test_scene FILE...\n");
        return 2;
    }
    for (int k = 1; k < argc; k++)
        bad |= check_file(argv[k], &st, &times);
    int nerr = 0;
    int efails = check_errors(&nerr);
    /* generated scenes: exact checks, but no tightness figure (that one is
     * the example files') */
    collect_tightness = 0;
    int naxes = 0, ndeep = 0;
    long checks0 = st.checks, dsame = 0, dtight = 0, dhull = 0;
    double whull = 0;
    int afails = check_axes(&st, &times, &naxes);
    printf("test_scene: %d tiny/huge rotation axes (7 axes x 5 angles) the same matrix and box as the axis "
           "at normal scale, %ld exact checks, %d failed\n", naxes, st.checks - checks0, afails);
    checks0 = st.checks;
    int dfails = check_deep(&st, &times, &ndeep, &dsame, &dtight, &dhull, &whull);
    printf("test_scene: %d deep random scenes (up to 300 nodes, motion nodes; past 64 steps composed), "
           "%ld exact checks, %d failed; against level by level: %ld axes identical, %ld tighter, "
           "%ld looser past 128 nested motion nodes (width up to %.3g times)\n",
           ndeep, st.checks - checks0, dfails, dsame, dtight, dhull, whull);
    int cfails = check_long_chain(&st, &times, 100000, 10000);
    int ngen = naxes + ndeep + 1, gfails = afails + dfails + cfails;
    double mx = 0, med = 0;
    if (st.ratios_n) {
        qsort(st.ratios, (size_t)st.ratios_n, sizeof *st.ratios, cmp_d);
        mx = st.ratios[st.ratios_n - 1];
        med = st.ratios[st.ratios_n / 2];
    }
    printf("test_scene: %d files and %d generated scenes, %ld leaves, %ld scene evaluations at sampled times, "
           "%ld exact containment checks, %ld failures\n",
           argc - 1, ngen, st.leaves, times, st.checks, st.fails);
    printf("  check containment %ld leaf-axes checked, %ld failed\n", st.checks, st.fails);
    printf("test_scene: tightness (world width / exact width, static scenes, %ld axes): "
           "max %.6f median %.9f\n", st.ratios_n, mx, med);
    printf("test_scene: %d broken scenes (3 of them with a NUL byte: line and column named), "
           "%d not rejected at the right line\n", nerr, efails);
    free(st.ratios);
    int failed = bad || st.fails || efails || gfails || st.checks == 0;
    printf("%s\n", failed ? "test_scene: FAILED" : "test_scene: passed");
    /* the closing line CI reads: one item per exact check, broken file and generated scene */
    long items = st.checks + nerr + ngen + (argc - 1);
    long nfail = st.fails + efails + gfails + bad + (st.checks == 0);
    printf("%ld passed, %ld failed\n", items - nfail, nfail);
    return failed ? 1 : 0;
}
