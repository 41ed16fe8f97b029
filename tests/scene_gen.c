/*
 * scene_gen.c: part of tests/test_scene.c (scene_parts.h): the generated
 * scene texts (a growing text buffer; deep random scenes; scenes whose
 * composed maps are the whole bound).
 */
#include <gmp.h>
#include <mpfr.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_parts.h"


void sct_sb_add(sbuf *b, const char *fmt, ...)
{
    va_list ap;
    for (;;) {
        va_start(ap, fmt);
        int k = vsnprintf(b->p ? b->p + b->n : NULL, b->p ? b->cap - b->n : 0, fmt, ap);
        va_end(ap);
        if (k < 0) { fprintf(stderr, "vsnprintf failed\n"); exit(2); }
        if (b->p && b->n + (size_t)k < b->cap) { b->n += (size_t)k; return; }
        b->cap = 2 * (b->cap + (size_t)k + 64);
        b->p = realloc(b->p, b->cap);
        if (!b->p) { fprintf(stderr, "out of memory\n"); exit(2); }
    }
}

/* A deep random scene: a chain of nn nodes (a branch to a random earlier node with probability pb %), each
 * with 0 to 3 operations near an isometry (so that 300 levels stay finite)
 * or a motion node (probability pm %), and nl leaves on nodes near the
 * bottom and anywhere.  Decimal numbers such as 0.1 are not doubles, so
 * the matrices are not exact and every rounding path is taken. */
void sct_gen_deep(xu_rng *r, sbuf *b, int nn, int nl, int pm, int pb)
{
    static const char *deg[] = {"30", "-45", "90", "1e-3", "123.456", "-179.9"};
    b->n = 0;
    sct_sb_add(b, "certbox-scene 1\n");
    for (int i = 0; i < nn; i++) {
        if (i == 0) sct_sb_add(b, "node n0\n");
        else sct_sb_add(b, "node n%d n%d\n", i, xu_rng_int(r, 0, 99) >= pb ? i - 1 : xu_rng_int(r, 0, i - 1));
        int motion = xu_rng_int(r, 0, 99) < pm, nops = motion ? 2 : xu_rng_int(r, 0, 3);
        if (motion && xu_rng_int(r, 0, 2) == 0) {
            /* a third of the motion nodes: keyframes (any turn, scale near 1) */
            sct_sb_add(b, "  keyframes");
            for (int k = 0; k < 2; k++) {
                sct_sb_add(b, "  %.17g %.17g %d ", 2 * xu_rng_unit(r) - 1, 0.5 * xu_rng_unit(r), xu_rng_int(r, -1, 1));
                sct_sb_add(b, " %.17g %.17g %.17g %.17g ", xu_rng_unit(r) - 0.5, xu_rng_unit(r) - 0.5,
                       xu_rng_unit(r) - 0.5, xu_rng_unit(r) - 0.5 + 0.01);
                sct_sb_add(b, " %.17g %.17g %.17g", 0.95 + 0.1 * xu_rng_unit(r), 0.95 + 0.1 * xu_rng_unit(r),
                       xu_rng_sign(r) * (0.95 + 0.1 * xu_rng_unit(r)));
            }
            sct_sb_add(b, "%s\n", xu_rng_int(r, 0, 3) == 0 ? " nlerp" : "");
            nops = 0;
        }
        for (int q = 0; q < nops; q++) {
            if (motion && q == 1) sct_sb_add(b, "  motion\n");
            switch (xu_rng_int(r, 0, 5)) {
            case 0: case 1:
                sct_sb_add(b, "  translate %.17g 0.1 %d\n", 20 * xu_rng_unit(r) - 10, xu_rng_int(r, -5, 5));
                break;
            case 2:
                sct_sb_add(b, "  scale %.17g %.17g 0.3\n", xu_rng_sign(r) * (0.8 + 0.45 * xu_rng_unit(r)),
                       xu_rng_sign(r) * (0.8 + 0.45 * xu_rng_unit(r)));
                b->n -= 4;      /* "0.3\n" -> a factor near 1 */
                sct_sb_add(b, "%s\n", xu_rng_int(r, 0, 1) ? "1.1" : "-0.9");
                break;
            case 3: case 4:
                sct_sb_add(b, "  rotate %.17g %.17g 0.25 %s\n", xu_rng_unit(r) - 0.5, xu_rng_unit(r), deg[xu_rng_int(r, 0, 5)]);
                break;
            default:
                sct_sb_add(b, "  matrix 1 0.1 %.17g 3  -0.05 1 0 0.1  0 %.17g 0.99 -2\n", 0.2 * xu_rng_unit(r) - 0.1,
                       0.1 * xu_rng_unit(r));
            }
        }
    }
    for (int l = 0; l < nl; l++) {
        int n = xu_rng_int(r, 0, 1) ? nn - 1 - xu_rng_int(r, 0, nn < 5 ? nn - 1 : 4) : xu_rng_int(r, 0, nn - 1);
        double x = 10 * xu_rng_unit(r) - 5;
        switch (xu_rng_int(r, 0, 2)) {
        case 0: sct_sb_add(b, "box b%d n%d %.17g -1 0.1 %.17g 0.5 0.7\n", l, n, x, x + 3 * xu_rng_unit(r)); break;
        case 1: sct_sb_add(b, "sphere b%d n%d %.17g 0.1 -2 %.17g\n", l, n, x, 2 * xu_rng_unit(r)); break;
        default: sct_sb_add(b, "ellipsoid b%d n%d 0.1 %.17g 1 0.5 0.2 %.17g 0.6 -0.8 0 0.8 0.6 0 0 0 1\n", l, n, x,
                        xu_rng_unit(r));
        }
    }
}

/* Scenes where the composed maps are the whole bound, so that a wrong
 * rounding direction shows: kind 0, a chain of nn nodes with 65 to 90
 * operations each (more than a leaf's 64 level-by-level steps, so its leaves
 * go straight to the interval maps) and point or thin box leaves; kind 1, a
 * chain of nn motion nodes, each a translation moving by 0.001 to 0.01
 * (past 128 of them: the world map with the hull of M0 and M1); kind 2,
 * nodes of 70 operations that are exact in doubles (small power-of-two
 * translations, signed permutations) but for a scale and a translation
 * by decimals, and
 * point leaves: the result is a few units in the last place wide, so a
 * product or sum rounded the wrong way fails the exact check. */
void sct_gen_tight(xu_rng *r, sbuf *b, int kind, int nn, int nl)
{
    b->n = 0;
    sct_sb_add(b, "certbox-scene 1\n");
    for (int i = 0; i < nn; i++) {
        if (i == 0) sct_sb_add(b, "node n0\n");
        else sct_sb_add(b, "node n%d n%d\n", i, i - 1);
        if (kind == 1) {
            sct_sb_add(b, "  translate 0.1 %.17g 0\n  motion\n  translate %.17g 0.1 0.3\n",
                   0.01 * xu_rng_unit(r), 0.001 + 0.01 * xu_rng_unit(r));
            continue;
        }
        if (kind == 2) {
            int a = xu_rng_int(r, 0, 69), c = xu_rng_int(r, 0, 69);
            for (int q = 0; q < 70; q++) {
                if (q == a) sct_sb_add(b, "  scale %.17g -0.3 %.17g\n", 0.5 + xu_rng_unit(r), 2 * xu_rng_unit(r) - 1);
                else if (q == c) sct_sb_add(b, "  translate 0.1 %.17g -0.7\n", xu_rng_unit(r));
                else if (q % 3 == 0) sct_sb_add(b, "  rotate 0 0 1 90\n");
                else if (q % 3 == 1) sct_sb_add(b, "  scale -1 1 -1\n");
                else sct_sb_add(b, "  translate 0x1p-%d 0 -0x1p-%d\n", xu_rng_int(r, 4, 9), xu_rng_int(r, 4, 9));
            }
            continue;
        }
        int nops = xu_rng_int(r, 65, 90);
        for (int q = 0; q < nops; q++)
            switch (xu_rng_int(r, 0, 3)) {
            case 0: sct_sb_add(b, "  translate 0.1 %.17g -0.3\n", xu_rng_unit(r) - 0.5); break;
            case 1: sct_sb_add(b, "  rotate 0.2 %.17g 1 %.17g\n", xu_rng_unit(r), 10 * xu_rng_unit(r)); break;
            case 2: sct_sb_add(b, "  scale 1.1 %.17g 0.9\n", 0.9 + 0.2 * xu_rng_unit(r)); break;
            default: sct_sb_add(b, "  matrix 1 0.01 0 0.7  0 1 %.17g 0  0 0 1 0.3\n", 0.02 * xu_rng_unit(r));
            }
    }
    for (int l = 0; l < nl; l++) {
        int n = xu_rng_int(r, 0, nn - 1);
        double x = xu_rng_unit(r) - 0.5, w = kind == 0 && xu_rng_int(r, 0, 1) ? 1e-9 * xu_rng_unit(r) : 0.0;
        double y = kind == 2 ? 3 * xu_rng_unit(r) : 0.1, z = kind == 2 ? xu_rng_unit(r) - 0.5 : -0.3;
        sct_sb_add(b, "box b%d n%d %.17g %.17g %.17g %.17g %.17g %.17g\n", l, kind == 1 ? nn - 1 : n, x, y, z, x + w, y, z);
    }
}
