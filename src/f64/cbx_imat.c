/*
 * Interval matrices: an affine map known only up to an interval per entry
 * (cbx_imat), as a chain of rounded transforms or a rotation built from a
 * quaternion produces.  cbx_transform_box_imat bounds the image of a box
 * under every map of the interval matrix; cbx_imat_compose encloses every
 * product of two such maps.  Both run the proven kernel of
 * src/f64/cbx_ikernel.h on every output coordinate whose inputs are in the
 * fast range (ordered finite intervals, linear entries and box ends at
 * most 2^509, translations at most 2^1018), and set the others to the
 * whole line with CBX_ERANGE.  Binary64.
 */
#include "certbox.h"
#include "cbx_round.h"
#include "cbx_domain.h"
#include "cbx_ikernel.h"

/* One coordinate, checked: the kernel in the fast range, else the whole
 * line; ok says which. */
typedef struct cbx_icoord { cbx_fp lo; cbx_fp hi; int ok; } cbx_icoord;

/* 1 when [l, h] is ordered, finite and within [nb, b] (IEEE comparisons:
 * false on NaN).  The bounds come as two literals (nb = -b): a negated
 * parameter made Why3 reject the goals (as in src/algo/cbx_fast.h). */
/*@ requires \is_finite(nb) && \is_finite(b) && nb == -b;
    assigns \nothing;
    ensures rng: 0 <= \result <= 1;
    ensures \result != 0 <==> iv_fast(l, h, b);
*/
static int iv_in(cbx_fp l, cbx_fp h, cbx_fp nb, cbx_fp b)
{
    int n = (l >= nb) + (l <= h) + (h <= b);
    return n == 3;
}

/*@ assigns \nothing;
    ensures val: icoord(\result.lo, \result.hi, ml0, mh0, ml1, mh1, ml2, mh2, tl, th,
                        l0, h0, l1, h1, l2, h2);
    ensures okr: 0 <= \result.ok <= 1;
    ensures ok: \result.ok != 0 <==> irow_fast(ml0, mh0, ml1, mh1, ml2, mh2, tl, th,
                                               l0, h0, l1, h1, l2, h2);
*/
static cbx_icoord icoord_of(cbx_fp ml0, cbx_fp mh0, cbx_fp ml1, cbx_fp mh1, cbx_fp ml2, cbx_fp mh2,
                            cbx_fp tl, cbx_fp th,
                            cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2)
{
    cbx_icoord r;
    int n = iv_in(ml0, mh0, -CBX_K(SB), CBX_K(SB)) + iv_in(ml1, mh1, -CBX_K(SB), CBX_K(SB))
            + iv_in(ml2, mh2, -CBX_K(SB), CBX_K(SB)) + iv_in(tl, th, -CBX_K(RT), CBX_K(RT))
            + iv_in(l0, h0, -CBX_K(SB), CBX_K(SB)) + iv_in(l1, h1, -CBX_K(SB), CBX_K(SB))
            + iv_in(l2, h2, -CBX_K(SB), CBX_K(SB));
    if (n == 7) {
        cbx_ends e = cbx_irow(ml0, mh0, ml1, mh1, ml2, mh2, tl, th, l0, h0, l1, h1, l2, h2);
        /*@ assert in: irow_in(e.lo, e.hi, ml0, mh0, ml1, mh1, ml2, mh2, tl, th,
                               l0, h0, l1, h1, l2, h2); */
        /*@ assert tight: irow_tight(e.lo, e.hi, ml0, mh0, ml1, mh1, ml2, mh2, tl, th,
                                     l0, h0, l1, h1, l2, h2); */
        r.lo = e.lo;
        r.hi = e.hi;
        r.ok = 1;
    } else {
        r.lo = cbx_ninf();
        r.hi = cbx_pinf();
        r.ok = 0;
    }
    return r;
}

/* 1 if some entry of row i of a is NaN or inverted (specs: imat_bad_row). */
/*@ requires \valid_read(a) && 0 <= i < 3;
    assigns \nothing;
    ensures \result != 0 <==> imat_bad_row(a, i);
*/
static int imat_row_bad(const cbx_imat *a, int i)
{
    return cbx_is_nan(a->lo[i][0]) | cbx_is_nan(a->hi[i][0]) | cbx_is_inverted(a->lo[i][0], a->hi[i][0])
           | cbx_is_nan(a->lo[i][1]) | cbx_is_nan(a->hi[i][1]) | cbx_is_inverted(a->lo[i][1], a->hi[i][1])
           | cbx_is_nan(a->lo[i][2]) | cbx_is_nan(a->hi[i][2]) | cbx_is_inverted(a->lo[i][2], a->hi[i][2])
           | cbx_is_nan(a->lo[i][3]) | cbx_is_nan(a->hi[i][3]) | cbx_is_inverted(a->lo[i][3], a->hi[i][3]);
}

/* 1 if some entry of a is NaN or inverted (specs: imat_bad). */
/*@ requires \valid_read(a);
    assigns \nothing;
    ensures \result != 0 <==> imat_bad(a);
*/
static int imat_any_bad(const cbx_imat *a)
{
    return imat_row_bad(a, 0) || imat_row_bad(a, 1) || imat_row_bad(a, 2);
}


/* The three coordinates of a's linear part applied to one column (a box,
 * or column j of the right factor of a composition), plus the
 * translation [tl_i, th_i] of each row (a's, or 0). */
typedef struct cbx_icol { cbx_icoord e0; cbx_icoord e1; cbx_icoord e2; } cbx_icol;

/*@ requires valid: \valid_read(a);
    assigns \nothing;
    ensures ent0: icoord(\result.e0.lo, \result.e0.hi, a->lo[0][0], a->hi[0][0], a->lo[0][1], a->hi[0][1],
                        a->lo[0][2], a->hi[0][2], tl0, th0, l0, h0, l1, h1, l2, h2);
    ensures ent1: icoord(\result.e1.lo, \result.e1.hi, a->lo[1][0], a->hi[1][0], a->lo[1][1], a->hi[1][1],
                        a->lo[1][2], a->hi[1][2], tl1, th1, l0, h0, l1, h1, l2, h2);
    ensures ent2: icoord(\result.e2.lo, \result.e2.hi, a->lo[2][0], a->hi[2][0], a->lo[2][1], a->hi[2][1],
                        a->lo[2][2], a->hi[2][2], tl2, th2, l0, h0, l1, h1, l2, h2);
    ensures okr: 0 <= \result.e0.ok <= 1 && 0 <= \result.e1.ok <= 1 && 0 <= \result.e2.ok <= 1;
    ensures ok0: \result.e0.ok != 0 <==> irow_fast(a->lo[0][0], a->hi[0][0], a->lo[0][1], a->hi[0][1],
                        a->lo[0][2], a->hi[0][2], tl0, th0, l0, h0, l1, h1, l2, h2);
    ensures ok1: \result.e1.ok != 0 <==> irow_fast(a->lo[1][0], a->hi[1][0], a->lo[1][1], a->hi[1][1],
                        a->lo[1][2], a->hi[1][2], tl1, th1, l0, h0, l1, h1, l2, h2);
    ensures ok2: \result.e2.ok != 0 <==> irow_fast(a->lo[2][0], a->hi[2][0], a->lo[2][1], a->hi[2][1],
                        a->lo[2][2], a->hi[2][2], tl2, th2, l0, h0, l1, h1, l2, h2);
*/
static cbx_icol col_apply(const cbx_imat *a, cbx_fp tl0, cbx_fp th0, cbx_fp tl1, cbx_fp th1,
                          cbx_fp tl2, cbx_fp th2,
                          cbx_fp l0, cbx_fp h0, cbx_fp l1, cbx_fp h1, cbx_fp l2, cbx_fp h2)
{
    cbx_icol r;
    r.e0 = icoord_of(a->lo[0][0], a->hi[0][0], a->lo[0][1], a->hi[0][1], a->lo[0][2], a->hi[0][2],
                     tl0, th0, l0, h0, l1, h1, l2, h2);
    r.e1 = icoord_of(a->lo[1][0], a->hi[1][0], a->lo[1][1], a->hi[1][1], a->lo[1][2], a->hi[1][2],
                     tl1, th1, l0, h0, l1, h1, l2, h2);
    r.e2 = icoord_of(a->lo[2][0], a->hi[2][0], a->lo[2][1], a->hi[2][1], a->lo[2][2], a->hi[2][2],
                     tl2, th2, l0, h0, l1, h1, l2, h2);
    return r;
}

/* Column j of b, as the box ends of col_apply. */
#define CBX_BCOL(b, j) \
    (b)->lo[0][j], (b)->hi[0][j], (b)->lo[1][j], (b)->hi[1][j], (b)->lo[2][j], (b)->hi[2][j]

cbx_status cbx_transform_box_imat(const cbx_imat *a, const cbx_box *in, cbx_box *out)
{
    if (imat_any_bad(a) || box_any_nan(in)) {
        set_whole(out);
        return CBX_EINVAL;
    }
    if (box_any_empty(in) != 0) {
        set_empty(out);
        return CBX_EMPTY;
    }
    cbx_icol x = col_apply(a, a->lo[0][3], a->hi[0][3], a->lo[1][3], a->hi[1][3],
                           a->lo[2][3], a->hi[2][3],
                           in->lo[0], in->hi[0], in->lo[1], in->hi[1], in->lo[2], in->hi[2]);
    out->lo[0] = x.e0.lo; out->hi[0] = x.e0.hi;
    out->lo[1] = x.e1.lo; out->hi[1] = x.e1.hi;
    out->lo[2] = x.e2.lo; out->hi[2] = x.e2.hi;
    return ((x.e0.ok + x.e1.ok + x.e2.ok) == 3) ? CBX_OK : CBX_ERANGE;
}

/* Every entry of out [-inf, +inf]. */
/*@ requires \valid(out);
    assigns *out;
    ensures imat_whole(out);
*/
static void whole_imat(cbx_imat *out)
{
    cbx_imat r;
    cbx_fp n = cbx_ninf();
    cbx_fp p = cbx_pinf();
    r.lo[0][0] = n; r.hi[0][0] = p; r.lo[0][1] = n; r.hi[0][1] = p;
    r.lo[0][2] = n; r.hi[0][2] = p; r.lo[0][3] = n; r.hi[0][3] = p;
    r.lo[1][0] = n; r.hi[1][0] = p; r.lo[1][1] = n; r.hi[1][1] = p;
    r.lo[1][2] = n; r.hi[1][2] = p; r.lo[1][3] = n; r.hi[1][3] = p;
    r.lo[2][0] = n; r.hi[2][0] = p; r.lo[2][1] = n; r.hi[2][1] = p;
    r.lo[2][2] = n; r.hi[2][2] = p; r.lo[2][3] = n; r.hi[2][3] = p;
    *out = r;
}

/* Column j of out from c: six assignments (statements, no comma
 * operator; a call site adds the last semicolon). */
#define CBX_PUT_COL(out, j, c) \
    (out)->lo[0][j] = (c).e0.lo; (out)->hi[0][j] = (c).e0.hi; \
    (out)->lo[1][j] = (c).e1.lo; (out)->hi[1][j] = (c).e1.hi; \
    (out)->lo[2][j] = (c).e2.lo; (out)->hi[2][j] = (c).e2.hi

cbx_status cbx_imat_compose(const cbx_imat *a, const cbx_imat *b, cbx_imat *out)
{
    if (imat_any_bad(a) || imat_any_bad(b)) {
        whole_imat(out);
        return CBX_EINVAL;
    }
    cbx_fp z = CBX_C(0.0);
    cbx_icol c0 = col_apply(a, z, z, z, z, z, z, CBX_BCOL(b, 0));
    cbx_icol c1 = col_apply(a, z, z, z, z, z, z, CBX_BCOL(b, 1));
    cbx_icol c2 = col_apply(a, z, z, z, z, z, z, CBX_BCOL(b, 2));
    cbx_icol c3 = col_apply(a, a->lo[0][3], a->hi[0][3], a->lo[1][3], a->hi[1][3],
                            a->lo[2][3], a->hi[2][3], CBX_BCOL(b, 3));
    cbx_imat r; /* built here, stored once: out and a, b have the same type */
    CBX_PUT_COL(&r, 0, c0);
    CBX_PUT_COL(&r, 1, c1);
    CBX_PUT_COL(&r, 2, c2);
    CBX_PUT_COL(&r, 3, c3);
    *out = r;
    int ok = c0.e0.ok + c0.e1.ok + c0.e2.ok + c1.e0.ok + c1.e1.ok + c1.e2.ok
             + c2.e0.ok + c2.e1.ok + c2.e2.ok + c3.e0.ok + c3.e1.ok + c3.e2.ok;
    return (ok == 12) ? CBX_OK : CBX_ERANGE;
}
