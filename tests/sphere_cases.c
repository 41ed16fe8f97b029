/*
 * The cases of tests/test_sphere.c (tests/sphere_parts.h): the hard-case
 * tables of cbx_sphere_box and cbx_ellipsoid_box, and the random generators
 * of both (the draws in a fixed order: the same cases on every machine).
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "sphere_parts.h"

/* ---------------------------------------------------------------------- */
/* Hard cases                                                             */
/* ---------------------------------------------------------------------- */

#define ROW(a, b, c, t) { a, b, c, t }
#define MAT(r0, r1, r2) { { r0, r1, r2 } }
#define ID3 MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0))

/* 2 Rx(45) Rz(30): rows (2c, -2s, 0), (2as, 2ac, -2a), (2as, 2ac, 2a) with
 * c = cos 30, s = sin 30, a = cos 45 = sin 45 (rounded literals) */
#define RZX2_T(t0, t1, t2) \
    MAT(ROW(1.7320508075688772, -1.0, 0.0, t0), \
        ROW(0.7071067811865476, 1.224744871391589, -1.4142135623730951, t1), \
        ROW(0.7071067811865476, 1.224744871391589, 1.4142135623730951, t2))

const sph_case spt_sph_hard[] = {
    /* the unit ball itself: exact box [-1, 1]^3 */
    { "identity (unit ball)", ID3, CBX_OK, 0 },
    /* radius 2, rotated 30 deg about z then 45 deg about x, t = (1, 2, 3) */
    { "radius 2, Rx(45) Rz(30), t = (1,2,3)",
      RZX2_T(1, 2, 3), CBX_OK, 0 },
    /* rank 2: a zero row (that axis is the point t = 5) */
    { "zero row (rank 2), t = 5",
      MAT(ROW(1, 2, 2, 0), ROW(0, 0, 0, 5), ROW(2, -1, 2, -1)), CBX_OK, 0 },
    /* rank 1: every row a multiple of (1, 2, 3) */
    { "rank 1 map",
      MAT(ROW(1, 2, 3, 0), ROW(-2, -4, -6, 1), ROW(0.1, 0.2, 0.30000000000000004, 2)),
      CBX_OK, 0 },
    /* all zeros with every sign: each axis is the point t (+-0) */
    { "all-zero map, signed zeros",
      MAT(ROW(-0.0, -0.0, -0.0, -0.0), ROW(0.0, -0.0, 0.0, 0.0), ROW(-0.0, 0.0, -0.0, 7)),
      CBX_OK, 0 },
    /* Pythagorean rows: sqrt(s) is an integer, the exact box is representable */
    { "Pythagorean rows: norms 7, 3, 13",
      MAT(ROW(2, 3, 6, 0.5), ROW(1, -2, 2, -1), ROW(3, 4, 12, 100)), CBX_OK, 0 },
    /* t = +-sqrt(s) exactly: an end is exactly 0 */
    { "t = +-sqrt(s): ends exactly 0",
      MAT(ROW(3, 4, 0, 5), ROW(3, 4, 0, -5), ROW(0, 0, 2, 2)), CBX_OK, 0 },
    /* t = -fl(sqrt(s)): the lower/upper end is a tiny rounding residue */
    { "t = -+fl(sqrt(s)): ends near 0",
      MAT(ROW(1, 1, 0, -1.4142135623730951), ROW(1, 1, 1, 1.7320508075688772),
          ROW(1e-8, 1, 0, -1)), CBX_OK, 0 },
    /* tiny-angle rotations: s = 1 + theta^2 rounds to 1, sqrt(s) > 1 */
    { "rotation 1e-8 about z",
      MAT(ROW(1.0, -1e-8, 0, 0), ROW(1e-8, 1.0, 0, 0), ROW(0, 0, 1, 0)), CBX_OK, 0 },
    { "rotation 1e-15 about x, translated",
      MAT(ROW(1, 0, 0, 5), ROW(0, 1.0, -1e-15, -1e15), ROW(0, 1e-15, 1.0, 0.25)),
      CBX_OK, 0 },
    { "rotation 1e-300 about y",
      MAT(ROW(1.0, 0, 1e-300, 0), ROW(0, 1, 0, 0), ROW(-1e-300, 0, 1.0, 0)), CBX_OK, 0 },
    /* a huge translation with a tiny radius: sqrt(s) far below ulp(t) */
    { "translation 1e15, radius 1e-10",
      MAT(ROW(1e-10, 0, 0, 1e15), ROW(0, 1e-10, 0, -1e15), ROW(0, 0, 1e-10, 1e15 + 0.125)),
      CBX_OK, 0 },
    /* t = 2^1018 with a subnormal radius: hi must step past 2^1018 */
    { "t = 2^1018, radius 2^-1074",
      MAT(ROW(0x1p-1074, 0, 0, 0x1p1018), ROW(0, 0x1p-1074, 0, -0x1p1018),
          ROW(0, 0, 0x1p-1074, 1)), CBX_OK, 0 },
    /* subnormal entries: s = 3 * 2^-2148 is far below the smallest double */
    { "subnormal entries",
      MAT(ROW(0x1p-1074, 0x1p-1074, 0x1p-1074, 0), ROW(0x1p-1074, 0, 0, 0x1p-1074),
          ROW(0x1.8p-1070, -0x1p-1060, 0x1p-1074, -0x1p-1060)), CBX_OK, 0 },
    /* entries 1e-200: squares underflow to 0 in binary64 */
    { "entries 1e-200 (squares underflow)",
      MAT(ROW(1e-200, 1e-200, 1e-200, 0), ROW(1e-200, 0, 0, 1), ROW(3e-160, 4e-160, 0, 0)),
      CBX_OK, 0 },
    /* 1e-300 next to 1e150 (1e150 < 2^509) */
    { "1e-300 next to 1e150",
      MAT(ROW(1e150, 1e-300, 0, 0), ROW(1e-300, 1e-300, 1e150, 1e300), ROW(1e-300, 0, 0, 0)),
      CBX_OK, 0 },
    /* 1e-200 next to 1e200: 1e200 > 2^509, row 0 out */
    { "1e-200 next to 1e200 (row 0 out)",
      MAT(ROW(1e200, 1e-200, 0, 0), ROW(1e-200, 1, 0, 0), ROW(0, 0, 1e-200, 0)),
      CBX_ERANGE, 1 },
    /* the domain limits themselves: entries 2^509, t = +-2^1018 */
    { "entries 2^509, t = +-2^1018",
      MAT(ROW(0x1p509, 0x1p509, 0x1p509, 0x1p1018),
          ROW(-0x1p509, 0x1p509, -0x1p509, -0x1p1018), ROW(0x1p509, 0, 0, 0)), CBX_OK, 0 },
    /* one ulp beyond */
    { "entry 2^509 + ulp (row 1 out)",
      MAT(ROW(0x1p509, 0, 0, 0), ROW(0, -P509U, 0, 0), ROW(0, 0, 1, 0)), CBX_ERANGE, 2 },
    { "t = 2^1018 + ulp (row 2 out)",
      MAT(ROW(1, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, -P1018U)), CBX_ERANGE, 4 },
    { "t = DBL_MAX, entry inf (rows 0, 1 out)",
      MAT(ROW(1, 0, 0, DBL_MAX), ROW(0, INF, 0, 0), ROW(0, 0, 1, 0)), CBX_ERANGE, 3 },
    { "t = -inf (row 0 out)",
      MAT(ROW(1, 0, 0, -INF), ROW(0, 1, 0, 0), ROW(0, 0, 1, 0)), CBX_ERANGE, 1 },
    /* NaN: EINVAL wins over everything */
    { "NaN entry", MAT(ROW(1, 0, 0, 0), ROW(0, NAN, 0, 0), ROW(0, 0, 1, 0)), CBX_EINVAL, 0 },
    { "NaN t and inf entry",
      MAT(ROW(INF, 0, 0, 0), ROW(0, 1, 0, 0), ROW(0, 0, 1, -NAN)), CBX_EINVAL, 0 },
};
#define N_SPH_HARD ((int)(sizeof spt_sph_hard / sizeof spt_sph_hard[0]))
const int spt_n_sph_hard = N_SPH_HARD;

#define V3(a, b, c) { a, b, c }
#define R3(r0, r1, r2) { r0, r1, r2 }
#define RID R3(V3(1, 0, 0), V3(0, 1, 0), V3(0, 0, 1))
/* Rx(45) Rz(30) */
#define RZX R3(V3(0.8660254037844387, -0.5, 0), \
               V3(0.3535533905932738, 0.6123724356957945, -0.7071067811865476), \
               V3(0.3535533905932738, 0.6123724356957945, 0.7071067811865476))
/* a rotation by 1e-300 about z, 1e-8 about z, 1e-15 about x */
#define RZ300 R3(V3(1.0, -1e-300, 0), V3(1e-300, 1.0, 0), V3(0, 0, 1))
#define RZ8 R3(V3(1.0, -1e-8, 0), V3(1e-8, 1.0, 0), V3(0, 0, 1))
#define RX15 R3(V3(1, 0, 0), V3(0, 1.0, -1e-15), V3(0, 1e-15, 1.0))

const ell_case spt_ell_hard[] = {
    /* unit sphere: exact [-1, 1]^3 */
    { "identity rot, unit radii", V3(0, 0, 0), V3(1, 1, 1), RID, CBX_OK, 0 },
    /* the demo's sphere as an ellipsoid: radius 2, Rx(45) Rz(30), (1,2,3) */
    { "radius 2, Rx(45) Rz(30), center (1,2,3)", V3(1, 2, 3), V3(2, 2, 2), RZX, CBX_OK, 0 },
    /* radii 1e-200 next to 1e200: 1e200 > 2^254, every axis out */
    { "radii 1e-200 next to 1e200 (all out)", V3(0, 0, 0), V3(1e-200, 1e200, 1), RZX,
      CBX_ERANGE, 7 },
    /* inside the domain: 1e-200 next to 1e70 */
    { "radii 1e-200 next to 1e70", V3(1, -1, 0), V3(1e-200, 1e70, 1), RZX, CBX_OK, 0 },
    /* 1e-300 next to 2^254 */
    { "radii 1e-300, 2^254, 1", V3(0, 0, 0x1p1018), V3(1e-300, 0x1p254, 1), RZX, CBX_OK, 0 },
    /* tiny-angle rotations */
    { "rotation 1e-8 about z, radii (1, 1e-3, 5)", V3(0, 0, 0), V3(1, 1e-3, 5), RZ8,
      CBX_OK, 0 },
    { "rotation 1e-15 about x, radii (3, 1e15, 1)", V3(5, -1e15, 0.25), V3(3, 1e15, 1),
      RX15, CBX_OK, 0 },
    { "rotation 1e-300 about z, radii (2^254, 1, 1)", V3(0, 0, 0),
      V3(0x1p254, 1, 1), RZ300, CBX_OK, 0 },
    /* a huge centre with tiny radii */
    { "center 1e15, radii 1e-10", V3(1e15, -1e15, 1e15 + 0.125), V3(1e-10, 1e-10, 1e-10),
      RZX, CBX_OK, 0 },
    /* degenerate radii: zero, -0.0, negative (a disc and a segment) */
    { "radii (0, -0.0, -3): a segment", V3(0, 0, 0), V3(0, -0.0, -3), RZX, CBX_OK, 0 },
    { "radii (-1, 2, 0): a disc", V3(1, 2, 3), V3(-1, 2, 0), RZX, CBX_OK, 0 },
    /* rank-deficient rot: a zero row, rank 1 */
    { "rot with a zero row", V3(1, 5, -1), V3(1, 2, 3),
      R3(V3(1, 2, 2), V3(0, -0.0, 0), V3(2, -1, 2)), CBX_OK, 0 },
    { "rot of rank 1", V3(0, 0, 0), V3(1, 0.5, 0.25),
      R3(V3(1, 2, 3), V3(-2, -4, -6), V3(0.1, 0.2, 0.30000000000000004)), CBX_OK, 0 },
    /* a shear: not orthogonal */
    { "shear rot", V3(0, 0, 0), V3(1, 1, 1),
      R3(V3(1, 1e3, 0), V3(0, 1, 1e-3), V3(0, 0, 1)), CBX_OK, 0 },
    /* subnormal rot and radii: a_ij = 2^-2148, sqrt(s) ~ 2^-2147 */
    { "subnormal rot and radii", V3(0, 0x1p-1074, -0.0), V3(0x1p-1074, 0x1p-1074, 0x1p-1074),
      R3(V3(0x1p-1074, 0x1p-1074, 0x1p-1074), V3(0x1p-1074, 0, 0), V3(0x1p-1060, 1, 0)),
      CBX_OK, 0 },
    /* the limits: rot 2^254, radii 2^254, center 2^1018 */
    { "rot, radii 2^254, center +-2^1018", V3(0x1p1018, -0x1p1018, 0), V3(0x1p254, -0x1p254, 0x1p254),
      R3(V3(0x1p254, 0x1p254, 0x1p254), V3(-0x1p254, 0x1p254, 0), V3(1, 1, 1)), CBX_OK, 0 },
    /* one ulp beyond each limit */
    { "rot entry 2^254 + ulp (axis 0 out)", V3(0, 0, 0), V3(1, 1, 1),
      R3(V3(0, P254U, 0), V3(0, 1, 0), V3(0, 0, 1)), CBX_ERANGE, 1 },
    { "radius 2^254 + ulp (all out)", V3(0, 0, 0), V3(1, -P254U, 1), RID, CBX_ERANGE, 7 },
    { "center 2^1018 + ulp (axis 2 out)", V3(0, 0, P1018U), V3(1, 1, 1), RID, CBX_ERANGE, 4 },
    /* infinities */
    { "center -inf (axis 1 out)", V3(0, -INF, 0), V3(1, 1, 1), RID, CBX_ERANGE, 2 },
    { "radius +inf (all out)", V3(0, 0, 0), V3(1, 1, INF), RID, CBX_ERANGE, 7 },
    /* signed zeros everywhere: each axis is the point center */
    { "signed zeros", V3(-0.0, 0.0, -0.0), V3(-0.0, 0.0, -0.0),
      R3(V3(-0.0, 1, -0.0), V3(1, -0.0, 0), V3(0, 0, -1)), CBX_OK, 0 },
    /* centre = +-sqrt(s) exactly: ends exactly 0 */
    { "center = +-sqrt(s): ends exactly 0", V3(5, -5, 0), V3(3, 4, 1),
      R3(V3(1, 1, 0), V3(1, 1, 0), V3(0, 0, 1)), CBX_OK, 0 },
    /* NaN */
    { "NaN radius", V3(0, 0, 0), V3(1, NAN, 1), RID, CBX_EINVAL, 0 },
    { "NaN rot entry", V3(0, 0, 0), V3(1, 1, 1),
      R3(V3(1, 0, 0), V3(0, 1, 0), V3(0, NAN, 1)), CBX_EINVAL, 0 },
    { "NaN center and inf radius", V3(0, -NAN, 0), V3(INF, 1, 1), RID, CBX_EINVAL, 0 },
};
#define N_ELL_HARD ((int)(sizeof spt_ell_hard / sizeof spt_ell_hard[0]))
const int spt_n_ell_hard = N_ELL_HARD;

/* ---------------------------------------------------------------------- */
/* Random generation                                                      */
/* ---------------------------------------------------------------------- */

/* a rotation by a tiny angle (1e-8 .. 1e-300) about a random axis */
static void gen_tiny_rotation(xu_rng *r, double R[3][3])
{
    static const double ang[] = { 1e-8, 1e-15, 1e-300, 1e-20, 1e-100, 1e-4 };
    double th = ang[xu_rng_int(r, 0, 5)] * (0.5 + xu_rng_unit(r));
    /* Taylor series in + and * only (correctly rounded everywhere, so the
     * same doubles on every architecture; libm's cos and sin are not):
     * th <= 1.5e-4, so the omitted terms are below an ulp */
    double t2 = th * th;
    double c = 1.0 - t2 / 2.0 + t2 * t2 / 24.0, s = th - th * t2 / 6.0;
    int ax = xu_rng_int(r, 0, 2), u = (ax + 1) % 3, v = (ax + 2) % 3, i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) R[i][j] = i == j ? 1.0 : 0.0;
    R[u][u] = c; R[u][v] = -s;
    R[v][u] = s; R[v][v] = c;
}

/* a 3x3 "linear part" for either function; entries within 2^emax */
static void gen_linear(xu_rng *r, double L[3][3], int emax)
{
    int i, j, mode = xu_rng_int(r, 0, 99);
    if (mode < 40) { /* rotation times one scale or per-column scales */
        int per_col = xu_rng_int(r, 0, 1), e = xu_rng_int(r, -1074, emax - 1);
        double sc[3];
        xu_rand_rotation(r, L);
        for (j = 0; j < 3; j++)
            sc[j] = per_col ? xu_gen_mag(r, -1074, emax - 1) : ldexp(1.0, e);
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++) L[i][j] *= sc[j];
    } else if (mode < 50) { /* tiny-angle rotation, scaled */
        double sc = ldexp(1.0, xu_rng_int(r, -1000, emax - 1));
        gen_tiny_rotation(r, L);
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++) L[i][j] *= sc;
    } else if (mode < 65) { /* narrow random: comparable entries */
        int P = xu_rng_int(r, -1070, emax);
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++) L[i][j] = xu_gen_signed(r, P - 4, P);
    } else if (mode < 80) { /* wide random: exponents spread */
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++) L[i][j] = xu_gen_signed(r, -1074, emax);
    } else if (mode < 90) { /* rank deficient */
        double v[3];
        int kind = xu_rng_int(r, 0, 2);
        for (j = 0; j < 3; j++) v[j] = xu_gen_signed(r, emax - 60, emax - 8);
        for (i = 0; i < 3; i++) {
            double f;
            if (kind == 0) { /* the exponent first: gcc's x86-64 argument order, made explicit */
                int e = -xu_rng_int(r, 0, 8);
                f = ldexp(xu_rng_sign(r), e);
            } else {
                f = xu_rng_unit(r) - 0.5;
            }
            for (j = 0; j < 3; j++) L[i][j] = f * v[j];
        }
        if (kind == 2) { /* plus a zero row */
            i = xu_rng_int(r, 0, 2);
            for (j = 0; j < 3; j++) L[i][j] = xu_rng_sign(r) * 0.0;
        }
    } else { /* signed permutation times scales, with signed zeros */
        int p = xu_rng_int(r, 0, 5);
        static const int perm[6][3] = { {0,1,2}, {0,2,1}, {1,0,2}, {1,2,0}, {2,0,1}, {2,1,0} };
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++)
                L[i][j] = j == perm[p][i] ? xu_gen_signed(r, -1074, emax)
                                          : xu_rng_sign(r) * 0.0;
    }
}

/* translation for row i given the exact s (scaled by 2^(2 sh)) */
static double gen_t(xu_rng *r, ctx *k, const mpz_t s, unsigned long sh)
{
    int p = xu_rng_int(r, 0, 99);
    double q;
    if (p < 15) { /* -+fl(sqrt(s)): an end nearly cancels */
        q = spt_sqrt_rn(k, s, sh);
        if (xu_rng_int(r, 0, 3) == 0) q = nextafter(q, xu_rng_sign(r) * INF);
        return xu_rng_sign(r) * q;
    }
    if (p < 25) return xu_rng_sign(r) * 0.0;
    if (p < 45) { /* comparable with sqrt(s) */
        int e;
        q = spt_sqrt_rn(k, s, sh);
        if (q == 0) return xu_gen_signed(r, -1074, 1018);
        frexp(q, &e);
        return xu_gen_signed(r, e - 8, e + 8 < 1018 ? e + 8 : 1018);
    }
    if (p < 55) return xu_gen_signed(r, 40, 1018); /* huge vs the radius */
    return xu_gen_signed(r, -1074, 1018);
}

void spt_gen_sphere(xu_rng *r, ctx *k, problem *P)
{
    double L[3][3];
    int i, j, p = xu_rng_int(r, 0, 999);
    memset(P, 0, sizeof *P);
    P->ell = 0;
    if (xu_rng_int(r, 0, 9) == 0) { /* tiny radius, huge translation */
        gen_linear(r, L, -20);
    } else {
        gen_linear(r, L, 509);
    }
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) P->a.m[i][j] = L[i][j];
        spt_sphere_s(k, &P->a, i);
        P->a.m[i][3] = gen_t(r, k, k->s[i], SH_SPHERE);
    }
    i = xu_rng_int(r, 0, 2);
    j = xu_rng_int(r, 0, 2);
    if (p < 100) { /* to or beyond the domain's edge */
        switch (xu_rng_int(r, 0, 6)) {
        case 0: P->a.m[i][j] = xu_rng_sign(r) * P509U; break;
        case 1: P->a.m[i][j] = xu_rng_sign(r) * 0x1p509; break; /* in */
        case 2: P->a.m[i][j] = xu_gen_signed(r, 509, 1023); break;
        case 3: P->a.m[i][xu_rng_int(r, 0, 3)] = xu_rng_sign(r) * INF; break;
        case 4: P->a.m[i][3] = xu_rng_sign(r) * P1018U; break;
        case 5: P->a.m[i][3] = xu_rng_sign(r) * 0x1p1018; break; /* in */
        default: P->a.m[i][3] = xu_rng_sign(r) * (xu_rng_int(r, 0, 1) ? DBL_MAX
                                                  : xu_gen_mag(r, 1018, 1023));
            break;
        }
    } else if (p < 115) {
        P->a.m[i][xu_rng_int(r, 0, 3)] = xu_rng_sign(r) * NAN;
    }
}

void spt_gen_ellipsoid(xu_rng *r, ctx *k, problem *P)
{
    double L[3][3];
    int i, j, p = xu_rng_int(r, 0, 999), mode = xu_rng_int(r, 0, 9);
    memset(P, 0, sizeof *P);
    P->ell = 1;
    if (mode < 6) { /* a rotation, optionally scaled */
        if (xu_rng_int(r, 0, 3)) xu_rand_rotation(r, L);
        else gen_tiny_rotation(r, L);
        if (xu_rng_int(r, 0, 2) == 0) {
            double sc = ldexp(1.0, xu_rng_int(r, -1074, 253));
            for (i = 0; i < 3; i++)
                for (j = 0; j < 3; j++) L[i][j] *= sc;
        }
    } else {
        gen_linear(r, L, 254);
    }
    memcpy(P->rot, L, sizeof L);
    switch (xu_rng_int(r, 0, 5)) {
    case 0: /* a sphere */
        P->radii[0] = P->radii[1] = P->radii[2] = xu_gen_signed(r, -1074, 254);
        break;
    case 1: { /* comparable radii */
        int e = xu_rng_int(r, -1070, 254);
        for (j = 0; j < 3; j++) P->radii[j] = xu_gen_signed(r, e - 6, e);
        break;
    }
    case 2: /* extreme ratio: 1e-200-like next to 1e70-like */
        P->radii[0] = xu_gen_signed(r, -1074, -600);
        P->radii[1] = xu_gen_signed(r, 200, 254);
        P->radii[2] = xu_gen_signed(r, -1074, 254);
        break;
    case 3: /* tiny radii (huge centres below) */
        for (j = 0; j < 3; j++) P->radii[j] = xu_gen_signed(r, -1074, -20);
        break;
    default:
        for (j = 0; j < 3; j++) P->radii[j] = xu_gen_signed(r, -1074, 254);
        break;
    }
    for (i = 0; i < 3; i++) {
        /* double[3][3] -> const double (*)[3] needs a cast in ISO C < C2X */
        spt_ell_s(k, P->radii, (const double (*)[3])P->rot, i);
        P->center[i] = gen_t(r, k, k->s[i], SH_ELL);
    }
    i = xu_rng_int(r, 0, 2);
    j = xu_rng_int(r, 0, 2);
    if (p < 100) {
        switch (xu_rng_int(r, 0, 8)) {
        case 0: P->rot[i][j] = xu_rng_sign(r) * P254U; break;
        case 1: P->rot[i][j] = xu_rng_sign(r) * 0x1p254; break; /* in */
        case 2: P->radii[j] = xu_rng_sign(r) * P254U; break;
        case 3: P->radii[j] = xu_rng_sign(r) * 0x1p254; break;  /* in */
        case 4: P->center[i] = xu_rng_sign(r) * P1018U; break;
        case 5: P->center[i] = xu_rng_sign(r) * 0x1p1018; break; /* in */
        case 6: P->rot[i][j] = xu_gen_signed(r, 254, 1023); break;
        case 7: P->radii[j] = xu_gen_signed(r, 254, 1023); break;
        default:
            switch (xu_rng_int(r, 0, 2)) {
            case 0: P->rot[i][j] = xu_rng_sign(r) * INF; break;
            case 1: P->radii[j] = xu_rng_sign(r) * INF; break;
            default: P->center[i] = xu_rng_sign(r) * INF; break;
            }
            break;
        }
    } else if (p < 115) {
        double nan = xu_rng_sign(r) * NAN;
        switch (xu_rng_int(r, 0, 2)) {
        case 0: P->rot[i][j] = nan; break;
        case 1: P->radii[j] = nan; break;
        default: P->center[i] = nan; break;
        }
    }
}
