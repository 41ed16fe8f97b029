/*
 * trs_special.c: the checks' tally of tests/test_trs.c (tests/trs_parts.h),
 * the predicates on output boxes, and the special cases: NaN, zero
 * quaternion, bad shutter or depth, out-of-range entries, empty and
 * infinite boxes, a 180-degree turn whose arc is a tie, instants and cell
 * edges, the pieces, balls and paths of such inputs.
 */
#include <stdio.h>
#include <math.h>

#include "trs_parts.h"

long trt_n_check, trt_n_fail, trt_n_logs;

void trt_check(int ok, const char *what, long pair)
{
    trt_n_check++;
    if (ok) {
        return;
    }
    trt_n_fail++;
    if (trt_n_logs++ < MAX_LOGS) {
        printf("FAIL %s (pair %ld)\n", what, pair);
    }
}

int trt_box_finite(const cbx_box *b)
{
    int i;
    for (i = 0; i < 3; i++) {
        if (!(fabs(b->lo[i]) <= 1e308 && fabs(b->hi[i]) <= 1e308)) {
            return 0;
        }
    }
    return 1;
}

static int box_finite_axis(const cbx_box *b, int i)
{
    return fabs(b->lo[i]) <= 1e308 && fabs(b->hi[i]) <= 1e308;
}

static int is_whole(const cbx_box *b)
{
    int i;
    for (i = 0; i < 3; i++) {
        if (!(b->lo[i] == -HUGE_VAL && b->hi[i] == HUGE_VAL)) {
            return 0;
        }
    }
    return 1;
}

/* ---- special cases ------------------------------------------------------ */

void trt_specials(exact *e)
{
    cbx_trs k0 = { { 1, 2, 3 }, { 0, 0, 0, 1 }, { 1, 1, 1 } };
    cbx_trs k1 = { { 2, 2, 3 }, { 0, 0, 1, 0 }, { 1, 1, 1 } }; /* 180 degrees about z, dot 0: a tie */
    cbx_box b = { { -1, -1, -1 }, { 1, 1, 1 } }, o, o2;
    cbx_trs bad;
    cbx_imat pc[64];
    size_t np = 0;
    cbx_status st;
    int d;
    /* the tie: both arcs covered (exact samples of each direction) */
    for (d = 0; d <= 4; d++) {
        int sgn, k, ok = 1;
        st = cbx_motion_trs_box(&k0, &k1, CBX_SLERP, 0, 1, (unsigned)d, &b, &o);
        trt_check(st == CBX_OK && trt_box_finite(&o), "tie: status", -1);
        for (sgn = -1; sgn <= 1; sgn += 2) {
            trt_ex_keys(e, &k0, &k1, 0, sgn);
            for (k = 0; k <= 32; k++) {
                ok &= trt_sample_in(e, &k0, &k1, k / 32.0, &b, &o);
            }
        }
        trt_check(ok, "tie: both arcs inside", -1);
    }
    bad = k0;
    bad.q[2] = NAN;
    st = cbx_motion_trs_box(&bad, &k1, CBX_SLERP, 0, 1, 3, &b, &o);
    trt_check(st == CBX_EINVAL && is_whole(&o), "NaN quaternion -> EINVAL, whole", -1);
    bad = k0;
    bad.q[0] = bad.q[1] = bad.q[2] = bad.q[3] = 0;
    st = cbx_motion_trs_box(&bad, &k1, CBX_SLERP, 0, 1, 3, &b, &o);
    trt_check(st == CBX_EINVAL && is_whole(&o), "zero quaternion -> EINVAL, whole", -1);
    st = cbx_motion_trs_box(&k0, &k1, CBX_SLERP, 0.7, 0.2, 3, &b, &o);
    trt_check(st == CBX_EINVAL && is_whole(&o), "s0 > s1 -> EINVAL", -1);
    st = cbx_motion_trs_box(&k0, &k1, CBX_SLERP, -0.1, 0.2, 3, &b, &o);
    trt_check(st == CBX_EINVAL && is_whole(&o), "s0 < 0 -> EINVAL", -1);
    st = cbx_motion_trs_box(&k0, &k1, CBX_SLERP, 0, 1, 17, &b, &o);
    trt_check(st == CBX_EINVAL && is_whole(&o), "depth 17 -> EINVAL", -1);
    st = cbx_motion_trs_box(&k0, &k1, (cbx_interp)7, 0, 1, 3, &b, &o);
    trt_check(st == CBX_EINVAL && is_whole(&o), "bad mode -> EINVAL", -1);
    bad = k0;
    bad.t[1] = 0x1p501;
    st = cbx_motion_trs_box(&bad, &k1, CBX_SLERP, 0, 1, 3, &b, &o);
    trt_check(st == CBX_ERANGE && is_whole(&o), "translation 2^501 -> ERANGE, whole", -1);
    bad = k0;
    bad.s[0] = HUGE_VAL;
    st = cbx_motion_trs_box(&bad, &k1, CBX_SLERP, 0, 1, 3, &b, &o);
    trt_check(st == CBX_ERANGE && is_whole(&o), "infinite scale -> ERANGE, whole", -1);
    bad = k0;
    bad.q[3] = 0x1p-130;
    st = cbx_motion_trs_box(&bad, &k1, CBX_SLERP, 0, 1, 3, &b, &o);
    trt_check(st == CBX_ERANGE && is_whole(&o), "tiny quaternion -> ERANGE, whole", -1);
    o2 = b;
    o2.lo[1] = 2;
    st = cbx_motion_trs_box(&k0, &k1, CBX_SLERP, 0, 1, 3, &o2, &o);
    trt_check(st == CBX_EMPTY && o.lo[0] == HUGE_VAL && o.hi[2] == -HUGE_VAL, "empty box -> EMPTY", -1);
    o2 = b;
    o2.lo[1] = NAN;
    st = cbx_motion_trs_box(&k0, &k1, CBX_SLERP, 0, 1, 3, &o2, &o);
    trt_check(st == CBX_EINVAL && is_whole(&o), "NaN box -> EINVAL", -1);
    o2 = b;
    o2.hi[0] = HUGE_VAL; /* x unbounded: every output axis that x reaches */
    st = cbx_motion_trs_box(&k0, &k1, CBX_SLERP, 0, 1, 3, &o2, &o);
    trt_check(st == CBX_ERANGE && o.lo[0] == -HUGE_VAL && o.hi[0] == HUGE_VAL, "infinite end -> ERANGE axis", -1);
    st = cbx_trs_pieces(&k0, &k1, CBX_SLERP, 0, 1, 7, pc, 64, &np);
    trt_check(st == CBX_EINVAL && np == 0, "pieces: 128 needed, cap 64 -> EINVAL", -1);
    st = cbx_transform_box_pieces(pc, 0, &b, &o);
    trt_check(st == CBX_EINVAL && is_whole(&o), "pieces: n = 0 -> EINVAL", -1);
    {
        double c[3] = { 1, 2, 3 }, cn[3] = { 1, NAN, 3 };
        st = cbx_motion_trs_ball(&k0, &k1, CBX_SLERP, 0, 1, 3, cn, 1.0, &o);
        trt_check(st == CBX_EINVAL && is_whole(&o), "ball: NaN centre -> EINVAL", -1);
        st = cbx_motion_trs_ball(&k0, &k1, CBX_SLERP, 0, 1, 3, c, 0x1p501, &o);
        trt_check(st == CBX_ERANGE && is_whole(&o), "ball: radius 2^501 -> ERANGE", -1);
        st = cbx_motion_trs_ball(&bad, &k1, CBX_SLERP, 0, 1, 3, c, 1.0, &o);
        trt_check(st == CBX_ERANGE && is_whole(&o), "ball: tiny quaternion -> ERANGE", -1);
        {   /* pieces a caller filled: a NaN entry, an entry beyond 2^509 */
            cbx_imat bp[2];
            size_t nb = 0;
            cbx_trs_pieces(&k0, &k1, CBX_SLERP, 0, 1, 1, bp, 2, &nb);
            bp[1].lo[0][0] = NAN;
            st = cbx_ball_pieces(bp, nb, c, 1.0, &o);
            trt_check(st == CBX_EINVAL && is_whole(&o), "ball pieces: NaN entry -> EINVAL", -1);
            bp[1].lo[0][0] = -0x1p600;
            st = cbx_ball_pieces(bp, nb, c, 1.0, &o);
            trt_check(st == CBX_ERANGE && o.lo[0] == -HUGE_VAL && o.hi[0] == HUGE_VAL && box_finite_axis(&o, 1),
                  "ball pieces: entry 2^600 -> ERANGE on that axis", -1);
        }
        st = cbx_ball_pieces(pc, 0, c, 1.0, &o);
        trt_check(st == CBX_EINVAL && is_whole(&o), "ball pieces: n = 0 -> EINVAL", -1);
        cbx_trs_pieces(&k0, &k1, CBX_SLERP, 0, 1, 2, pc, 64, &np);
        st = cbx_ball_pieces(pc, np, c, 0x1p501, &o);
        trt_check(st == CBX_ERANGE && is_whole(&o), "ball pieces: radius 2^501 -> ERANGE", -1);
        st = cbx_ball_pieces(pc, 0, c, 1.0, &o);
        trt_check(st == CBX_EINVAL && is_whole(&o), "ball pieces: n = 0 -> EINVAL", -1);
        st = cbx_motion_trs_ball(&k0, &k1, CBX_SLERP, 0, 1, 2, c, 0.0, &o);
        trt_check(st == CBX_OK && trt_box_finite(&o), "ball: radius 0 (a moving point)", -1);
    }
    /* instants and cell edges: s0 = s1 at 0, 1/2 (a cell edge) and 1 */
    {
        static const double inst[3] = { 0.0, 0.5, 1.0 };
        int m, q;
        for (q = 0; q < 2; q++) {
            for (m = 0; m < 3; m++) {
                int okk;
                st = cbx_motion_trs_box(&k0, &k1, q ? CBX_NLERP : CBX_SLERP, inst[m], inst[m], 3, &b, &o);
                trt_ex_keys(e, &k0, &k1, q, 1);
                okk = trt_sample_in(e, &k0, &k1, inst[m], &b, &o);
                trt_ex_keys(e, &k0, &k1, q, -1);
                okk &= trt_sample_in(e, &k0, &k1, inst[m], &b, &o);
                trt_check(st == CBX_OK && okk, "instant: the exact image inside", -1);
            }
        }
    }
    /* pieces: bad keyframes, and boxes that are not ordinary */
    st = cbx_trs_pieces(&bad, &k1, CBX_SLERP, 0, 1, 3, pc, 64, &np);
    trt_check(st == CBX_ERANGE && np == 0, "pieces: tiny quaternion -> ERANGE, none", -1);
    st = cbx_trs_pieces(&k0, &k1, CBX_SLERP, 0, 1, 3, pc, 64, &np);
    trt_check(st == CBX_OK && np == 8, "pieces: 8 at depth 3", -1);
    o2 = b;
    o2.hi[0] = HUGE_VAL;
    st = cbx_transform_box_pieces(pc, np, &o2, &o);
    trt_check(st == CBX_ERANGE && o.lo[0] == -HUGE_VAL && o.hi[0] == HUGE_VAL, "pieces: infinite end -> ERANGE", -1);
    o2 = b;
    o2.lo[2] = NAN;
    st = cbx_transform_box_pieces(pc, np, &o2, &o);
    trt_check(st == CBX_EINVAL && is_whole(&o), "pieces: NaN box -> EINVAL", -1);
    o2 = b;
    o2.lo[2] = 5;
    st = cbx_transform_box_pieces(pc, np, &o2, &o);
    trt_check(st == CBX_EMPTY && o.lo[0] == HUGE_VAL, "pieces: empty box -> EMPTY", -1);
    st = cbx_motion_trs_path(&k0, 0, CBX_SLERP, 0, 1, 3, &b, &o);
    trt_check(st == CBX_EINVAL && is_whole(&o), "path: no keyframe -> EINVAL", -1);
    {
        cbx_trs ks[3];
        ks[0] = k0;
        ks[1] = k1;
        ks[2] = k0;
        st = cbx_motion_trs_path(ks, 3, CBX_SLERP, 0.7, 0.2, 3, &b, &o);
        trt_check(st == CBX_EINVAL && is_whole(&o), "path: s0 > s1 -> EINVAL", -1);
        o2 = b;
        o2.lo[0] = 3;
        st = cbx_motion_trs_path(ks, 3, CBX_SLERP, 0, 1, 3, &o2, &o);
        trt_check(st == CBX_EMPTY && o.lo[1] == HUGE_VAL && o.hi[1] == -HUGE_VAL, "path: empty box -> EMPTY", -1);
        ks[2].t[0] = NAN;
        st = cbx_motion_trs_path(ks, 3, CBX_SLERP, 0, 1, 3, &b, &o);
        trt_check(st == CBX_EINVAL && is_whole(&o), "path: NaN keyframe -> EINVAL", -1);
    }
    st = cbx_motion_trs_path(&k0, 1, CBX_SLERP, 0, 1, 3, &b, &o);
    trt_check(st == CBX_OK && o.lo[0] <= 0 && o.hi[0] >= 2, "path: one keyframe, still", -1);
}
