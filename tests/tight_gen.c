/*
 * tight_gen.c: part of tests/test_tight.c (tight_parts.h): the random
 * generators of sections 1 to 5 (splitmix64, exact_util.h); each draws in
 * a fixed order, so that every machine (make check-cross) draws the same
 * cases.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <math.h>
#include <gmp.h>
#include <mpfr.h>

#include "tight_parts.h"

/* ---------------------------------------------------------------------- */
/* Generators                                                             */
/* ---------------------------------------------------------------------- */

/* a full-mantissa value in [2^e, 2^(e+1)) (rounded when subnormal) */
static double gm(xu_rng *r, int e)
{
    double f = 1.0 + ldexp((double)(xu_rng_next(r) >> 12), -52);
    if (e > 1023) e = 1023;
    if (e < -1074) e = -1074;
    return ldexp(f, e);
}

static double sgm(xu_rng *r, int e) { return xu_rng_sign(r) * gm(r, e); }

static int clampi(int v, int lo, int hi) { return v < lo ? lo : v > hi ? hi : v; }

/* Callers draw w before u: the order gcc gives sort_axis(b, j, U, W) on
 * x86-64 (arguments right to left), made explicit so that ARM draws the
 * same cases. */
static void sort_axis(cbx_box *b, int j, double u, double w)
{
    b->lo[j] = u < w ? u : w;
    b->hi[j] = u < w ? w : u;
}

/* Section 1: random full rows, exponents over the whole range. */
void tgt_gen_wide(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    int ec[3], i, j;
    for (j = 0; j < 3; j++) {
        int p = xu_rng_int(r, 0, 99);
        double c1, c2;
        ec[j] = p < 55 ? xu_rng_int(r, -40, 40) : p < 85 ? xu_rng_int(r, -1060, 1010)
                                                         : xu_rng_int(r, -300, 300);
        c1 = sgm(r, ec[j]);
        p = xu_rng_int(r, 0, 99);
        if (p < 10) c2 = c1;                       /* flat axis */
        else if (p < 20) c2 = xu_rng_sign(r) * 0.0;
        else if (p < 30) c2 = -c1;
        else c2 = sgm(r, ec[j] - xu_rng_int(r, 0, 12));
        sort_axis(b, j, c1, c2);
    }
    for (i = 0; i < 3; i++) {
        int p = xu_rng_int(r, 0, 99), R;
        R = p < 45 ? xu_rng_int(r, -80, 80) : p < 80 ? xu_rng_int(r, -960, 995)
                                                     : xu_rng_int(r, -1074, 1018);
        for (j = 0; j < 3; j++) {
            int em;
            if (xu_rng_int(r, 0, 99) < 8) {
                a->m[i][j] = xu_rng_sign(r) * 0.0;
                continue;
            }
            em = p < 90 ? R - ec[j] + xu_rng_int(r, -30, 30) : xu_rng_int(r, -1074, 1018);
            em = clampi(em, -1074, 1016 - ec[j]);
            em = clampi(em, -1074, 1018);
            a->m[i][j] = sgm(r, em);
        }
        p = xu_rng_int(r, 0, 99);
        if (p < 20) a->m[i][3] = xu_rng_sign(r) * 0.0;
        else if (p < 65) a->m[i][3] = sgm(r, clampi(R + xu_rng_int(r, -60, 10), -1074, 1017));
        else if (p < 85) a->m[i][3] = xu_gen_signed(r, -1074, 1017);
        else a->m[i][3] = xu_gen_signed(r, -20, 20);
    }
}

/* Section 2: integers and small dyadics, often with a representable E. */
static double dy(xu_rng *r, int range, int den_log2)
{
    return ldexp((double)xu_rng_int(r, -range, range), -den_log2);
}

void tgt_gen_int(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    int p = xu_rng_int(r, 0, 99), i, j, sm = 0, sc = 0;
    if (p < 25) { /* small integers */
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) a->m[i][j] = (double)xu_rng_int(r, -4, 4);
            a->m[i][3] = (double)xu_rng_int(r, -1000000, 1000000);
        }
        for (j = 0; j < 3; j++) { double w = dy(r, 1000, 0); sort_axis(b, j, dy(r, 1000, 0), w); }
    } else if (p < 45) { /* small dyadics */
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) a->m[i][j] = dy(r, 64, 3);
            a->m[i][3] = dy(r, 1 << 20, 2);
        }
        for (j = 0; j < 3; j++) { double w = dy(r, 1 << 20, 4); sort_axis(b, j, dy(r, 1 << 20, 4), w); }
    } else if (p < 60) { /* permutation / sign flip, scales 2^s */
        int perm[3] = { 0, 1, 2 };
        for (j = 2; j > 0; j--) {
            int q = xu_rng_int(r, 0, j), t = perm[j];
            perm[j] = perm[q];
            perm[q] = t;
        }
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) a->m[i][j] = xu_rng_int(r, 0, 1) ? 0.0 : -0.0;
            a->m[i][perm[i]] = xu_rng_sign(r) * ldexp(1.0, xu_rng_int(r, -3, 3));
            a->m[i][3] = xu_rng_int(r, 0, 3) ? dy(r, 1 << 24, 3) : 0.0;
        }
        for (j = 0; j < 3; j++) { double w = dy(r, 1 << 30, 6); sort_axis(b, j, dy(r, 1 << 30, 6), w); }
    } else if (p < 80) { /* large integers: sums beyond 2^53 */
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++)
                a->m[i][j] = (double)xu_rng_int(r, -(1 << 26), 1 << 26);
            int e = xu_rng_int(r, 0, 30);
            a->m[i][3] = ldexp((double)xu_rng_int(r, -(1 << 30), 1 << 30), e);
        }
        for (j = 0; j < 3; j++) {
            double w = (double)xu_rng_int(r, -(1 << 30), 1 << 30);
            sort_axis(b, j, (double)xu_rng_int(r, -(1 << 30), 1 << 30), w);
        }
    } else { /* powers of two with wide spreads */
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++)
                a->m[i][j] = xu_rng_int(r, 0, 5) ? xu_rng_sign(r) * ldexp(1.0, xu_rng_int(r, -40, 40))
                                                 : 0.0;
            a->m[i][3] = xu_rng_int(r, 0, 3) ? xu_rng_sign(r) * ldexp(1.0, xu_rng_int(r, -80, 80))
                                             : 0.0;
        }
        for (j = 0; j < 3; j++) {
            double w = xu_rng_int(r, 0, 2) ? xu_rng_sign(r) * ldexp(1.0, xu_rng_int(r, -40, 40)) : 0.0;
            sort_axis(b, j, xu_rng_sign(r) * ldexp(1.0, xu_rng_int(r, -40, 40)), w);
        }
    }
    /* scale by powers of two (exact unless a value becomes subnormal) */
    if (xu_rng_int(r, 0, 2) == 0) {
        sm = xu_rng_int(r, -480, 480);
        sc = xu_rng_int(r, -480, 480);
        if (sm + sc > 900) sc = 900 - sm;
        if (sm + sc < -900) sc = -900 - sm;
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) a->m[i][j] = ldexp(a->m[i][j], sm);
            a->m[i][3] = ldexp(a->m[i][3], sm + sc);
        }
        for (j = 0; j < 3; j++) {
            b->lo[j] = ldexp(b->lo[j], sc);
            b->hi[j] = ldexp(b->hi[j], sc);
        }
    }
}

/* the vertex of one end of row i (0 where m_j == 0); finite box assumed */
static void vertex_of(const cbx_affine *a, const cbx_box *b, int i, int up, double v[3])
{
    int j;
    for (j = 0; j < 3; j++) {
        double m = a->m[i][j];
        v[j] = m == 0 ? 0.0 : ((m > 0) != (up != 0)) ? b->lo[j] : b->hi[j];
    }
}

/* Section 3: heavy cancellation at one end of each row. */
void tgt_gen_cancel(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    int i, j, ec[3];
    int scale = xu_rng_int(r, 0, 3) == 0 ? xu_rng_int(r, -900, 900) : xu_rng_int(r, -30, 30);
    for (j = 0; j < 3; j++) {
        double c1, c2;
        ec[j] = scale / 2 + xu_rng_int(r, -20, 20);
        c1 = sgm(r, ec[j]);
        c2 = xu_rng_int(r, 0, 3) ? sgm(r, ec[j] - xu_rng_int(r, 0, 10)) : c1;
        sort_axis(b, j, c1, c2);
    }
    for (i = 0; i < 3; i++) {
        int up = xu_rng_int(r, 0, 1), p = xu_rng_int(r, 0, 99);
        double v[3], t;
        a->m[i][3] = 0.0;
        for (j = 0; j < 3; j++)
            a->m[i][j] = sgm(r, clampi(scale - ec[j] + xu_rng_int(r, -20, 20), -1074, 1000));
        if (p < 35) {
            /* t = -fl(m.v), then maybe a few ulps off */
            vertex_of(a, b, i, up, v);
            t = -(a->m[i][0] * v[0] + a->m[i][1] * v[1] + a->m[i][2] * v[2]);
            if (xu_rng_int(r, 0, 1)) {
                int n = xu_rng_int(r, 1, 3), d = xu_rng_int(r, 0, 1);
                while (n--) t = nextafter(t, d ? INF : -INF);
            }
            a->m[i][3] = t;
        } else if (p < 55) {
            /* t = -fl(m_0 v_0); the other products much smaller or zero */
            a->m[i][1] = xu_rng_int(r, 0, 1) ? 0.0 : ldexp(a->m[i][1], -xu_rng_int(r, 40, 70));
            a->m[i][2] = xu_rng_int(r, 0, 1) ? 0.0 : ldexp(a->m[i][2], -xu_rng_int(r, 40, 70));
            vertex_of(a, b, i, up, v);
            a->m[i][3] = -(a->m[i][0] * v[0]);
        } else if (p < 80) {
            /* exact cancellation: m_1 = +-v_0 2^s, v_1 = -+m_0 2^-s, so
             * m_1 v_1 = -m_0 v_0; the rest tiny or zero */
            int s = xu_rng_int(r, -8, 8);
            double sg = xu_rng_sign(r), c;
            vertex_of(a, b, i, up, v);
            if (v[0] == 0 || a->m[i][0] == 0) continue;
            a->m[i][1] = sg * ldexp(v[0], s);
            c = -sg * ldexp(a->m[i][0], -s);
            /* v_1 = c must be the box end the sign of m_1 selects */
            if ((a->m[i][1] > 0) != (up != 0)) {
                b->lo[1] = c;
                if (b->hi[1] < c) b->hi[1] = c;
            } else {
                b->hi[1] = c;
                if (b->lo[1] > c) b->lo[1] = c;
            }
            switch (xu_rng_int(r, 0, 3)) {
            case 0: a->m[i][2] = xu_rng_sign(r) * 0.0; a->m[i][3] = 0.0; break;
            case 1: a->m[i][2] = ldexp(a->m[i][2], -xu_rng_int(r, 30, 80));
                    a->m[i][3] = 0.0; break;
            case 2: vertex_of(a, b, i, up, v);
                    a->m[i][3] = -(a->m[i][2] * v[2]); break;
            default: a->m[i][3] = xu_gen_signed(r, -1074, -1000); break;
            }
        } else {
            /* products near 2^-960 and t = -fl(sum): E deep in the subnormals */
            for (j = 0; j < 3; j++)
                a->m[i][j] = sgm(r, clampi(-958 - ec[j] + xu_rng_int(r, 0, 6), -1074, 1000));
            vertex_of(a, b, i, up, v);
            a->m[i][3] = -(a->m[i][0] * v[0] + a->m[i][1] * v[1] + a->m[i][2] * v[2]);
        }
    }
}

/* Section 4: half-spaces, huge ends, zeros, infinities, NaN, empty. */
static double gen_entry4(xu_rng *r)
{
    int p = xu_rng_int(r, 0, 99);
    if (p < 20) return xu_rng_sign(r) * 0.0;
    if (p < 60) return xu_gen_signed(r, -20, 10);
    if (p < 70) return xu_gen_signed(r, -1074, -900);
    if (p < 80) return xu_rng_sign(r) * (xu_rng_int(r, 0, 1) ? 0x1p1018 : 1e300);
    if (p < 83) return xu_rng_sign(r) * DBL_MAX;
    return xu_gen_signed(r, -1074, 1023);
}

static double gen_coord4(xu_rng *r)
{
    int p = xu_rng_int(r, 0, 99);
    if (p < 40) return xu_gen_signed(r, -10, 10);
    if (p < 50) return xu_rng_sign(r) * 0.0;
    if (p < 60) return xu_rng_sign(r);
    if (p < 75) return xu_gen_signed(r, -1074, 1018);
    if (p < 80) return xu_rng_sign(r) * 0x1p1018;
    if (p < 85) return xu_rng_sign(r) * DBL_MAX;
    return xu_gen_signed(r, -30, 30);
}

void tgt_gen_special(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) a->m[i][j] = gen_entry4(r);
        a->m[i][3] = xu_rng_int(r, 0, 2) ? xu_gen_signed(r, -20, 20) : gen_entry4(r);
        if (xu_rng_int(r, 0, 24) == 0) a->m[i][xu_rng_int(r, 0, 3)] = xu_rng_sign(r) * INF;
    }
    for (j = 0; j < 3; j++) {
        int p = xu_rng_int(r, 0, 99);
        double w = gen_coord4(r);
        sort_axis(b, j, gen_coord4(r), w);
        if (p < 20) b->lo[j] = -INF;
        else if (p < 40) b->hi[j] = INF;
        else if (p < 45) { b->lo[j] = -INF; b->hi[j] = INF; }
        else if (p < 47) b->lo[j] = INF;      /* empty */
        else if (p < 49) b->hi[j] = -INF;     /* empty */
        else if (p < 51) { double t = b->lo[j]; b->lo[j] = b->hi[j]; b->hi[j] = t; } /* maybe empty */
    }
    if (xu_rng_int(r, 0, 29) == 0) {
        if (xu_rng_int(r, 0, 1)) a->m[xu_rng_int(r, 0, 2)][xu_rng_int(r, 0, 3)] = NAN;
        else if (xu_rng_int(r, 0, 1)) b->lo[xu_rng_int(r, 0, 2)] = NAN;
        else b->hi[xu_rng_int(r, 0, 2)] = NAN;
    }
}

/* Section 5: near the exception's boundaries. */
void tgt_gen_boundary(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    int i, j, kind = xu_rng_int(r, 0, 2);
    for (j = 0; j < 3; j++) { double w = xu_gen_signed(r, -4, 4); sort_axis(b, j, xu_gen_signed(r, -4, 4), w); }
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            int e;
            if (xu_rng_int(r, 0, 9) == 0) {
                a->m[i][j] = 0.0;
                continue;
            }
            if (kind == 0) e = xu_rng_int(r, -974, -962) - ilogb(fmax(fabs(b->lo[j]), 0x1p-1000));
            else if (kind == 1) e = xu_rng_int(r, 1006, 1017);
            else e = xu_rng_int(r, -60, 60);
            a->m[i][j] = sgm(r, clampi(e, -1074, 1018));
        }
        if (kind == 0)
            a->m[i][3] = xu_rng_int(r, 0, 1) ? 0.0 : sgm(r, xu_rng_int(r, -1000, -955));
        else if (kind == 1)
            a->m[i][3] = xu_rng_int(r, 0, 2) ? sgm(r, xu_rng_int(r, 1011, 1017)) : 0.0;
        else
            a->m[i][3] = xu_rng_int(r, 0, 1) ? xu_rng_sign(r) * 0x1p1015
                         : sgm(r, xu_rng_int(r, 1013, 1018));
    }
}
