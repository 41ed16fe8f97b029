/*
 * NOT BUILT, NOT PROVEN AS A WHOLE: the vectorised batch of issue 17, as it
 * stood when the session ran out of proof time (kept as a reproducer and a
 * starting point; src/algo/cbx_batch.c is the proven per-box loop).
 *
 * What it does: under a general map of the fast range, 8 boxes at a time
 * are copied into six local arrays (structure of arrays), the kernel runs
 * lane by lane in a loop that gcc -O2 vectorises (16-byte vectors,
 * -fopt-info-vec), and the boxes are written back with put_box.  Measured
 * (make bench's row 3b, same machine and run as docs/measurements.md): about
 * 1.2x classic Arvo per box with one map, against 2.45x for the per-box
 * loop; bit-identical outputs (tests/test_batch, bench's checks).
 *
 * What proved (dev runs, CVC4 + Z3, 30 s per goal): fast_block 209/209
 * goals without the w parameter (lane_done carries the kernel's statement
 * from the copies to the box's own ends: ACSL == on doubles is equality of
 * real values, so \is_finite and predicates over doubles do not follow a
 * copy; below8/above8/tightness depend only on the real values); the kernel
 * loop's invariant over the local (logic) arrays is cheap.
 * What did not: the glue in batch().  Each lane's promise has to be carried
 * from fast_block's pre-state to batch's pre-state across the writes of
 * earlier iterations (the separation of in[] and out[] per lane): about
 * 9-10 s of CVC4 per lane and per split part, 14-15 s for the severity
 * invariant, and fast_block's 'this' went over 30 s once box_sev_le was
 * added.  A version for CI would need that transfer done once per block
 * (e.g. the block's results kept as values in batch()'s own local arrays, or
 * a lemma function per block), not per lane and goal.
 */
/*
 * Batch forms of the interval transform: cbx_transform_boxes (a map) and
 * cbx_transform_boxes_prep (a prepared map), the most severe status met.
 * binary64: the map's class is found once per call (cbx_classify, so a
 * prepared map's recorded class and fast flag are not trusted here); a
 * general map sends every box to cbx_transform_box (one range check of the
 * map and one of the box, then the branch-free kernel), a map of a smaller
 * class to the class kernel (cbx_transform_box_as).  binary32:
 * cbx_transform_boxf.  Either way out[k] is exactly
 * cbx_transform_box_as(a, cbx_classify(a), in + k, out + k)'s output
 * (binary32: cbx_transform_boxf's).  The call for box k writes exactly
 * out[k]; the loop invariant carries each finished box's whole promise as a
 * predicate on values (box_done_m), which a write elsewhere cannot touch.
 */
#include "certbox.h"
#include "cbx_onebox.h"
#include "cbx_fast.h"
/* The per-box kernel: the class kernel in binary64, the general one in
 * binary32 (where CBX_CLS_ARG and the class clauses vanish). */
#if CBX_INST == 64
#define CBX_CLS_PARAM , cbx_class cls
#define CBX_CLS_ARG , cls
#define CBX_ONE_BOX(a, b) one_box_as(a, cls, b)
#define CBX_IS_GENERAL (cls == CBX_CLASS_GENERAL)
#else
#define CBX_CLS_PARAM
#define CBX_CLS_ARG
#define CBX_ONE_BOX(a, b) one_box(a, b)
#define CBX_IS_GENERAL 1
#endif

/* Severity order of the statuses (specs: sev). */
/*@ assigns \nothing;
    ensures \result == sev(s);
*/
static int severity(cbx_status s)
{
    if (s == CBX_EINVAL) return 3;
    if (s == CBX_ERANGE) return 2;
    if (s == CBX_EMPTY) return 1;
    return 0;
}


/* Write out[k]; every other out[j] is left alone (a small goal of its own:
 * with the box promise in context the provers do not find this frame). */
/*@ requires valid: \valid(out + (0 .. n - 1));
    requires k: k < n;
    assigns out[k];
    ensures val: out[k] == o;
    ensures frame: \forall integer j; 0 <= j < n && j != k ==> out[j] == \at(out[j], Pre);
*/
static void put_box(cbx_box *out, size_t k, size_t n, cbx_box o)
{
    (void)n;
    out[k] = o;
}

/* ---- the vectorised block ----------------------------------------------
 * Under a map of the fast range, CBX_LANES boxes of the fast range at a
 * time: the boxes are copied into one array per end (structure of arrays),
 * the kernel (src/algo/cbx_fast.h) runs on them in a loop with a constant trip
 * count and no branch, which compilers vectorise (gcc -O2: 16-byte vectors;
 * -fopt-info-vec shows it), and the ends are written back box by box.  The
 * same operations in the same order as cbx_transform_box: the same bits. */
#define CBX_LANES 8
/* Box k + d of a block has its promise, with CBX_OK (one conjunct per lane
 * in fast_block's contract: the caller then needs no quantifier
 * instantiation across the block). */
#define CBX_LANE_DONE(d, w) (\forall integer j; j == k + (d) ==> \
      box_done_m(CBX_AV(a, Pre), CBX_BV(in + j, Pre), out[j]) \
      && box_sev_v(CBX_AV(a, Pre), CBX_BV(in + j, Pre), 0) \
      && box_sev_le(CBX_AV(a, Pre), CBX_BV(in + j, Pre), w))

/* 1 when the CBX_LANES boxes from in on are all in the fast range. */
/*@ requires valid: \valid_read(in + (0 .. CBX_LANES - 1));
    assigns \nothing;
    ensures fast: \result != 0 ==> \forall integer j; 0 <= j < CBX_LANES ==> box_fast(in + j);
*/
static int block_fast(const cbx_box *in)
{
    int c = 0;
    int j;
    /*@ loop invariant rng: 0 <= j <= CBX_LANES && 0 <= c <= j;
        loop invariant all: c == j ==> \forall integer i; 0 <= i < j ==> box_fast(in + i);
        loop assigns j, c;
        loop variant CBX_LANES - j;
    */
    for (j = 0; j < CBX_LANES; j++)
        c += cbx_box_fast(in + j) != 0;
    return c == CBX_LANES;
}

/* One box's promise from the kernel's statements on its values (lemma
 * function).  The kernel ran on copies of the box's ends (v0 .. w2, the
 * structure of arrays), equal as reals to the ends l0 .. h2 and finite like
 * them: the statements depend only on that, so they carry over.  A map and
 * a box of the fast range have no NaN and no empty axis, so box_done_m is
 * the three axes' statement, with CBX_OK. */
/*@ requires fin: map_fin(a00, a01, a02, a03) && map_fin(a10, a11, a12, a13) && map_fin(a20, a21, a22, a23);
    requires box: \is_finite(l0) && \is_finite(h0) && \is_finite(l1) && \is_finite(h1)
                  && \is_finite(l2) && \is_finite(h2) && l0 <= h0 && l1 <= h1 && l2 <= h2;
    requires cpy: \is_finite(v0) && \is_finite(w0) && \is_finite(v1) && \is_finite(w1)
                  && \is_finite(v2) && \is_finite(w2)
                  && v0 == l0 && w0 == h0 && v1 == l1 && w1 == h1 && v2 == l2 && w2 == h2;
    requires full: row_full(a00, a01, a02, a03, l0, h0, l1, h1, l2, h2)
                   && row_full(a10, a11, a12, a13, l0, h0, l1, h1, l2, h2)
                   && row_full(a20, a21, a22, a23, l0, h0, l1, h1, l2, h2)
                   && row_full(a00, a01, a02, a03, v0, w0, v1, w1, v2, w2)
                   && row_full(a10, a11, a12, a13, v0, w0, v1, w1, v2, w2)
                   && row_full(a20, a21, a22, a23, v0, w0, v1, w1, v2, w2);
    requires w: w >= 0;
    requires ax: axis_sound_s(O.lo[0], O.hi[0], a00, a01, a02, a03, v0, w0, v1, w1, v2, w2)
                 && axis_sound_s(O.lo[1], O.hi[1], a10, a11, a12, a13, v0, w0, v1, w1, v2, w2)
                 && axis_sound_s(O.lo[2], O.hi[2], a20, a21, a22, a23, v0, w0, v1, w1, v2, w2);
    assigns \nothing;
    ensures done: box_done_m(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23,
                             l0, h0, l1, h1, l2, h2, O);
    ensures sev: box_sev_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23,
                           l0, h0, l1, h1, l2, h2, 0);
    ensures le: box_sev_le(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23,
                           l0, h0, l1, h1, l2, h2, w);
*/
static void lane_done(cbx_fp a00, cbx_fp a01, cbx_fp a02, cbx_fp a03, cbx_fp a10, cbx_fp a11,
                      cbx_fp a12, cbx_fp a13, cbx_fp a20, cbx_fp a21, cbx_fp a22, cbx_fp a23,
                      cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2,
                      cbx_fp v0, cbx_fp w0, cbx_fp v1, cbx_fp w1, cbx_fp v2, cbx_fp w2, cbx_box O,
                      int w)
{
    (void)a00; (void)a01; (void)a02; (void)a03; (void)a10; (void)a11; (void)a12; (void)a13;
    (void)a20; (void)a21; (void)a22; (void)a23;
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2;
    (void)v0; (void)w0; (void)v1; (void)w1; (void)v2; (void)w2; (void)O; (void)w;
    /*@ assert b0: below8(O.lo[0], a00, a01, a02, a03, l0, h0, l1, h1, l2, h2)
                   && above8(O.hi[0], a00, a01, a02, a03, l0, h0, l1, h1, l2, h2)
                   && lo_tight(O.lo[0], a00, a01, a02, a03, l0, h0, l1, h1, l2, h2)
                   && hi_tight(O.hi[0], a00, a01, a02, a03, l0, h0, l1, h1, l2, h2); */
    /*@ assert b1: below8(O.lo[1], a10, a11, a12, a13, l0, h0, l1, h1, l2, h2)
                   && above8(O.hi[1], a10, a11, a12, a13, l0, h0, l1, h1, l2, h2)
                   && lo_tight(O.lo[1], a10, a11, a12, a13, l0, h0, l1, h1, l2, h2)
                   && hi_tight(O.hi[1], a10, a11, a12, a13, l0, h0, l1, h1, l2, h2); */
    /*@ assert b2: below8(O.lo[2], a20, a21, a22, a23, l0, h0, l1, h1, l2, h2)
                   && above8(O.hi[2], a20, a21, a22, a23, l0, h0, l1, h1, l2, h2)
                   && lo_tight(O.lo[2], a20, a21, a22, a23, l0, h0, l1, h1, l2, h2)
                   && hi_tight(O.hi[2], a20, a21, a22, a23, l0, h0, l1, h1, l2, h2); */
    /*@ assert f: \is_finite(O.lo[0]) && \is_finite(O.hi[0]) && \is_finite(O.lo[1])
                  && \is_finite(O.hi[1]) && \is_finite(O.lo[2]) && \is_finite(O.hi[2]); */
    /*@ assert s0: axis_sound_s(O.lo[0], O.hi[0], a00, a01, a02, a03, l0, h0, l1, h1, l2, h2); */
    /*@ assert s1: axis_sound_s(O.lo[1], O.hi[1], a10, a11, a12, a13, l0, h0, l1, h1, l2, h2); */
    /*@ assert s2: axis_sound_s(O.lo[2], O.hi[2], a20, a21, a22, a23, l0, h0, l1, h1, l2, h2); */
    /*@ assert nn: !nan_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23, l0, h0, l1, h1, l2, h2); */
    /*@ assert ne: !empty_v(l0, h0, l1, h1, l2, h2); */
    /*@ assert dv: box_done_v(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23,
                              l0, h0, l1, h1, l2, h2, O.lo[0], O.hi[0], O.lo[1], O.hi[1], O.lo[2], O.hi[2]); */
}

/* Boxes k .. k + CBX_LANES - 1, all of the fast range, under a map of the
 * fast range: each out[j] gets its box's promise with CBX_OK; every other
 * out[j] is left alone. */
/*@ requires valid: \valid_read(a) && \valid_read(in + (0 .. n - 1)) && \valid(out + (0 .. n - 1));
    requires sep: \separated(out + (0 .. n - 1), a) && \separated(out + (0 .. n - 1), in + (0 .. n - 1));
    requires k: k + CBX_LANES <= n;
    requires fast: map_fast(a) && \forall integer j; k <= j < k + CBX_LANES ==> box_fast(in + j);
    requires w: w >= 0;
    assigns out[k .. k + CBX_LANES - 1];
    ensures done: CBX_LANE_DONE(0, w) && CBX_LANE_DONE(1, w) && CBX_LANE_DONE(2, w) && CBX_LANE_DONE(3, w)
                  && CBX_LANE_DONE(4, w) && CBX_LANE_DONE(5, w) && CBX_LANE_DONE(6, w) && CBX_LANE_DONE(7, w);
    ensures frame: \forall integer j; 0 <= j < n && (j < k || k + CBX_LANES <= j) ==>
      out[j] == \at(out[j], Pre);
*/
static void fast_block(const cbx_affine *a, const cbx_box *in, cbx_box *out, size_t k, size_t n,
                       int w)
{
    cbx_fp L0[CBX_LANES], H0[CBX_LANES], L1[CBX_LANES], H1[CBX_LANES], L2[CBX_LANES], H2[CBX_LANES];
    cbx_fp P0[CBX_LANES], Q0[CBX_LANES], P1[CBX_LANES], Q1[CBX_LANES], P2[CBX_LANES], Q2[CBX_LANES];
    cbx_fp a00 = a->m[0][0], a01 = a->m[0][1], a02 = a->m[0][2], a03 = a->m[0][3];
    cbx_fp a10 = a->m[1][0], a11 = a->m[1][1], a12 = a->m[1][2], a13 = a->m[1][3];
    cbx_fp a20 = a->m[2][0], a21 = a->m[2][1], a22 = a->m[2][2], a23 = a->m[2][3];
    size_t j;
    /*@ loop invariant rng: 0 <= j <= CBX_LANES;
        loop invariant got: \forall integer i; 0 <= i < j ==>
          L0[i] == in[k + i].lo[0] && H0[i] == in[k + i].hi[0] && L1[i] == in[k + i].lo[1]
          && H1[i] == in[k + i].hi[1] && L2[i] == in[k + i].lo[2] && H2[i] == in[k + i].hi[2];
        loop invariant fin: \forall integer i; 0 <= i < j ==>
          \is_finite(L0[i]) && \is_finite(H0[i]) && \is_finite(L1[i]) && \is_finite(H1[i])
          && \is_finite(L2[i]) && \is_finite(H2[i]);
        loop invariant fast: \forall integer i; 0 <= i < j ==>
          -CBX_SB <= L0[i] && L0[i] <= H0[i] && H0[i] <= CBX_SB
          && -CBX_SB <= L1[i] && L1[i] <= H1[i] && H1[i] <= CBX_SB
          && -CBX_SB <= L2[i] && L2[i] <= H2[i] && H2[i] <= CBX_SB;
        loop assigns j, L0[0 .. CBX_LANES - 1], H0[0 .. CBX_LANES - 1], L1[0 .. CBX_LANES - 1],
                     H1[0 .. CBX_LANES - 1], L2[0 .. CBX_LANES - 1], H2[0 .. CBX_LANES - 1];
        loop variant CBX_LANES - j;
    */
    for (j = 0; j < CBX_LANES; j++) {
        /*@ assert lane: box_fast(in + (k + j)); */
        L0[j] = in[k + j].lo[0]; H0[j] = in[k + j].hi[0];
        L1[j] = in[k + j].lo[1]; H1[j] = in[k + j].hi[1];
        L2[j] = in[k + j].lo[2]; H2[j] = in[k + j].hi[2];
    }
    /*@ loop invariant rng: 0 <= j <= CBX_LANES;
        loop invariant ax: \forall integer i; 0 <= i < j ==>
          axis_sound_s(P0[i], Q0[i], a00, a01, a02, a03, L0[i], H0[i], L1[i], H1[i], L2[i], H2[i])
          && axis_sound_s(P1[i], Q1[i], a10, a11, a12, a13, L0[i], H0[i], L1[i], H1[i], L2[i], H2[i])
          && axis_sound_s(P2[i], Q2[i], a20, a21, a22, a23, L0[i], H0[i], L1[i], H1[i], L2[i], H2[i]);
        loop assigns j, P0[0 .. CBX_LANES - 1], Q0[0 .. CBX_LANES - 1], P1[0 .. CBX_LANES - 1],
                     Q1[0 .. CBX_LANES - 1], P2[0 .. CBX_LANES - 1], Q2[0 .. CBX_LANES - 1];
        loop variant CBX_LANES - j;
    */
    for (j = 0; j < CBX_LANES; j++) {
        cbx_ends r0 = cbx_fast_axis(a00, a01, a02, a03, L0[j], H0[j], L1[j], H1[j], L2[j], H2[j]);
        cbx_ends r1 = cbx_fast_axis(a10, a11, a12, a13, L0[j], H0[j], L1[j], H1[j], L2[j], H2[j]);
        cbx_ends r2 = cbx_fast_axis(a20, a21, a22, a23, L0[j], H0[j], L1[j], H1[j], L2[j], H2[j]);
        P0[j] = r0.lo; Q0[j] = r0.hi;
        P1[j] = r1.lo; Q1[j] = r1.hi;
        P2[j] = r2.lo; Q2[j] = r2.hi;
    }
    /*@ loop invariant rng: 0 <= j <= CBX_LANES;
        loop invariant done: \forall integer i; k <= i < k + j ==>
          box_done_m(CBX_AV(a, Pre), CBX_BV(in + i, Pre), out[i])
          && box_sev_v(CBX_AV(a, Pre), CBX_BV(in + i, Pre), 0)
          && box_sev_le(CBX_AV(a, Pre), CBX_BV(in + i, Pre), w);
        loop invariant frame: \forall integer i; 0 <= i < n && (i < k || k + j <= i) ==>
          out[i] == \at(out[i], Pre);
        loop assigns j, out[k .. k + CBX_LANES - 1];
        loop variant CBX_LANES - j;
    */
    for (j = 0; j < CBX_LANES; j++) {
        cbx_box o;
        o.lo[0] = P0[j]; o.hi[0] = Q0[j];
        o.lo[1] = P1[j]; o.hi[1] = Q1[j];
        o.lo[2] = P2[j]; o.hi[2] = Q2[j];
        /*@ assert lane: box_fast(in + (k + j)); */
        cbx_fast_row(a00, a01, a02, a03, in[k + j].lo[0], in[k + j].hi[0], in[k + j].lo[1],
                     in[k + j].hi[1], in[k + j].lo[2], in[k + j].hi[2]);
        cbx_fast_row(a10, a11, a12, a13, in[k + j].lo[0], in[k + j].hi[0], in[k + j].lo[1],
                     in[k + j].hi[1], in[k + j].lo[2], in[k + j].hi[2]);
        cbx_fast_row(a20, a21, a22, a23, in[k + j].lo[0], in[k + j].hi[0], in[k + j].lo[1],
                     in[k + j].hi[1], in[k + j].lo[2], in[k + j].hi[2]);
        cbx_fast_row(a00, a01, a02, a03, L0[j], H0[j], L1[j], H1[j], L2[j], H2[j]);
        cbx_fast_row(a10, a11, a12, a13, L0[j], H0[j], L1[j], H1[j], L2[j], H2[j]);
        cbx_fast_row(a20, a21, a22, a23, L0[j], H0[j], L1[j], H1[j], L2[j], H2[j]);
        lane_done(a00, a01, a02, a03, a10, a11, a12, a13, a20, a21, a22, a23,
                  in[k + j].lo[0], in[k + j].hi[0], in[k + j].lo[1], in[k + j].hi[1],
                  in[k + j].lo[2], in[k + j].hi[2], L0[j], H0[j], L1[j], H1[j], L2[j], H2[j], o, w);
        put_box(out, k + j, n, o);
        /*@ assert this: \forall integer i; i == k + j ==>
              box_done_m(CBX_AV(a, Pre), CBX_BV(in + i, Pre), out[i])
              && box_sev_v(CBX_AV(a, Pre), CBX_BV(in + i, Pre), 0)
              && box_sev_le(CBX_AV(a, Pre), CBX_BV(in + i, Pre), w); */
    }
}

/* Box k of the batch, and what it leaves alone: every other out[j]. */
/*@ requires valid: \valid_read(a) && \valid_read(in + (0 .. n - 1)) && \valid(out + (0 .. n - 1));
    requires sep: \separated(out + (0 .. n - 1), a) && \separated(out + (0 .. n - 1), in + (0 .. n - 1));
    requires k: k < n;
    assigns out[k];
    ensures done: box_done_m(CBX_AV(a, Pre), CBX_BV(in + k, Pre), out[k]);
    ensures sev: box_sev_v(CBX_AV(a, Pre), CBX_BV(in + k, Pre), sev(\result));
    ensures st: \result == CBX_OK || \result == CBX_EMPTY || \result == CBX_ERANGE || \result == CBX_EINVAL;
    ensures frame: \forall integer j; 0 <= j < n && j != k ==> out[j] == \at(out[j], Pre);
*/
static cbx_status step(const cbx_affine *a CBX_CLS_PARAM, const cbx_box *in, cbx_box *out,
                       size_t k, size_t n)
{
    box_st r;
    if (CBX_IS_GENERAL)
        r = one_box(a, in + k);
    else
        r = CBX_ONE_BOX(a, in + k);
    put_box(out, k, n, r.o);
    return r.s;
}

/* The loop over the boxes under one map, checked by the caller. */
/*@ requires valid: \valid_read(a) && \valid_read(in + (0 .. n - 1)) && \valid(out + (0 .. n - 1));
    requires sep: \separated(out + (0 .. n - 1), a) && \separated(out + (0 .. n - 1), in + (0 .. n - 1));
    requires fast: fast != 0 ==> map_fast(a);
    assigns out[0 .. n - 1];
    CBX_BATCH_POST(a)
*/
static cbx_status batch(const cbx_affine *a CBX_CLS_PARAM, int fast, const cbx_box *in,
                        cbx_box *out, size_t n)
{
    cbx_status worst = CBX_OK;
    size_t k = 0;
    int skip = 0;
    /*@ loop invariant rng: 0 <= k <= n && 0 <= skip <= CBX_LANES;
        loop invariant done: \forall integer j; 0 <= j < k ==>
          box_done_m(CBX_AV(a, Pre), CBX_BV(in + j, Pre), out[j]);
        loop invariant sevmax: \forall integer j; 0 <= j < k ==>
          box_sev_le(CBX_AV(a, Pre), CBX_BV(in + j, Pre), sev(worst));
        loop invariant met: (k == 0 && worst == CBX_OK)
          || (\exists integer j; 0 <= j < k && box_sev_v(CBX_AV(a, Pre), CBX_BV(in + j, Pre), sev(worst)));
        loop invariant stv: worst == CBX_OK || worst == CBX_EMPTY || worst == CBX_ERANGE || worst == CBX_EINVAL;
        loop assigns k, worst, skip, out[0 .. n - 1];
        loop variant n - k;
    */
    while (k < n) {
        int blk = 0;
        if (fast && skip == 0 && n - k >= CBX_LANES) {
            blk = block_fast(in + k);
            if (!blk)
                skip = CBX_LANES;   /* a box outside the fast range: one at a time for a while */
        }
        if (blk) {
            fast_block(a, in, out, k, n, severity(worst));
            /*@ assert kept: \forall integer j; 0 <= j < k ==>
                  box_done_m(CBX_AV(a, Pre), CBX_BV(in + j, Pre), out[j]); */
            /*@ assert blk: CBX_LANE_DONE(0, sev(worst)) && CBX_LANE_DONE(1, sev(worst))
                  && CBX_LANE_DONE(2, sev(worst)) && CBX_LANE_DONE(3, sev(worst))
                  && CBX_LANE_DONE(4, sev(worst)) && CBX_LANE_DONE(5, sev(worst))
                  && CBX_LANE_DONE(6, sev(worst)) && CBX_LANE_DONE(7, sev(worst)); */
            /*@ assert one: \forall integer j; j == k ==> box_sev_v(CBX_AV(a, Pre), CBX_BV(in + j, Pre), 0); */
            /*@ assert donenext: \forall integer j; 0 <= j < k + CBX_LANES ==>
                  box_done_m(CBX_AV(a, Pre), CBX_BV(in + j, Pre), out[j]); */
            /*@ assert sevnext: \forall integer j; 0 <= j < k + CBX_LANES ==>
                  box_sev_le(CBX_AV(a, Pre), CBX_BV(in + j, Pre), sev(worst)); */
            k += CBX_LANES;
        } else {
            cbx_status s = step(a CBX_CLS_ARG, in, out, k, n);
            /*@ assert this: \forall integer j; j == k ==>
                  box_done_m(CBX_AV(a, Pre), CBX_BV(in + j, Pre), out[j]); */
            /*@ assert sevk: \forall integer j; j == k ==>
                  box_sev_v(CBX_AV(a, Pre), CBX_BV(in + j, Pre), sev(s)); */
            if (severity(s) > severity(worst))
                worst = s;
            if (skip > 0)
                skip--;
            k++;
        }
    }
    /*@ assert kn: k == n; */
    return worst;
}

cbx_status cbx_transform_boxes(const cbx_affine *a, const cbx_box *in, cbx_box *out, size_t n)
{
#if CBX_INST == 64
    cbx_class cls = cbx_classify(a);   /* once per call */
#endif
    int fast = CBX_IS_GENERAL && cbx_map_fast(a);
    return batch(a CBX_CLS_ARG, fast, in, out, n);
}

/* Nothing of *p but its map is used (the class is found again, once per
 * call): a prepared map changed by hand still gives sound boxes. */
cbx_status cbx_transform_boxes_prep(const cbx_prepared *p, const cbx_box *in, cbx_box *out, size_t n)
{
    return cbx_transform_boxes(&p->a, in, out, n);
}
