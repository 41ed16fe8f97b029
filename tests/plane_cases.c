/*
 * The 2D hard cases of test_plane (tests/plane_parts.h: NaN in each of the
 * 10 inputs, empty axes, half-planes, the domain's edges, rotations,
 * subnormals), shared by the box, center form and conversion suites, and
 * the failure log all suites share.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "plane_parts.h"

#define INF HUGE_VAL
const plane_case plt_hard[] = {
    { "identity", { { 1, 0, 0 }, { 0, 1, 0 } }, { -1, -2 }, { 3, 4 } },
    { "rotation by 90 degrees", { { 0, -1, 5 }, { 1, 0, -5 } }, { -1, -2 }, { 3, 4 } },
    { "rotation by 30 degrees", { { 0.8660254037844387, -0.5, 0 }, { 0.5, 0.8660254037844387, 0 } },
      { -1, -1 }, { 1, 1 } },
    { "shear and mirror", { { -1, 3, 0.1 }, { 0, -1, 1e-300 } }, { 0.1, -0.3 }, { 0.7, 0.2 } },
    { "point box", { { 3, 5, 7 }, { 11, 13, 17 } }, { 0.1, 0.2 }, { 0.1, 0.2 } },
    { "subnormal entries", { { 0x1p-1074, -0x1p-1060, 0x1p-1070 }, { 1, 0x1p-1074, 0 } },
      { -0x1p-1074, 3 }, { 0x1p-1000, 4 } },
    { "-0 entries and ends", { { -0.0, 1, -0.0 }, { 1, -0.0, 0 } }, { -0.0, -0.0 }, { 0, 0 } },
    { "entries at 2^509", { { 0x1p509, -0x1p509, 0x1p1018 }, { 0x1p509, 0x1p509, -0x1p1018 } },
      { -0x1p509, -0x1p509 }, { 0x1p509, 0x1p509 } },
    { "product above the domain", { { 0x1p600, 1, 0 }, { 1, 1, 0 } }, { -0x1p500, 0 }, { 0x1p500, 1 } },
    { "half-plane x >= 2", { { 1, 1, 0 }, { -1, 2, 0 } }, { 2, 0 }, { INF, 1 } },
    { "half-plane x <= 2 times zero", { { 0, 1, 0 }, { 1, 0, 0 } }, { -INF, 0 }, { 2, 1 } },
    { "the whole plane", { { 1, 0, 0 }, { 0, 0, 1 } }, { -INF, -INF }, { INF, INF } },
    { "infinite entry", { { INF, 0, 0 }, { 1, 1, 1 } }, { 0, 0 }, { 1, 1 } },
    { "infinite translation", { { 1, 0, -INF }, { 1, 1, 1 } }, { 0, 0 }, { 1, 1 } },
    { "empty axis 0", { { 1, 0, 0 }, { 0, 1, 0 } }, { 1, 0 }, { 0, 1 } },
    { "empty axis 1 (+inf, +inf)", { { 1, 0, 0 }, { 0, 1, 0 } }, { 0, INF }, { 1, INF } },
    { "NaN m00", { { NAN, 0, 0 }, { 0, 1, 0 } }, { 0, 0 }, { 1, 1 } },
    { "NaN m01", { { 1, NAN, 0 }, { 0, 1, 0 } }, { 0, 0 }, { 1, 1 } },
    { "NaN t0", { { 1, 0, NAN }, { 0, 1, 0 } }, { 0, 0 }, { 1, 1 } },
    { "NaN m10", { { 1, 0, 0 }, { NAN, 1, 0 } }, { 0, 0 }, { 1, 1 } },
    { "NaN m11", { { 1, 0, 0 }, { 0, NAN, 0 } }, { 0, 0 }, { 1, 1 } },
    { "NaN t1", { { 1, 0, 0 }, { 0, 1, NAN } }, { 0, 0 }, { 1, 1 } },
    { "NaN lo0 with an empty axis", { { 1, 0, 0 }, { 0, 1, 0 } }, { NAN, 1 }, { 1, 0 } },
    { "NaN lo1", { { 1, 0, 0 }, { 0, 1, 0 } }, { 0, NAN }, { 1, 1 } },
    { "NaN hi0", { { 1, 0, 0 }, { 0, 1, 0 } }, { 0, 0 }, { NAN, 1 } },
    { "NaN hi1", { { 1, 0, 0 }, { 0, 1, 0 } }, { 0, 0 }, { 1, NAN } },
};
#define N_HARD ((int)(sizeof plt_hard / sizeof plt_hard[0]))
const int plt_n_hard = N_HARD;

static long fail_logs;

void plt_fail(const char *fam, const char *what, const char *why)
{
    if (fail_logs++ < 20) printf("FAIL %s %s: %s\n", fam, what, why);
}

/* +inf, -inf */
int plt_is_pinf(double d) { return d > 0 && isinf(d); }
int plt_is_ninf(double d) { return d < 0 && isinf(d); }

