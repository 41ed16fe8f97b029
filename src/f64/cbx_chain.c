/*
 * Chains of maps: the box of a box under p[0] p[1] ... p[n-1] (p[n-1]
 * applied first), one map at a time with cbx_transform_box_as (the map's
 * class from cbx_prepare).
 *
 * Soundness is an induction over the chain: before step k the current box
 * holds the image of every real point of the input under p[k+1 .. n-1]
 * (chain_x); cbx_transform_box_as's promise on one axis (axis_sound_s)
 * holds the image of every real point of its input box (lemma
 * axis_sound_pt), and the image of the chain's image under p[k] is the
 * chain's image one step longer (the definition of chain_x).  A NaN, an
 * empty box or an infinite entry on the way gives infinite ends, which are
 * no constraint, so the induction goes through every status.
 */
#include "certbox.h"
#include "cbx_round.h"
#include "cbx_domain.h"

/* One step: *b becomes the box of *b under *a (cbx_transform_box_as with
 * the class cls), stated as the step of the induction: the image of every
 * real point of the old box lies in the new one, axis by axis (lemma
 * axis_sound_pt on cbx_transform_box_as's promise). */
/*@ requires valid: \valid_read(a) && \valid(b) && \separated(a, b);
    assigns *b;
    ensures st: \result == CBX_OK || \result == CBX_EMPTY || \result == CBX_ERANGE
                || \result == CBX_EINVAL;
    ensures ax0: \forall real q0, q1, q2; pt_in(q0, q1, q2, CBX_BV(b, Pre)) ==>
      ext_in(lin3(CBX_ROWV(a, 0, Pre), q0, q1, q2), b->lo[0], b->hi[0]);
    ensures ax1: \forall real q0, q1, q2; pt_in(q0, q1, q2, CBX_BV(b, Pre)) ==>
      ext_in(lin3(CBX_ROWV(a, 1, Pre), q0, q1, q2), b->lo[1], b->hi[1]);
    ensures ax2: \forall real q0, q1, q2; pt_in(q0, q1, q2, CBX_BV(b, Pre)) ==>
      ext_in(lin3(CBX_ROWV(a, 2, Pre), q0, q1, q2), b->lo[2], b->hi[2]);
*/
static cbx_status chain_step(const cbx_affine *a, cbx_class cls, cbx_box *b)
{
    return cbx_transform_box_as(a, cls, b, b);
}

/* proof: -wp-split */
cbx_status cbx_transform_box_chain(const cbx_prepared *p, size_t n, const cbx_box *in, cbx_box *out)
{
    cbx_status st = CBX_OK;
    size_t k = n;
    cbx_box cur;
    const double i0 = in->lo[0];
    const double i1 = in->lo[1];
    const double i2 = in->lo[2];
    const double j0 = in->hi[0];
    const double j1 = in->hi[1];
    const double j2 = in->hi[2];
    double l0;
    double l1;
    double l2;
    double h0;
    double h1;
    double h2;
    if (n == 0U) {
        set_whole(out);
        return CBX_EINVAL;
    }
    cur.lo[0] = i0; cur.lo[1] = i1; cur.lo[2] = i2;
    cur.hi[0] = j0; cur.hi[1] = j1; cur.hi[2] = j2;
    /*@ loop invariant rng: 0 <= k <= n;
        loop invariant st: st == CBX_OK || st == CBX_EMPTY || st == CBX_ERANGE || st == CBX_EINVAL;
        loop invariant contain: \forall real x0, x1, x2;
          pt_in(x0, x1, x2, i0, j0, i1, j1, i2, j2) ==>
          chain_in{Pre}(p, k, n, x0, x1, x2, cur.lo[0], cur.hi[0], cur.lo[1], cur.hi[1],
                        cur.lo[2], cur.hi[2]);
        loop assigns k, cur, st;
        loop variant k;
    */
    while (k > 0U) {
        cbx_status sk;
        /*@ ghost double ol0 = cur.lo[0], ol1 = cur.lo[1], ol2 = cur.lo[2]; */
        /*@ ghost double oh0 = cur.hi[0], oh1 = cur.hi[1], oh2 = cur.hi[2]; */
        k--;
        /*@ assert kdec: k + 1 == \at(k, LoopCurrent); */
        /*@ assert unfold: \let kk = (integer)k; \forall real x0, x1, x2; \forall integer i;
              0 <= i < 3 ==>
              \at(chain_x(p, kk, n, i, x0, x1, x2), Pre)
              == lin3(\at(p[kk].a.m[i][0], Pre), \at(p[kk].a.m[i][1], Pre),
                      \at(p[kk].a.m[i][2], Pre), \at(p[kk].a.m[i][3], Pre),
                      \at(chain_x(p, kk + 1, n, 0, x0, x1, x2), Pre),
                      \at(chain_x(p, kk + 1, n, 1, x0, x1, x2), Pre),
                      \at(chain_x(p, kk + 1, n, 2, x0, x1, x2), Pre)); */
        /*@ assert same: \let kk = (integer)k; \forall integer i, c; 0 <= i < 3 ==> 0 <= c < 4 ==>
              p[kk].a.m[i][c] == \at(p[kk].a.m[i][c], Pre); */
        sk = chain_step(&p[k].a, (cbx_class)p[k].cls, &cur);
        /*@ assert ax: \let kk = (integer)k; \forall real q0, q1, q2;
              pt_in(q0, q1, q2, ol0, oh0, ol1, oh1, ol2, oh2) ==>
              (ext_in(lin3(\at(p[kk].a.m[0][0], Pre), \at(p[kk].a.m[0][1], Pre),
                           \at(p[kk].a.m[0][2], Pre), \at(p[kk].a.m[0][3], Pre), q0, q1, q2),
                      cur.lo[0], cur.hi[0])
               && ext_in(lin3(\at(p[kk].a.m[1][0], Pre), \at(p[kk].a.m[1][1], Pre),
                              \at(p[kk].a.m[1][2], Pre), \at(p[kk].a.m[1][3], Pre), q0, q1, q2),
                         cur.lo[1], cur.hi[1])
               && ext_in(lin3(\at(p[kk].a.m[2][0], Pre), \at(p[kk].a.m[2][1], Pre),
                              \at(p[kk].a.m[2][2], Pre), \at(p[kk].a.m[2][3], Pre), q0, q1, q2),
                         cur.lo[2], cur.hi[2])); */
        if (cbx_severity(sk) > cbx_severity(st)) {
            st = sk;
        }
    }
    l0 = cur.lo[0]; l1 = cur.lo[1]; l2 = cur.lo[2];
    h0 = cur.hi[0]; h1 = cur.hi[1]; h2 = cur.hi[2];
    out->lo[0] = l0; out->lo[1] = l1; out->lo[2] = l2;
    out->hi[0] = h0; out->hi[1] = h1; out->hi[2] = h2;
    return st;
}
