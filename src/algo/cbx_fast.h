/*
 * The fast path of the interval transform, both formats: one range check
 * per map (cbx_map_fast) and one per box (cbx_box_fast), then the
 * branch-free kernel of src/algo/cbx_kernel.h on every axis.  Inside the fast
 * range (every linear entry and box end at most 2^509 in magnitude, every
 * translation at most 2^1018; binary32: 2^61 and 2^122) every pair lies in
 * the first magnitude class, so every row is full and the kernel's output
 * is exactly what the careful path (src/algo/cbx_interval.c) computes for it,
 * with CBX_OK.  The checks are IEEE comparisons, false on NaN and
 * infinities: such inputs, inverted boxes and larger magnitudes fail them
 * and take the careful path.
 */
#ifndef CBX_FAST_H
#define CBX_FAST_H

#include "certbox.h"
#include "cbx_prec.h"
#include "cbx_kernel.h"

/* 2 when nb <= x <= b (x then finite), else 0 or 1: no branch (the
 * callers add the counts and compare once).  The bounds come as two
 * literals (-B, B): a negated parameter made Why3 reject the goals. */
/*@ requires \is_finite(nb) && \is_finite(b);
    assigns \nothing;
    ensures rng: 0 <= \result <= 2;
    ensures in: \result == 2 ==> \is_finite(x) && nb <= x <= b;
    ensures all: (\is_finite(x) && nb <= x <= b) ==> \result == 2;
*/
static inline int cbx_in2(cbx_fp x, cbx_fp nb, cbx_fp b)
{
    return (x >= nb) + (x <= b);
}

/* 3 when nb <= l <= h <= b (l, h then finite), else less. */
/*@ requires \is_finite(nb) && \is_finite(b);
    assigns \nothing;
    ensures rng: 0 <= \result <= 3;
    ensures in: \result == 3 ==> \is_finite(l) && \is_finite(h) && nb <= l && l <= h && h <= b;
    ensures all: (\is_finite(l) && \is_finite(h) && nb <= l && l <= h && h <= b) ==> \result == 3;
*/
static inline int cbx_ord3(cbx_fp l, cbx_fp h, cbx_fp nb, cbx_fp b)
{
    return (l >= nb) + (l <= h) + (h <= b);
}

/* 1 when the map is in the fast range (specs: map_fast), else 0. */
/*@ requires valid: \valid_read(a);
    assigns \nothing;
    ensures fast: \result != 0 <==> map_fast(a);
*/
static inline int cbx_map_fast(const cbx_affine *a)
{
    int n = cbx_in2(a->m[0][0], -CBX_K(SB), CBX_K(SB)) + cbx_in2(a->m[0][1], -CBX_K(SB), CBX_K(SB))
          + cbx_in2(a->m[0][2], -CBX_K(SB), CBX_K(SB)) + cbx_in2(a->m[0][3], -CBX_K(RT), CBX_K(RT))
          + cbx_in2(a->m[1][0], -CBX_K(SB), CBX_K(SB)) + cbx_in2(a->m[1][1], -CBX_K(SB), CBX_K(SB))
          + cbx_in2(a->m[1][2], -CBX_K(SB), CBX_K(SB)) + cbx_in2(a->m[1][3], -CBX_K(RT), CBX_K(RT))
          + cbx_in2(a->m[2][0], -CBX_K(SB), CBX_K(SB)) + cbx_in2(a->m[2][1], -CBX_K(SB), CBX_K(SB))
          + cbx_in2(a->m[2][2], -CBX_K(SB), CBX_K(SB)) + cbx_in2(a->m[2][3], -CBX_K(RT), CBX_K(RT));
    return n == 24;
}

/* 1 when the box is in the fast range (specs: box_fast), else 0. */
/*@ requires valid: \valid_read(b);
    assigns \nothing;
    ensures fast: \result != 0 <==> box_fast(b);
*/
static inline int cbx_box_fast(const cbx_box *b)
{
    int n = cbx_ord3(b->lo[0], b->hi[0], -CBX_K(SB), CBX_K(SB)) + cbx_ord3(b->lo[1], b->hi[1], -CBX_K(SB), CBX_K(SB))
          + cbx_ord3(b->lo[2], b->hi[2], -CBX_K(SB), CBX_K(SB));
    return n == 9;
}

/* Lemma function (no code): a row of the fast range is full. */
/* proof: -wp-split */
/*@ requires fin: \is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t)
                  && \is_finite(l0) && \is_finite(h0) && \is_finite(l1) && \is_finite(h1)
                  && \is_finite(l2) && \is_finite(h2);
    requires rm: -CBX_SB <= m0 <= CBX_SB && -CBX_SB <= m1 <= CBX_SB && -CBX_SB <= m2 <= CBX_SB;
    requires rb: -CBX_SB <= l0 <= CBX_SB && -CBX_SB <= h0 <= CBX_SB && -CBX_SB <= l1 <= CBX_SB
                 && -CBX_SB <= h1 <= CBX_SB && -CBX_SB <= l2 <= CBX_SB && -CBX_SB <= h2 <= CBX_SB;
    requires rt: -CBX_RT <= t <= CBX_RT;
    assigns \nothing;
    ensures full: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures dom: in_dom(m0, l0) && in_dom(m0, h0) && in_dom(m1, l1) && in_dom(m1, h1)
                 && in_dom(m2, l2) && in_dom(m2, h2);
*/
static inline void cbx_fast_row(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                                cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2)
{
    (void)m0; (void)m1; (void)m2; (void)t;
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
}

/* Lemma function (no code): on a full row, the kernel's statement is
 * cbx_transform_box's promise for that axis (axis_sound_s), with CBX_OK. */
/*@ requires full: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    requires fin: \is_finite(lo) && \is_finite(hi);
    requires sound: lo <= row_lo(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
                    && hi >= row_hi(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    requires tight: lo_tight(lo, m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
                    && hi_tight(hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    assigns \nothing;
    ensures sound: axis_sound_s(lo, hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures ok: axis_ok_s(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
*/
static inline void cbx_full_axis(cbx_fp lo, cbx_fp hi, cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                                 cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2)
{
    (void)lo; (void)hi; (void)m0; (void)m1; (void)m2; (void)t;
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
}

/* One axis of the fast path: the kernel and its promise. */
/*@ requires fin: \is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t)
                  && \is_finite(l0) && \is_finite(h0) && \is_finite(l1) && \is_finite(h1)
                  && \is_finite(l2) && \is_finite(h2);
    requires rm: -CBX_SB <= m0 <= CBX_SB && -CBX_SB <= m1 <= CBX_SB && -CBX_SB <= m2 <= CBX_SB;
    requires rb: -CBX_SB <= l0 <= CBX_SB && -CBX_SB <= h0 <= CBX_SB && -CBX_SB <= l1 <= CBX_SB
                 && -CBX_SB <= h1 <= CBX_SB && -CBX_SB <= l2 <= CBX_SB && -CBX_SB <= h2 <= CBX_SB;
    requires rt: -CBX_RT <= t <= CBX_RT;
    assigns \nothing;
    ensures sound: axis_sound_s(\result.lo, \result.hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures ok: axis_ok_s(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
*/
static inline cbx_ends cbx_fast_axis(cbx_fp m0, cbx_fp m1, cbx_fp m2, cbx_fp t,
                                     cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2)
{
    cbx_fast_row(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    cbx_ends r = cbx_axis(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    cbx_full_axis(r.lo, r.hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    return r;
}

/* The whole box on the fast path: cbx_transform_box's box_input case,
 * with CBX_OK.  out may be in (the inputs are read first). */
/*@ requires valid: \valid_read(a) && \valid_read(in) && \valid(out);
    requires sep: \separated(out, a) && (\separated(out, in) || out == in);
    requires fast: map_fast(a) && box_fast(in);
    assigns *out;
    CBX_FAST_POST(a, in, out)
*/
static inline cbx_status cbx_fast_box(const cbx_affine *a, const cbx_box *in, cbx_box *out)
{
    cbx_fp l0 = in->lo[0];
    cbx_fp l1 = in->lo[1];
    cbx_fp l2 = in->lo[2];
    cbx_fp h0 = in->hi[0];
    cbx_fp h1 = in->hi[1];
    cbx_fp h2 = in->hi[2];
    cbx_fp a00 = a->m[0][0];
    cbx_fp a01 = a->m[0][1];
    cbx_fp a02 = a->m[0][2];
    cbx_fp a03 = a->m[0][3];
    cbx_fp a10 = a->m[1][0];
    cbx_fp a11 = a->m[1][1];
    cbx_fp a12 = a->m[1][2];
    cbx_fp a13 = a->m[1][3];
    cbx_fp a20 = a->m[2][0];
    cbx_fp a21 = a->m[2][1];
    cbx_fp a22 = a->m[2][2];
    cbx_fp a23 = a->m[2][3];
    cbx_ends r0 = cbx_fast_axis(a00, a01, a02, a03, l0, h0, l1, h1, l2, h2);
    cbx_ends r1 = cbx_fast_axis(a10, a11, a12, a13, l0, h0, l1, h1, l2, h2);
    cbx_ends r2 = cbx_fast_axis(a20, a21, a22, a23, l0, h0, l1, h1, l2, h2);
    out->lo[0] = r0.lo; out->hi[0] = r0.hi;
    out->lo[1] = r1.lo; out->hi[1] = r1.hi;
    out->lo[2] = r2.lo; out->hi[2] = r2.hi;
    /*@ assert same_in: \at(a->m[0][0], Pre) == a00 && \at(a->m[0][1], Pre) == a01 && \at(a->m[0][2], Pre) == a02
          && \at(a->m[0][3], Pre) == a03 && \at(a->m[1][0], Pre) == a10 && \at(a->m[1][1], Pre) == a11
          && \at(a->m[1][2], Pre) == a12 && \at(a->m[1][3], Pre) == a13 && \at(a->m[2][0], Pre) == a20
          && \at(a->m[2][1], Pre) == a21 && \at(a->m[2][2], Pre) == a22 && \at(a->m[2][3], Pre) == a23
          && \at(in->lo[0], Pre) == l0 && \at(in->lo[1], Pre) == l1 && \at(in->lo[2], Pre) == l2
          && \at(in->hi[0], Pre) == h0 && \at(in->hi[1], Pre) == h1 && \at(in->hi[2], Pre) == h2; */
    /*@ assert same_out: out->lo[0] == r0.lo && out->hi[0] == r0.hi
          && out->lo[1] == r1.lo && out->hi[1] == r1.hi
          && out->lo[2] == r2.lo && out->hi[2] == r2.hi; */
    return CBX_OK;
}

#endif /* CBX_FAST_H */
