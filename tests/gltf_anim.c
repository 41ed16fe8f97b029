/*
 * gltf_anim.c: part of tests/test_gltf.c (gltf_anim.h): the exact image of
 * a box under a node's exact map, and the checks of --animated: the keys
 * read as written (make.py's "extras"), the samplers' exact values (slerp
 * in MPFR), and every mesh instance's box at times spread over each
 * animation.  It needs the tool's headers and jansson: built like
 * tests/gltf_oracle.c (GLTFORACLE in the Makefile, scripts/cross.sh,
 * scripts/evidence.py), not into build/libtestutil.a.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <gmp.h>
#include <jansson.h>
#include <mpfr.h>
#include "gltf.h"
#include "gltf_oracle.h"
#include "exact_util.h"
#include "gltf_parts.h"
#include "gltf_anim.h"

/* exact image of box b (finite) under W on axis i: lo, hi */
void glt_box_image(const cbx_box *b, const gx_map *W, int i, mpq_t lo, mpq_t hi)
{
    mpq_t a, c, t;
    mpq_inits(a, c, t, NULL);
    mpq_set(lo, W->m[i][3]);
    mpq_set(hi, W->m[i][3]);
    for (int j = 0; j < 3; j++) {
        mpq_set_d(t, b->lo[j]); mpq_mul(a, W->m[i][j], t);
        mpq_set_d(t, b->hi[j]); mpq_mul(c, W->m[i][j], t);
        if (mpq_cmp(a, c) > 0) mpq_swap(a, c);
        mpq_add(lo, lo, a);
        mpq_add(hi, hi, c);
    }
    mpq_clears(a, c, t, NULL);
}

/* ---- animations (--animated) ------------------------------------------- */
/* What the reader read from each sampler's buffer equals the numbers
 * make.py wrote beside them in its "extras" (float32 values, exactly;
 * normalized integers as integers). */
static void check_extras(const gl_doc *d, const char *file, stats *st)
{
    json_t *A = json_object_get((json_t *)d->json, "animations");
    for (int a = 0; a < d->nanim; a++)
        for (int s = 0; s < d->anims[a].nsmp; s++) {
            const gl_sampler *M = &d->anims[a].smp[s];
            json_t *X = json_object_get(json_object_get(json_array_get(json_object_get(json_array_get(A, (size_t)a),
                                         "samplers"), (size_t)s), "extras"), "input");
            json_t *Y = json_object_get(json_object_get(json_array_get(json_object_get(json_array_get(A, (size_t)a),
                                         "samplers"), (size_t)s), "extras"), "output");
            if (!X || !Y) { FAIL("%s: animation %d sampler %d: no extras\n", file, a, s); continue; }
            long nv = M->v ? M->n * M->ncomp * (M->interp == GL_CUBICSPLINE ? 3 : 1) : 0;
            if ((long)json_array_size(X) != M->n || (M->v && (long)json_array_size(Y) != nv)) {
                FAIL("%s: animation %d sampler %d: %ld keys read, %zu written\n", file, a, s, M->n, json_array_size(X));
                continue;
            }
            for (long k = 0; k < M->n; k++)
                if (M->t[k] != json_number_value(json_array_get(X, (size_t)k)))
                    FAIL("%s: animation %d sampler %d: key time %ld read as %.17g\n", file, a, s, k, M->t[k]);
            for (long k = 0; k < nv; k++)
                if (M->v[k] != json_number_value(json_array_get(Y, (size_t)k)))
                    FAIL("%s: animation %d sampler %d: value %ld read as %.17g\n", file, a, s, k, M->v[k]);
            st->anim_keys += M->n;
        }
}


/* The value of sampler M at time t: exact for translation and scale (and
 * for STEP and CUBICSPLINE rotations); slerp in MPFR at 256 bits, taken as
 * a rational (its rotation matrix then within 2^-250 of the exact one).
 * arc: for a LINEAR rotation segment whose keys' dot product is exactly 0,
 * which of the two arcs (the reader covers both). */
static void anim_value(const gl_sampler *M, double t, int arc, mpq_t out[4])
{
    long i = -1;
    while (i + 1 < M->n && M->t[i + 1] <= t) i++;
    int nc = M->ncomp, cub = M->interp == GL_CUBICSPLINE, ofs = cub ? nc : 0, stp = cub ? 3 * nc : nc;
    if (i < 0 || i + 1 >= M->n || M->interp == GL_STEP) {
        const double *v = M->v + (size_t)(i < 0 ? 0 : i) * (size_t)stp + (size_t)ofs;
        for (int j = 0; j < nc; j++) mpq_set_d(out[j], v[j]);
        return;
    }
    const double *a = M->v + (size_t)i * (size_t)stp + (size_t)ofs, *b = a + stp;
    mpq_t u, D, x, y, h[4];
    mpq_inits(u, D, x, y, h[0], h[1], h[2], h[3], NULL);
    mpq_set_d(x, t); mpq_set_d(y, M->t[i]); mpq_sub(u, x, y);
    mpq_set_d(x, M->t[i + 1]); mpq_sub(D, x, y); mpq_div(u, u, D);
    if (cub) {
        /* Hermite: (2u^3 - 3u^2 + 1) a + (u^3 - 2u^2 + u) D aout
         *        + (-2u^3 + 3u^2) b + (u^3 - u^2) D bin */
        mpq_t u2, u3;
        mpq_inits(u2, u3, NULL);
        mpq_mul(u2, u, u); mpq_mul(u3, u2, u);
        long c[4][4] = { { 2, -3, 0, 1 }, { 1, -2, 1, 0 }, { -2, 3, 0, 0 }, { 1, -1, 0, 0 } };
        for (int k = 0; k < 4; k++) {
            mpq_set_si(h[k], c[k][3], 1);
            mpq_set_si(x, c[k][2], 1); mpq_mul(x, x, u); mpq_add(h[k], h[k], x);
            mpq_set_si(x, c[k][1], 1); mpq_mul(x, x, u2); mpq_add(h[k], h[k], x);
            mpq_set_si(x, c[k][0], 1); mpq_mul(x, x, u3); mpq_add(h[k], h[k], x);
        }
        mpq_mul(h[1], h[1], D);
        mpq_mul(h[3], h[3], D);
        const double *p[4] = { a, a + nc, b, b - nc };
        for (int j = 0; j < nc; j++) {
            mpq_set_ui(out[j], 0, 1);
            for (int k = 0; k < 4; k++) { mpq_set_d(x, p[k][j]); mpq_mul(x, x, h[k]); mpq_add(out[j], out[j], x); }
        }
        mpq_clears(u2, u3, NULL);
    } else if (nc == 3) {
        for (int j = 0; j < 3; j++) {
            mpq_set_d(x, a[j]); mpq_set_d(y, b[j]); mpq_sub(y, y, x); mpq_mul(y, y, u); mpq_add(out[j], x, y);
        }
    } else {                                      /* exact_util's slerp oracle */
        xu_slerp sl;
        mpfr_t uu, q[4];
        xu_slerp_init(&sl, 256);
        mpfr_init2(uu, 256);
        for (int j = 0; j < 4; j++) mpfr_init2(q[j], 256);
        xu_slerp_keys(&sl, a, b, 0, arc && glt_dot_sign(a, b) == 0 ? -1 : 0);   /* the other arc only at a tie */
        mpfr_set_q(uu, u, MPFR_RNDN);
        xu_slerp_at(&sl, uu, q);
        for (int j = 0; j < 4; j++) { mpfr_get_q(out[j], q[j]); mpfr_clear(q[j]); }
        mpfr_clear(uu);
        xu_slerp_clear(&sl);
    }
    mpq_clears(u, D, x, y, h[0], h[1], h[2], h[3], NULL);
}

/* set while a file of kind "anim loose" is checked: its excess is not
 * counted (an exact half turn, both arcs: expect.txt) */
int glt_anim_no_stats;

/* The --animated boxes: at times spread over each animation (every key
 * time, ANIM_T random times between each two consecutive ones, and times
 * before the first and after the last key), every node's exact map (its
 * channels' values, the other properties as written) composed down the
 * chain, and each mesh instance's box mapped exactly: inside its printed
 * box.  The excess of each box over the hull of those images (relative to
 * the hull's extent per axis) is reported: sampled, so an upper bound on
 * the excess over the exact union. */
double glt_check_anim(const gl_doc *d, const char *file, stats *st)
{
    check_extras(d, file, st);
    int nn = d->nn;
    gx_map *W = malloc((size_t)(nn + 1) * sizeof *W), *S = malloc((size_t)(nn + 1) * sizeof *S);
    if (!W || !S) exit(2);
    for (int k = 0; k < nn; k++) { gx_init(&W[k]); gx_init(&S[k]); }
    double (*hl)[3] = malloc((size_t)(d->nl + 1) * sizeof *hl), (*hh)[3] = malloc((size_t)(d->nl + 1) * sizeof *hh);
    if (!hl || !hh) exit(2);
    for (int k = 0; k < d->nl; k++)
        for (int j = 0; j < 3; j++) { hl[k][j] = HUGE_VAL; hh[k][j] = -HUGE_VAL; }
    mpq_t lo, hi, tmp, T[3], Q[4], Sc[3];
    mpq_inits(lo, hi, tmp, NULL);
    for (int j = 0; j < 4; j++) mpq_init(Q[j]);
    for (int j = 0; j < 3; j++) { mpq_init(T[j]); mpq_init(Sc[j]); }
    /* the static pose too: the boxes hold it */
    for (int k = 0; k < d->nl; k++) {
        const gx_map *M = gx_world(d, S, d->leaves[k].node);
        for (int i = 0; i < 3; i++) {
            glt_box_image(&d->leaves[k].local, M, i, lo, hi);
            if (mpq_get_d(lo) < hl[k][i]) hl[k][i] = mpq_get_d(lo);
            if (mpq_get_d(hi) > hh[k][i]) hh[k][i] = mpq_get_d(hi);
        }
    }
    unsigned long long rs = 12345;
    for (int a = 0; a < d->nanim; a++) {
        const gl_anim *G = &d->anims[a];
        if (d->only_anim >= 0 && a != d->only_anim)
            continue;
        /* the animation's key times, sorted */
        int nt = 0;
        double *tau = NULL;
        for (int h = 0; h < G->nch; h++) {
            if (G->ch[h].node < 0) continue;
            const gl_sampler *M = &G->smp[G->ch[h].sampler];
            tau = realloc(tau, (size_t)(nt + M->n) * sizeof *tau);
            if (!tau) exit(2);
            for (long e = 0; e < M->n; e++) tau[nt++] = M->t[e];
        }
        if (nt == 0) { free(tau); continue; }
        for (int x = 1; x < nt; x++)          /* insertion sort: few keys */
            for (int y = x; y > 0 && tau[y] < tau[y - 1]; y--) { double z = tau[y]; tau[y] = tau[y - 1]; tau[y - 1] = z; }
        /* a LINEAR rotation segment whose keys' dot product is exactly 0
         * (a half turn: the reader covers both arcs) is sampled on both */
        int ties = 0;
        for (int h = 0; h < G->nch; h++) {
            const gl_sampler *M = &G->smp[G->ch[h].sampler];
            if (G->ch[h].node < 0 || G->ch[h].path != 1 || M->interp != GL_LINEAR) continue;
            for (long e = 0; e + 1 < M->n; e++)
                ties += glt_dot_sign(M->v + 4 * e, M->v + 4 * e + 4) == 0;
        }
        int ns = 2 + nt * (ANIM_T + 1);
        for (int q = 0; q < ns; q++) {
            double t;
            if (q == 0) t = tau[0] - 1.0;
            else if (q == 1) t = tau[nt - 1] + 1.0;
            else {
                int e = (q - 2) / (ANIM_T + 1), r = (q - 2) % (ANIM_T + 1);
                if (r == 0 || e + 1 >= nt) t = tau[e];
                else {
                    rs = rs * 6364136223846793005ULL + 1442695040888963407ULL;
                    t = tau[e] + (tau[e + 1] - tau[e]) * ((double)(rs >> 11) * 0x1p-53);
                    if (t > tau[e + 1]) t = tau[e + 1];
                }
            }
            for (int arc = 0; arc < 1 + (ties > 0); arc++) {
                /* maps at t: animated nodes' locals, composed down */
                for (int k = 0; k < nn; k++) {
                    const gl_node *g = &d->nodes[k];
                    int anim = 0;
                    for (int j = 0; j < 3; j++) { mpq_set_d(T[j], g->t[j]); mpq_set_d(Sc[j], g->s[j]); }
                    for (int j = 0; j < 4; j++) mpq_set_d(Q[j], g->r[j]);
                    for (int h = 0; h < G->nch; h++) {
                        if (G->ch[h].node != k) continue;
                        anim = 1;
                        anim_value(&G->smp[G->ch[h].sampler], t, arc, G->ch[h].path == 0 ? T : G->ch[h].path == 1 ? Q : Sc);
                    }
                    gx_map L;
                    gx_init(&L);
                    if (anim) gx_trs(&L, T, Q, Sc); else gx_local(&L, g);
                    for (int i = 0; i < 3; i++) for (int j = 0; j < 4; j++) mpq_set(W[k].m[i][j], L.m[i][j]);
                    W[k].done = 0;
                    gx_clear(&L);
                }
                /* world = parent's world o local, parents first */
                for (int k = 0; k < nn; k++) {
                    int chain[64], n = 0;
                    for (int x = k; x >= 0 && !W[x].done && n < 64; x = d->nodes[x].parent) chain[n++] = x;
                    while (n-- > 0) {
                        int x = chain[n], p = d->nodes[x].parent;
                        if (p >= 0) {
                            gx_map L;
                            gx_init(&L);
                            gx_compose(&L, &W[p], &W[x]);
                            for (int i = 0; i < 3; i++) for (int j = 0; j < 4; j++) mpq_set(W[x].m[i][j], L.m[i][j]);
                            gx_clear(&L);
                        }
                        W[x].done = 1;
                    }
                }
                for (int k = 0; k < d->nl; k++) {
                    const gl_leaf *L = &d->leaves[k];
                    for (int i = 0; i < 3; i++) {
                        glt_box_image(&L->local, &W[L->node], i, lo, hi);
                        if (gx_outside(lo, &L->world, i, tmp) || gx_outside(hi, &L->world, i, tmp))
                            FAIL("%s: animation %d at t = %.17g%s: leaf %s axis %d [%.17g, %.17g] not inside [%.17g, %.17g]\n",
                                 file, a, t, arc ? " (other arc)" : "", L->path, i, mpq_get_d(lo), mpq_get_d(hi),
                                 L->world.lo[i], L->world.hi[i]);
                        if (mpq_get_d(lo) < hl[k][i]) hl[k][i] = mpq_get_d(lo);
                        if (mpq_get_d(hi) > hh[k][i]) hh[k][i] = mpq_get_d(hi);
                        st->anim_checks++;
                    }
                }
                st->anim_poses++;
            }
        }
        free(tau);
    }
    double emax = 0.0;
    for (int k = 0; k < d->nl; k++)
        for (int i = 0; i < 3; i++) {
            double w = hh[k][i] - hl[k][i];
            if (!(w > 0)) continue;
            double e = (d->leaves[k].world.hi[i] - hh[k][i] + hl[k][i] - d->leaves[k].world.lo[i]) / w;
            if (e > emax) emax = e;
            if (getenv("ANIM_DEBUG")) printf("excess %s cells %d leaf %s axis %d: %.4g of %.4g\n", file, d->cells, d->leaves[k].path, i, e, w);
            if (d->cells != GLTF_ANIM_CELLS || glt_anim_no_stats) continue;
            if (e > st->anim_excess) st->anim_excess = e;
            st->anim_excess_sum += e;
            st->anim_axes++;
        }
    mpq_clears(lo, hi, tmp, NULL);
    for (int j = 0; j < 4; j++) mpq_clear(Q[j]);
    for (int j = 0; j < 3; j++) { mpq_clear(T[j]); mpq_clear(Sc[j]); }
    for (int k = 0; k < nn; k++) { gx_clear(&W[k]); gx_clear(&S[k]); }
    free(W); free(S); free(hl); free(hh);
    st->anim_files++;
    return emax;
}
