/*
 * Hard cases of the build check's fma, sqrt and EFT tests (src/core/cbx_ieee.c),
 * as data: inputs and the IEEE-754 result, exact hexadecimal literals.
 * Found offline with exact rational arithmetic; tests/test_eft.c checks
 * every row again with MPFR (correctly rounded, binary64/binary32 range
 * with subnormals) and GMP (the EFT pairs' exact sums).
 * Included by cbx_ieee.c once per format (CBX_INST 64 or 32), and by the
 * test with CBX_IEEE_CASES_ALL (both tables).
 */
#ifndef CBX_IEEE_CASES_H
#define CBX_IEEE_CASES_H

#if defined(CBX_IEEE_CASES_ALL) || CBX_INST == 64
/* fma(x, y, z) == r.  Columns: x, y, z, r. */
static const double cbx_fma_cases[][4] = {
    /* x*y+z rounded twice gives 0; fused: -2^-60 */
    { 0x1.00000004p+0, 0x1.fffffff8p-1, -0x1p+0, -0x1p-60 },
    /* cancellation: rounded twice 0x1.cfcf8p-33; the exact sum rounded
     * to 64 bits first (x87 style) ties to 0x1.cfcf88675f388p-33 */
    { 0x1.a0c42671c82fbp+0, 0x1.cc81faf6a3e68p+0, -0x1.76da083e00000p+1, 0x1.cfcf88675f387p-33 },
    /* subnormal result (gradual underflow inside the fma); twice: 0x1.762p-1041 */
    { 0x1.18972048bd52fp-500, 0x1.91e4f33706a35p-500, -0x1.b87faabe74000p-1000, 0x1.761b9d47p-1041 },
    /* exact cancellation: +0 (sign checked) */
    { 0x1.8p+1, 0x1.4p+2, -0x1.ep+3, 0.0 },
};

/* two_prod(a, b) == (hi, lo), hi + lo == a*b exactly.  Columns: a, b, hi, lo.
 * Rows 3-4 take the Dekker form's scaled path (a factor above 2^995),
 * rows 5-7 products near the contract's lower limit 2^-969 (row 7: a
 * subnormal factor), row 8 a product near 2^1018. */
static const double cbx_prod_cases[][4] = {
    { 0x1.0000004p+0, 0x1.fffffff8p-1, 0x1.0000003cp+0, -0x1p-56 },
    { 0x1.a0c42671c82fbp+0, 0x1.cc81faf6a3e68p+0, 0x1.76da083e73f3ep+1, 0x1.0cebe70efffe0p-54 },
    { 0x1.8000000000001p+1000, -0x1.0000000000003p+10, -0x1.8000000000006p+1010, 0x1.ffffffffffff4p+956 },
    { 0x1.0000000000001p-10, 0x1.fffffffffffffp+1005, 0x1p+996, 0x1.ffffffffffffep+942 },
    { 0x1.0000000000001p-500, 0x1.0000000000001p-469, 0x1.0000000000002p-969, 0x1p-1073 },
    { -0x1.1111111111111p-485, 0x1.fffffffffffffp-484, -0x1.111111111111p-968, -0x1.ddddddddddddep-1022 },
    { 0x0.0000000000003p-1022, 0x1.5555555555555p+200, 0x1p-872, -0x1p-926 },
    { 0x1.fffffffffffffp+511, 0x1.fffffffffffffp+505, 0x1.ffffffffffffep+1017, 0x1p+912 },
};

/* two_sum(a, b) == (s, e), s + e == a + b exactly.  Columns: a, b, s, e. */
static const double cbx_sum_cases[][4] = {
    { 0x1p+0, 0x1p-60, 0x1p+0, 0x1p-60 },
    { 0x1.fffffffffffffp+1018, 0x1.0000000000001p+966, 0x1p+1019, 0x1p+914 },
    { 0x0.0000000000001p-1022, 0x1p-1000, 0x1p-1000, 0x1p-1074 },
    { 0x1.999999999999ap-4, 0x1.999999999999ap-3, 0x1.3333333333334p-2, -0x1p-55 },
};

/* sqrt(x) == r.  Hard cases: x = M^2 - k 2^-106 (M a midpoint between two
 * doubles, k = 1, -7, 9, -15, 17, -23 in units of M's last place squared), so
 * sqrt(x) lies within about 2^-52 ulp of M: the rounding direction is
 * decided at the 106th bit.  Then the same scaled by 2^+-1000, and exact
 * squares (subnormal inputs included).  Columns: x, r. */
static const double cbx_sqrt_cases[][2] = {
    { 0x1.0000000000001p+0, 0x1p+0 },                 /* k = 1: just below M */
    { 0x1.fffffffffffffp+1, 0x1.fffffffffffffp+0 },
    { 0x1.d407bb3641da5p+0, 0x1.5a24e31b39fa6p+0 },   /* k = -7: just above M */
    { 0x1.5b95344972fe2p+1, 0x1.a5db1ce4c605bp+0 },
    { 0x1.0000000000003p+0, 0x1.0000000000001p+0 },   /* k = 9 */
    { 0x1.ffffffffffffdp+1, 0x1.ffffffffffffep+0 },
    { 0x1.2b035c1197f48p+0, 0x1.14ac03ef7226dp+0 },   /* k = -15 */
    { 0x1.256565cadcbf4p+0, 0x1.120f999e99374p+0 },   /* k = 17 */
    { 0x1.e99893042c2cbp+0, 0x1.62077061349eap+0 },   /* k = -23 */
    { 0x1.4eb5f85e783a9p+1, 0x1.9df88f9ecb617p+0 },
    { 0x1.d407bb3641da5p+1000, 0x1.5a24e31b39fa6p+500 },
    { 0x1.0000000000003p-1000, 0x1.0000000000001p-500 },
    { 0x1.2p+1, 0x1.8p+0 },                           /* exact squares */
    { 0x1.ffffff0000002p+51, 0x1.ffffff8p+25 },      /* (2^26 - 1)^2 */
    { 0x1p-1074, 0x1p-537 },                          /* subnormal inputs */
    { 0x1.2p-1071, 0x1.8p-536 },
};
#endif

#if defined(CBX_IEEE_CASES_ALL) || CBX_INST == 32
/* sqrtf(x) == r, the same construction for binary32 (M^2 - k 2^-48). */
static const float cbx_sqrtf_cases[][2] = {
    { 0x1.000002p+0f, 0x1p+0f },
    { 0x1.fffffep+1f, 0x1.fffffep+0f },
    { 0x1.f82294p+0f, 0x1.673f4cp+0f },
    { 0x1.000006p+0f, 0x1.000002p+0f },
    { 0x1.fffffap+1f, 0x1.fffffcp+0f },
    { 0x1.24b0b2p+0f, 0x1.11bb28p+0f },
    { 0x1.dd26e4p+1f, 0x1.ee44dap+0f },
    { 0x1.618d86p+0f, 0x1.2cd916p+0f },
    { 0x1.aa3b7ep+1f, 0x1.d326e8p+0f },
    { 0x1.52f7dep+0f, 0x1.2693d4p+0f },
    { 0x1.b5c076p+1f, 0x1.d96c2ep+0f },
    { 0x1.f82294p+100f, 0x1.673f4cp+50f },
    { 0x1.2p+1f, 0x1.8p+0f },                          /* exact squares */
    { 0x1p-148f, 0x1p-74f },                           /* subnormal inputs */
    { 0x1.2p-145f, 0x1.8p-73f },
};
#endif


/* Division, correctly rounded (C99 Annex F): a, b, RN(a / b).  Thirds and
 * tenths (halfway tails), quotients next to 1, a subnormal quotient, one
 * near the top of the range that cbx_quot_ok admits; recomputed with MPFR
 * by tests/test_eft. */
static const double cbx_div_cases[][3] = {
    { 0x1p+0, 0x1.8p+1, 0x1.5555555555555p-2 },
    { 0x1p+1, 0x1.8p+1, 0x1.5555555555555p-1 },
    { 0x1p+0, 0x1.4p+3, 0x1.999999999999ap-4 },
    { 0x1.fffffffffffffp+0, 0x1.ffffffffffffep+0, 0x1.0000000000001p+0 },
    { 0x1.23456789abcdep-1000, 0x1.5p+60, 0x0.000000000377bp-1022 },
    { -0x1.8p+900, 0x1.0000000000001p-100, -0x1.7ffffffffffffp+1000 },
    { 0x1.5555555555555p+0, 0x1.aaaaaaaaaaaabp-1, 0x1.9999999999999p+0 },
};
static const float cbx_divf_cases[][3] = {
    { 0x1p+0f, 0x1.8p+1f, 0x1.555556p-2f },
    { 0x1p+1f, 0x1.8p+1f, 0x1.555556p-1f },
    { 0x1p+0f, 0x1.4p+3f, 0x1.99999ap-4f },
    { 0x1.fffffep+0f, 0x1.fffffcp+0f, 0x1.000002p+0f },
    { 0x1.234568p-100f, 0x1.5p+40f, 0x1.bcp-141f },
    { -0x1.8p+100f, 0x1.000002p-20f, -0x1.7ffffep+120f },
};

#endif /* CBX_IEEE_CASES_H */
