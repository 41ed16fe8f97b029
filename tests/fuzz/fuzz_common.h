/*
 * fuzz_common.h: shared code of the certbox libFuzzer harnesses
 * (tests/fuzz/fuzz_*.c) and of the seed-corpus generator (make_corpus.c).
 *
 * 1. Decoding: the fuzzer's bytes -> doubles.  Each double starts with a
 *    tag byte t (a missing byte reads as 0):
 *      t < 0x80          special value fz_special_tab[t & 63], negated
 *                        when t & 0x40 (so "-NaN", -0.0, -inf exist too);
 *      0x80 <= t < 0xa0  a special (next byte as above) moved by
 *                        1 + ((t >> 1) & 3) ulps, up if t & 1, else down:
 *                        the neighbours of the domain limits;
 *      0xa0 <= t < 0xc0  a small integer times a power of two:
 *                        (int8) next * 2^(next16 % 2200 - 1100);
 *      t >= 0xc0         8 raw bytes, little-endian IEEE-754 binary64.
 *    The specials: NaN (quiet and with payloads), +-inf, +-0, subnormals,
 *    DBL_MIN, DBL_MAX, the domain limits 2^254, 2^509, 2^1018, 2^1019 and
 *    their neighbours, the class boundaries of the transform domain, small
 *    integers and a few ordinary fractions.
 *    fz_encode() is the inverse used by make_corpus.c.
 *
 * 2. The oracle: tests/fuzz/fuzz_oracle.h (not included with FZ_DECODE_ONLY).
 */
#ifndef FUZZ_COMMON_H
#define FUZZ_COMMON_H

#include <stdint.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <float.h>
#include <stdarg.h>

#if defined(__GNUC__) || defined(__clang__)
#define FZ_UNUSED __attribute__((unused))
#else
#define FZ_UNUSED
#endif
#define FZ_FN static FZ_UNUSED

/* ---------------------------------------------------------------------- */
/* Decoding                                                               */
/* ---------------------------------------------------------------------- */

typedef struct fz_in { const uint8_t *p; size_t n; } fz_in;

FZ_FN unsigned fz_byte(fz_in *in)
{
    if (in->n == 0) return 0;
    in->n--;
    return *in->p++;
}

FZ_FN double fz_from_bits(uint64_t u)
{
    double d;
    memcpy(&d, &u, sizeof d);
    return d;
}

FZ_FN uint64_t fz_to_bits(double d)
{
    uint64_t u;
    memcpy(&u, &d, sizeof u);
    return u;
}

#define FZ_NSPECIAL 64
/* Bit patterns, so that NaN payloads are exact.  Index -> value. */
static const uint64_t fz_special_tab[FZ_NSPECIAL] = {
    0x0000000000000000u, /*  0  +0                                        */
    0x7ff8000000000000u, /*  1  quiet NaN                                 */
    0x7ff0000000000000u, /*  2  +inf                                      */
    0x3ff0000000000000u, /*  3  1                                         */
    0x4000000000000000u, /*  4  2                                         */
    0x4008000000000000u, /*  5  3                                         */
    0x3fe0000000000000u, /*  6  0.5                                       */
    0x3fb999999999999au, /*  7  0.1                                       */
    0x3fd5555555555555u, /*  8  1/3                                       */
    0x3fe8000000000000u, /*  9  0.75                                      */
    0x4010000000000000u, /* 10  4                                         */
    0x4014000000000000u, /* 11  5                                         */
    0x401c000000000000u, /* 12  7                                         */
    0x4024000000000000u, /* 13  10                                        */
    0x4059000000000000u, /* 14  100                                       */
    0x0000000000000001u, /* 15  2^-1074, the smallest subnormal           */
    0x0000000000000003u, /* 16  3 * 2^-1074                               */
    0x000fffffffffffffu, /* 17  the largest subnormal                     */
    0x0010000000000000u, /* 18  DBL_MIN = 2^-1022                         */
    0x0010000000000001u, /* 19  DBL_MIN + 1 ulp                           */
    0x7fefffffffffffffu, /* 20  DBL_MAX                                   */
    0x7fe0000000000000u, /* 21  2^1023                                    */
    0x7fa0000000000000u, /* 22  2^1019: conversion limit                  */
    0x7fa0000000000001u, /* 23  2^1019 + 1 ulp                            */
    0x7f9fffffffffffffu, /* 24  2^1019 - 1 ulp                            */
    0x7f90000000000000u, /* 25  2^1018: translation / class k=0,1018 limit*/
    0x7f90000000000001u, /* 26  2^1018 + 1 ulp                            */
    0x7f8fffffffffffffu, /* 27  2^1018 - 1 ulp                            */
    0x5fc0000000000000u, /* 28  2^509: class k=509, sphere limit          */
    0x5fc0000000000001u, /* 29  2^509 + 1 ulp                             */
    0x5fbfffffffffffffu, /* 30  2^509 - 1 ulp                             */
    0x4fd0000000000000u, /* 31  2^254: ellipsoid limit                    */
    0x4fd0000000000001u, /* 32  2^254 + 1 ulp                             */
    0x4fcfffffffffffffu, /* 33  2^254 - 1 ulp                             */
    0x43f0000000000000u, /* 34  2^64: class k=64                          */
    0x43f0000000000001u, /* 35  2^64 + 1 ulp                              */
    0x7b90000000000000u, /* 36  2^954 (partner of 2^64)                   */
    0x7bf0000000000000u, /* 37  2^960: class k=960                        */
    0x4390000000000000u, /* 38  2^58 (partner of 2^960)                   */
    0x6fb0000000000000u, /* 39  2^764 (= 2^(1018-254))                    */
    0x3010000000000000u, /* 40  2^-254                                    */
    0x2020000000000000u, /* 41  2^-509                                    */
    0x2d30000000000000u, /* 42  2^-300: sphere rescaling threshold        */
    0x2d2fffffffffffffu, /* 43  2^-300 - 1 ulp                            */
    0x1e60000000000000u, /* 44  2^-537                                    */
    0x0000000000000010u, /* 45  2^-1070 (the widenings' absolute term)   */
    0x4330000000000000u, /* 46  2^52                                      */
    0x4340000000000000u, /* 47  2^53                                      */
    0x4340000000000001u, /* 48  2^53 + 2                                  */
    0x3fefffffffffffffu, /* 49  1 - 2^-53                                 */
    0x3ff0000000000001u, /* 50  1 + 2^-52                                 */
    0x7e37e43c8800759cu, /* 51  1e300                                     */
    0x01a56e1fc2f8f359u, /* 52  1e-300                                    */
    0x7fe1ccf385ebc8a0u, /* 53  1e308                                     */
    0x4018000000000000u, /* 54  6                                         */
    0x4020000000000000u, /* 55  8                                         */
    0x5ff0000000000000u, /* 56  2^512: class k=512                        */
    0x5f90000000000000u, /* 57  2^506 (partner of 2^512)                  */
    0x0170000000000000u, /* 58  2^-1000                                   */
    0x3e45798ee2308c3au, /* 59  1e-8                                      */
    0x3e50000000000000u, /* 60  2^-26                                     */
    0x0000000000000400u, /* 61  2^-1064 (a subnormal near the widening)  */
    0x7ff0000000000001u, /* 62  signalling NaN                            */
    0x7ff8dead0000beefu, /* 63  quiet NaN with a payload                  */
};

FZ_FN double fz_special(unsigned t)
{
    uint64_t u = fz_special_tab[t & 63u];
    if (t & 0x40u) u ^= UINT64_C(0x8000000000000000);
    return fz_from_bits(u);
}

FZ_FN double fz_double(fz_in *in)
{
    unsigned t = fz_byte(in);
    if (t < 0x80u) return fz_special(t);
    if (t < 0xa0u) {
        double v = fz_special(fz_byte(in));
        int k, n = 1 + (int)((t >> 1) & 3u);
        for (k = 0; k < n; k++) v = nextafter(v, (t & 1u) ? HUGE_VAL : -HUGE_VAL);
        return v;
    }
    if (t < 0xc0u) {
        int m = (int)fz_byte(in);
        unsigned e16 = fz_byte(in);
        e16 |= fz_byte(in) << 8;
        if (m > 127) m -= 256;
        return ldexp((double)m, (int)(e16 % 2200u) - 1100);
    }
    {
        uint64_t u = 0;
        int k;
        for (k = 0; k < 8; k++) u |= (uint64_t)fz_byte(in) << (8 * k);
        return fz_from_bits(u);
    }
}

/* Encode v so that fz_double() gives back exactly v (same bits): one byte
 * for a special, nine otherwise.  Returns the number of bytes written. */
FZ_FN size_t fz_encode(double v, uint8_t *buf)
{
    uint64_t u = fz_to_bits(v);
    unsigned t;
    int k;
    for (t = 0; t < 0x80u; t++)
        if (fz_to_bits(fz_special(t)) == u) {
            buf[0] = (uint8_t)t;
            return 1;
        }
    buf[0] = 0xc0;
    for (k = 0; k < 8; k++) buf[1 + k] = (uint8_t)(u >> (8 * k));
    return 9;
}

/* ---------------------------------------------------------------------- */
/* Printing                                                               */
/* ---------------------------------------------------------------------- */

FZ_FN void fz_pd(FILE *f, double v)
{
    fprintf(f, "%a (%.17g)", v, v);
    if (v != v) fprintf(f, " [bits 0x%016llx]", (unsigned long long)fz_to_bits(v));
}

FZ_FN void fz_print_vec(FILE *f, const char *label, const double *v, int n)
{
    int k;
    fprintf(f, "  %s = {", label);
    for (k = 0; k < n; k++) {
        if (k) fprintf(f, ", ");
        fz_pd(f, v[k]);
    }
    fprintf(f, "}\n");
}

#ifndef FZ_DECODE_ONLY
/* |v| <= 2^1019: the conversions' domain (false for NaN and infinities). */
FZ_FN int fz_in_conv_dom(double v) { return v >= -0x1p1019 && v <= 0x1p1019; }

/* row j of the identity map: y = x_j */
FZ_FN void fz_unit_row(double m[4], int j)
{
    m[0] = m[1] = m[2] = m[3] = 0.0;
    m[j] = 1.0;
}

#include "fuzz_oracle.h"
#endif /* FZ_DECODE_ONLY */
#endif /* FUZZ_COMMON_H */
