/*
 * test_ieee [mode] [expect]: the build check, cbx_ieee_check(), and its teeth.
 *   mode   plain (default): call it as the library was built;
 *          ftz: set the x86 flush-to-zero and denormals-are-zero modes first;
 *          ftzonly, daz: set only one of them (each must be caught alone);
 *          up, down, zero: set that rounding mode first (fesetround)
 *   expect the bits that must be set (default 0: no bit may be set; with
 *          a nonzero expectation other bits may be set too, since one
 *          fault can fail several checks).  scripts/ieee.sh builds the library's check with bad flags
 *          (FMA contraction, reassociation, ...) and runs this with the bits
 *          each must raise (an fma rounded twice, a sqrt rounded twice,
 *          through the test hooks CBX_TEST_NAIVE_FMA / CBX_TEST_NAIVE_SQRT,
 *          and the fma-free build CBX_NO_FMA, which must pass), and checks
 *          that -ffast-math, -ffinite-math-only and x87 arithmetic are
 *          refused at compile time.
 * Prints what it checked; the last line is "N passed, M failed".
 */
#include <fenv.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "certbox.h"

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#define HAVE_MXCSR 1
#endif

/* the CBX_IEEE_* bits of certbox.h, in order */
static const char *const bit_name[] = { "contract", "excess", "ftz", "rounding", "special", "assoc",
                                        "fma", "sqrt", "eft", "div" };
#define NBITS (int)(sizeof bit_name / sizeof bit_name[0])

static void print_bits(unsigned b)
{
    int k, any = 0;
    for (k = 0; k < NBITS; k++)
        if (b & (1u << k)) { printf("%s%s", any ? "," : "", bit_name[k]); any = 1; }
    if (!any) printf("none");
}

/* GCC 12.2 at -O2 drops the rounding of (double)(float)(a * b) in loops
 * its SLP vectorizer packs (found by test_float): a probe, printed, not
 * counted: the library never converts between formats (cbx_ieee_check
 * checks each format on its own), and the tests round through volatile. */
__attribute__((noinline)) static void fill(double R[3][3])
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) R[i][j] = 0.1 * (i + 1) + 0.01 * j;
}

static int slp_probe(void)
{
    double R[3][3], m[3][4], sc = 1.0 / 3;
    int i, j, bad = 0;
    fill(R);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) m[i][j] = (float)(R[i][j] * sc);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            volatile float f = (float)m[i][j];
            if ((double)f != m[i][j]) bad++;
        }
    return bad;
}

int main(int argc, char **argv)
{
    const char *mode = argc > 1 ? argv[1] : "plain";
    unsigned expect = argc > 2 ? (unsigned)strtoul(argv[2], 0, 0) : 0u, got;
    int ok;
    if (!strcmp(mode, "ftz") || !strcmp(mode, "ftzonly") || !strcmp(mode, "daz")) {
#ifdef HAVE_MXCSR
        /* FTZ is MXCSR bit 15 (0x8000), DAZ bit 6 (0x0040) */
        _mm_setcsr(_mm_getcsr() | (!strcmp(mode, "ftz") ? 0x8040u : !strcmp(mode, "daz") ? 0x0040u : 0x8000u));
#else
        printf("test_ieee: ftz mode needs x86 SSE; skipped\n0 passed, 0 failed\n");
        return 0;
#endif
    } else if (!strcmp(mode, "up")) {
        fesetround(FE_UPWARD);
    } else if (!strcmp(mode, "down")) {
        fesetround(FE_DOWNWARD);
    } else if (!strcmp(mode, "zero")) {
        fesetround(FE_TOWARDZERO);
    } else if (strcmp(mode, "plain")) {
        fprintf(stderr, "usage: test_ieee [plain|ftz|ftzonly|daz|up|down|zero] [expected bits]\n");
        return 2;
    }
    got = cbx_ieee_check();
    fesetround(FE_TONEAREST);
    /* the plain build: nothing set; a broken mode or build: at least the
     * expected bits (one fault can fail several checks: under a directed
     * rounding mode the contraction case does not cancel either) */
    ok = expect == 0 ? got == 0 : (got & expect) == expect;
    printf("test_ieee: cbx_ieee_check() in mode %s: ", mode);
    print_bits(got);
    printf(" (expected ");
    print_bits(expect);
    printf(")%s\n", ok ? "" : "  FAILED");
    if (!strcmp(mode, "plain") && expect == 0) {
        int p = slp_probe();
        printf("test_ieee: probe (not counted): this compiler %s the float rounding of "
               "(double)(float)(a*b) in an SLP-vectorized loop (%d of 9 values)\n",
               p ? "DROPS" : "keeps", p);
    }
    printf("%d passed, %d failed\n", ok, !ok);
    return !ok;
}
