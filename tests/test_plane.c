/*
 * test_plane [N] [seed]: the 2D form (cbx_transform_box2, cbx_transform_box2f)
 * against exact rational arithmetic, in both formats.
 *
 * Each case is a 2D map and box.  Its embedding in 3D has the same two
 * rows with a zero third column, a zero third row, and the third box axis
 * [0, 0]: the 2D contract is the 3D one on that plane (specs/cbx_plane.h).
 * For every case:
 *   1. oracle: the 2D output, with the third axis of the 3D call, is judged
 *      by exact_util's oracle on the embedding (xu_check_result: the status
 *      computed exactly, the special outputs, containment of the exact
 *      image and the proven bound 12 u S + eta on every finite end, the
 *      end kinds of half-planes and out-of-domain rows; the corners in mpq
 *      on every 50th case);
 *   2. the same bits as the 3D function on the embedding (axes 0, 1 and the
 *      status): the 2D form is not a second algorithm;
 *   3. in place (out == in) gives the same bits; the inputs are unchanged.
 * Cases: a table of 2D hard cases (NaN in each of the 10 inputs, empty
 * axes, half-planes, the domain's edges, rotations, subnormals), then N
 * random cases drawn by test_exact's generator (rows 0 and 1, box axes 0
 * and 1), in binary64 and then in binary32 (values rounded to float).
 * The center form (cbx_transform_cbox2, cbx_transform_cbox2f): the status
 * against exact_util's cbox rules on the 3D embedding, the special
 * outputs, every lost axis exactly c = 0, h = +inf, every other axis
 * finite and holding the exact image of the 4 corners c_j -+ h_j (mpq,
 * zero-coefficient columns dropped as the contract says), and the same
 * bits as cbx_transform_cbox on the embedding (whose tightness test_cbox
 * checks exactly).
 * The conversions (cbx_box2_to_cbox2, cbx_cbox2_to_box2 and their binary32
 * twins): the status and special outputs from the domain, each converted
 * axis holding its input axis and within the proven 16 u (|x| + |y|) +
 * 2^-1066 (binary32: 2^-141) of it, both in mpq, and the same bits as the
 * 3D conversions on the embedding.
 * Disks and ellipses (cbx_disk_box2, cbx_ellipse_box2 and their binary32
 * twins): on every axis the status and the special outputs as computed
 * from the domain (NaN -> CBX_EINVAL and the whole plane; an axis outside
 * the domain exactly [-inf, +inf] with CBX_ERANGE); on an axis in the
 * domain, t -+ sqrt(s) (s = m_i0^2 + m_i1^2, for the ellipse with
 * m_ij = rot_ij radii_j, all exact in GMP) inside [lo, hi], and each end
 * within the proven 80 u (|t| + sqrt s) + 2^-1064 (binary32: 2^-139), both
 * decided exactly in integers; and the same bits as cbx_sphere_box /
 * cbx_ellipsoid_box on the 3D embedding.  A table of hard cases, then N
 * random disks and N random ellipses per format.
 * The last line is "P passed, F failed".
 *
 * This file is the driver (arguments, the order of the suites, the last
 * line); the suites are in tests/plane_box.c, tests/plane_cbox.c and
 * tests/plane_balls.c, their hard cases in tests/plane_cases.c
 * (tests/plane_parts.h).
 */
#include <stdint.h>
#include <stdio.h>

#include "plane_parts.h"

int main(int argc, char **argv)
{
    long n = (long)xu_arg_num(argc, argv, 1, 200000, "test_plane [N] [seed]");
    uint64_t seed = xu_arg_num(argc, argv, 2, 7, "test_plane [N] [seed]");
    xu_exact x;
    long failed = 0, passed = 0;
    xu_init(&x);
    printf("test_plane: the 2D family (boxes in both forms, conversions, disks, ellipses; both formats) against exact "
           "rationals, N = %ld, seed = %llu\n", n,
           (unsigned long long)seed);
    xu_set_format(&xu_binary64);
    failed += plt_family(&x, "cbx_transform_box2 (binary64)", plt_run64, n, seed, &passed);
    xu_set_format(&xu_binary32);
    failed += plt_family(&x, "cbx_transform_box2f (binary32)", plt_run32, n, seed + 1, &passed);
    xu_set_format(&xu_binary64);
    failed += plt_cboxes(0, n / 2, seed + 4, &passed);
    xu_set_format(&xu_binary32);
    failed += plt_cboxes(1, n / 2, seed + 5, &passed);
    xu_set_format(&xu_binary64);
    failed += plt_convs(0, n / 2, seed + 6, &passed);
    xu_set_format(&xu_binary32);
    failed += plt_convs(1, n / 2, seed + 7, &passed);
    xu_set_format(&xu_binary64);
    failed += plt_balls(&x, &plt_bf64, n / 2, seed + 2, &passed);
    xu_set_format(&xu_binary32);
    failed += plt_balls(&x, &plt_bf32, n / 2, seed + 3, &passed);
    xu_clear(&x);
    printf("%ld passed, %ld failed\n", passed, failed);
    return failed ? 1 : 0;
}
