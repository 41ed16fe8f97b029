/*
 * Motion with rotation (issue 21): the box of a box, or of a ball, swept by
 * T(s) R(s) S(s) for every real s of a shutter interval [s0, s1] in [0, 1],
 * where T and S are interpolated linearly between two keyframes and R by
 * slerp (or nlerp) of the keyframes' normalised quaternions along the
 * shorter arc.  Binary64.
 *
 * How (no sin, cos or acos anywhere): the shutter [0, 1] is cut into 2^d
 * cells [k 2^-d, (k+1) 2^-d].  Slerp runs along the great arc at constant
 * speed, so its value at a dyadic time is the normalised sum of the values
 * at the two ends of the enclosing cell: (p + r) / |p + r|.  Each cell's
 * ends are enclosed by interval boxes in R^4 (repeated bisection from the
 * keyframes; nlerp: the normalised blend).  On a cell, the arc from p to r
 * lies in the triangle p, r, (p + r) / (1 + p.r) (the chord and the two
 * tangents), so in the box of those three points; the rotation matrix of
 * every unit quaternion of that box lies in the interval extension of the
 * unit-quaternion formula of R(q).  T and S are linear in s, so their
 * values on a cell lie between their values at its ends.  A cell's maps
 * T R S are then enclosed by one interval matrix (entry (i, j) the
 * interval product R_ij S_j, column 3 T_i), and the box by
 * cbx_transform_box_imat (proven); the result is the hull over the cells.
 *
 * Proven (job T64, proofs/trs.c): the interval arithmetic
 * (src/f64/cbx_iv.h: sums, products, squares, square roots, quotients and
 * the linear paths of T and S, each containing the exact result for every
 * real point of its operands, each end within a stated bound of the exact
 * end), the rotation matrices of a box of unit quaternions
 * (src/f64/cbx_quat.h: every entry of R(q) for every unit q of the box),
 * the quaternion path's steps (src/f64/cbx_quat.h: normalisation, sums,
 * negation, hulls, nlerp's blend, and the arc box holding every unit
 * l p + m r, l, m >= 0)
 * and each cell's interval matrix from them (src/f64/cbx_cell.h: every
 * entry R_ij S_j(s) and T_i(s) for every s of the cell).  Tested only
 * (tests/test_trs.c, against MPFR): what remains in this file, the
 * bisection walk, the choice of the shorter arc and the cells' loop
 * (proofs/README.md, "Rotation motion").
 */
#include <stdint.h>

#include "certbox.h"
#include "cbx_round.h"
#include "cbx_quot.h"
#include "cbx_domain.h"
#include "cbx_iv.h"
#include "cbx_quat.h"
#include "cbx_cell.h"

#define TRS_MAX_DEPTH 16U

/* acc = b (first != 0), else acc grown to hold b. */
static void box_grow(cbx_box *acc, const cbx_box *b, int first)
{
    if (first != 0) {
        *acc = *b;
    } else {
        int i;
        for (i = 0; i < 3; i++) {
            acc->lo[i] = cbx_min2(acc->lo[i], b->lo[i]);
            acc->hi[i] = cbx_max2(acc->hi[i], b->hi[i]);
        }
    }
}

/* The more severe of two statuses (cbx_severity's order). */
static cbx_status st_worse(cbx_status a, cbx_status b)
{
    return (cbx_severity(b) > cbx_severity(a)) ? b : a;
}

/* ---- keyframes ----------------------------------------------------------- */

#define TRS_TMAX 0x1p500 /* translations */
#define TRS_SMAX 0x1p250 /* scales */
#define TRS_QMAX 0x1p250 /* stored quaternion components */
#define TRS_QMIN 0x1p-120 /* the largest component of a stored quaternion */

static int key_nan(const cbx_trs *k)
{
    int n = 0;
    int i;
    for (i = 0; i < 3; i++) {
        n += cbx_is_nan(k->t[i]) + cbx_is_nan(k->s[i]);
    }
    for (i = 0; i < 4; i++) {
        n += cbx_is_nan(k->q[i]);
    }
    return n != 0;
}

/* 1 when every component is in range and the quaternion is not tiny. */
static int key_in_range(const cbx_trs *k)
{
    int n = 0;
    double qm = 0.0;
    int i;
    for (i = 0; i < 3; i++) {
        n += (k->t[i] >= -TRS_TMAX) + (k->t[i] <= TRS_TMAX);
        n += (k->s[i] >= -TRS_SMAX) + (k->s[i] <= TRS_SMAX);
    }
    for (i = 0; i < 4; i++) {
        n += (k->q[i] >= -TRS_QMAX) + (k->q[i] <= TRS_QMAX);
        qm = cbx_max2(qm, cbx_abs(k->q[i]));
    }
    return (n == 20) && (qm >= TRS_QMIN);
}

static int key_zero_q(const cbx_trs *k)
{
    int z = (k->q[0] == 0.0) + (k->q[1] == 0.0) + (k->q[2] == 0.0) + (k->q[3] == 0.0);
    return z == 4;
}

/* ---- the path of the rotation, cell by cell ------------------------------ */

/* A cell index: cells of 2^-levels of the shutter, levels <= 28 (a shutter
 * shorter than 2^(depth-28) of the keyframe interval gets fewer cells than
 * 2^depth: sound, only less tight; the cap keeps the walk's stacks at
 * about 4 KB). */
typedef uint64_t trs_ix;
#define TRS_MAX_LEVELS 28U

/* A walk along one arc, cell end by cell end: the current end (index k,
 * enclosure cur) and a stack of the ends to its right that bound the
 * dyadic intervals around it (indices growing from the top, st[n - 1]):
 * each midpoint is formed once, from its interval's two ends. */
typedef struct trs_walk {
    trs_q cur;
    trs_ix k;
    unsigned n;
    trs_ix sk[TRS_MAX_LEVELS + 1U];
    trs_q st[TRS_MAX_LEVELS + 1U];
} trs_walk;

/* A motion's cells: the two unit quaternions (u1 on the shorter arc from
 * u0; both != 0 when the sign of the dot product is not decided, and then
 * u1n = -u1 gives the other arc), the cells of 2^-levels meeting [s0, s1]
 * (first .. last), the next one, and the walk along each arc. */
typedef struct trs_path {
    trs_q u0;
    trs_q u1;
    trs_q u1n;
    int both;
    int nlerp;
    unsigned levels;
    double s0;
    double s1;
    trs_ix first;
    trs_ix last;
    trs_ix next;
    trs_walk w[2];
} trs_path;

/* Slerp by bisection: from the end at lo (a) to the one at target, within
 * [lo, hi] (b at hi, already on the stack): each midpoint is the
 * normalised sum of its interval's ends; the right ends met are pushed. */
static void walk_descend(trs_walk *w, trs_ix lo, const trs_q *a, trs_ix hi, const trs_q *b, trs_ix target)
{
    trs_q ql = *a;
    trs_q qh = *b;
    trs_ix l = lo;
    trs_ix h = hi;
    while (target != l) {
        trs_ix mid = l + ((h - l) / 2U);
        trs_q sum = q_add(&ql, &qh);
        trs_q m = q_normalise(&sum);
        if (target < mid) {
            w->sk[w->n] = mid;
            w->st[w->n] = m;
            w->n++;
            h = mid;
            qh = m;
        } else {
            l = mid;
            ql = m;
        }
    }
    w->cur = ql;
    w->k = target;
}

/* The enclosure of the rotation's quaternion at time k 2^-levels on the
 * arc from u0 to u1 (nlerp: the normalised blend). */
static void walk_init(const trs_path *p, trs_walk *w, const trs_q *u1, trs_ix k)
{
    trs_ix top = (trs_ix)1U << p->levels;
    if (p->nlerp != 0) {
        double s = (double)k / (double)top; /* exact */
        trs_q v = q_blend(&p->u0, u1, s);
        w->cur = q_normalise(&v);
        w->k = k;
        w->n = 0U;
    } else {
        w->n = 1U;
        w->sk[0] = top;
        w->st[0] = *u1;
        walk_descend(w, 0U, &p->u0, top, u1, k);
    }
}

/* The next cell end (index k + 1). */
static void walk_next(const trs_path *p, trs_walk *w, const trs_q *u1)
{
    trs_ix j = w->k + 1U;
    if (p->nlerp != 0) {
        walk_init(p, w, u1, j);
    } else if (w->sk[w->n - 1U] == j) {
        w->n--;
        w->cur = w->st[w->n];
        w->k = j;
    } else {
        trs_q a = w->cur;
        walk_descend(w, w->k, &a, w->sk[w->n - 1U], &w->st[w->n - 1U], j);
    }
}

/* Checks the keyframes and the shutter and sets up the cells: 2^depth
 * cells over the shutter's length (2^depth to 2^(depth+1) + 1 of them, of
 * 2^-levels each, levels = depth + about log2(1 / (s1 - s0)), at most 28).
 * CBX_OK, or the status to return with the whole space. */
static cbx_status path_setup(const cbx_trs *k0, const cbx_trs *k1, cbx_interp mode,
                             double s0, double s1, unsigned depth, trs_path *p)
{
    cbx_iv dot;
    double w;
    double f;
    double l;
    trs_ix n;
    unsigned e;
    int go = 1;
    /* counts, not && chains: one test each */
    int nan = key_nan(k0) + key_nan(k1) + cbx_is_nan(s0) + cbx_is_nan(s1);
    int good = (s0 >= 0.0) + (s0 <= s1) + (s1 <= 1.0) + (depth <= TRS_MAX_DEPTH)
               + (mode == CBX_SLERP) + (mode == CBX_NLERP) + (key_zero_q(k0) == 0) + (key_zero_q(k1) == 0);
    if ((nan != 0) || (good != 7)) {
        return CBX_EINVAL;
    }
    if ((key_in_range(k0) + key_in_range(k1)) != 2) {
        return CBX_ERANGE;
    }
    p->u0 = q_unit_of(k0->q);
    p->u1 = q_unit_of(k1->q);
    p->u1n = q_neg(&p->u1);
    dot = q_dot(&p->u0, &p->u1);
    p->both = (dot.lo < 0.0) && (dot.hi >= 0.0); /* the sign is not decided: both arcs */
    if (dot.hi < 0.0) {
        p->u1 = p->u1n; /* the shorter arc: q1 negated */
    }
    p->nlerp = mode == CBX_NLERP;
    p->s0 = s0;
    p->s1 = s1;
    /* levels: the shutter's length w times 2^(levels - depth) in (1/2, 1] */
    p->levels = depth;
    w = s1 - s0;
    for (e = depth; e < TRS_MAX_LEVELS; e++) {
        go = go & ((w * 2.0) <= 1.0); /* no branch: the shutter still fits twice */
        w = w + (w * (double)go);
        p->levels += (unsigned)go;
    }
    n = (trs_ix)1U << p->levels;
    f = s0 * (double)n; /* exact: a power of two */
    l = s1 * (double)n;
    p->first = (trs_ix)f;
    p->last = (trs_ix)l;
    if ((double)p->last < l) {
        p->last++;
    }
    if (p->first >= n) {
        p->first = n - 1U;
    }
    p->last = (p->last > 0U) ? (p->last - 1U) : 0U;
    if (p->last < p->first) {
        p->last = p->first;
    }
    p->next = p->first;
    walk_init(p, &p->w[0], &p->u1, p->first);
    if (p->both != 0) {
        walk_init(p, &p->w[1], &p->u1n, p->first);
    }
    return CBX_OK;
}

/* The next cell's interval matrix: every map of the motion at every s of
 * the cell within [s0, s1]. */
static void path_cell(trs_path *p, const cbx_trs *k0, const cbx_trs *k1, cbx_imat *m)
{
    trs_ix k = p->next;
    trs_ix top = (trs_ix)1U << p->levels;
    double n = (double)top;
    double a = cbx_max2((double)k / n, p->s0);
    double b = cbx_min2((double)(trs_ix)(k + 1U) / n, p->s1);
    trs_q start = p->w[0].cur;
    trs_q arc;
    trs_rot r;
    walk_next(p, &p->w[0], &p->u1);
    arc = q_arc_box(&start, &p->w[0].cur);
    if (p->both != 0) {
        trs_q startn = p->w[1].cur;
        trs_q arcn;
        walk_next(p, &p->w[1], &p->u1n);
        arcn = q_arc_box(&startn, &p->w[1].cur);
        arc = q_hull(&arc, &arcn);
    }
    p->next = k + 1U;
    r = q_rotation(&arc);
    cell_imat(k0, k1, &r, a, b, m);
}

/* ---- public functions ---------------------------------------------------- */

cbx_status cbx_trs_pieces(const cbx_trs *k0, const cbx_trs *k1, cbx_interp mode, double s0, double s1,
                          unsigned depth, cbx_imat *pieces, size_t cap, size_t *count)
{
    trs_path p;
    cbx_status st = path_setup(k0, k1, mode, s0, s1, depth, &p);
    *count = 0;
    if (st != CBX_OK) {
        return st;
    }
    if ((p.last - p.first) >= (trs_ix)cap) {
        return CBX_EINVAL;
    }
    while (p.next <= p.last) {
        path_cell(&p, k0, k1, &pieces[*count]);
        (*count)++;
    }
    return st;
}

cbx_status cbx_transform_box_pieces(const cbx_imat *pieces, size_t n, const cbx_box *in, cbx_box *out)
{
    cbx_box acc;
    cbx_status st = CBX_OK;
    size_t k;
    set_empty(&acc); /* every path writes it before use; the analyzer cannot tell */
    if (n == 0U) {
        set_whole(out);
        return CBX_EINVAL;
    }
    for (k = 0; k < n; k++) {
        cbx_box b;
        cbx_status cs = cbx_transform_box_imat(&pieces[k], in, &b);
        st = st_worse(st, cs);
        box_grow(&acc, &b, k == 0U);
    }
    if (st == CBX_EINVAL) {
        set_whole(out);
    } else if (st == CBX_EMPTY) {
        set_empty(out);
    } else {
        *out = acc;
    }
    return st;
}

cbx_status cbx_motion_trs_box(const cbx_trs *k0, const cbx_trs *k1, cbx_interp mode, double s0, double s1,
                              unsigned depth, const cbx_box *in, cbx_box *out)
{
    trs_path p;
    cbx_box src = *in; /* out may be in */
    cbx_box acc;
    cbx_status st;
    set_empty(&acc); /* every path writes it before use; the analyzer cannot tell */
    if (box_any_nan(&src) != 0) {
        set_whole(out);
        return CBX_EINVAL;
    }
    st = path_setup(k0, k1, mode, s0, s1, depth, &p);
    if (st != CBX_OK) {
        set_whole(out);
        return st;
    }
    if (box_any_empty(&src) != 0) {
        set_empty(out);
        return CBX_EMPTY;
    }
    while (p.next <= p.last) {
        int firstcell = p.next == p.first;
        cbx_imat m;
        cbx_box bk;
        cbx_status cs;
        path_cell(&p, k0, k1, &m);
        cs = cbx_transform_box_imat(&m, &src, &bk);
        st = st_worse(st, cs);
        box_grow(&acc, &bk, firstcell != 0);
    }
    *out = acc;
    return st;
}

/* ---- balls --------------------------------------------------------------- */

#define TRS_CMAX 0x1p500 /* ball centres and radii */
#define TRS_BALLMAX 0x1p1000 /* a centre's end finite and far from overflow */

/* The box of the ball |x - c| <= |r| under every map of *m: the centre's
 * box (cbx_transform_box_imat) grown by |r| times the largest row norm,
 * rounded up; an axis the centre's box leaves infinite stays so. */
static cbx_status ball_piece(const cbx_imat *m, const double c[3], double r, cbx_box *out)
{
    cbx_box cb;
    cbx_status st;
    cbx_iv rad = iv_pt(cbx_abs(r));
    int i;
    int j;
    for (j = 0; j < 3; j++) {
        cb.lo[j] = c[j];
        cb.hi[j] = c[j];
    }
    st = cbx_transform_box_imat(m, &cb, out);
    for (i = 0; i < 3; i++) {
        cbx_iv n2 = iv_pt(0.0);
        cbx_iv g;
        for (j = 0; j < 3; j++) {
            n2 = iv_add(n2, iv_sqr(iv_pt(cbx_max2(cbx_abs(m->lo[i][j]), cbx_abs(m->hi[i][j])))));
        }
        g = iv_mul(rad, iv_sqrt(n2));
        int fin = (out->lo[i] >= -TRS_BALLMAX) + (out->hi[i] <= TRS_BALLMAX);
        if (fin == 2) {
            out->lo[i] = cbx_add_dn(out->lo[i], -g.hi);
            out->hi[i] = cbx_add_up(out->hi[i], g.hi);
        }
    }
    return st;
}

/* 1 when the ball's centre and radius are in range (NaN: 0). */
static int ball_in_range(const double c[3], double r)
{
    int n = (r >= -TRS_CMAX) + (r <= TRS_CMAX);
    int j;
    for (j = 0; j < 3; j++) {
        n += (c[j] >= -TRS_CMAX) + (c[j] <= TRS_CMAX);
    }
    return n == 8;
}

static int ball_nan(const double c[3], double r)
{
    return (cbx_is_nan(c[0]) + cbx_is_nan(c[1]) + cbx_is_nan(c[2]) + cbx_is_nan(r)) != 0;
}

cbx_status cbx_ball_pieces(const cbx_imat *pieces, size_t n, const double c[3], double r, cbx_box *out)
{
    cbx_box acc;
    cbx_status st = CBX_OK;
    size_t k;
    set_empty(&acc); /* every path writes it before use; the analyzer cannot tell */
    if (((n == 0U) + ball_nan(c, r)) != 0) {
        set_whole(out);
        return CBX_EINVAL;
    }
    if (ball_in_range(c, r) == 0) {
        set_whole(out);
        return CBX_ERANGE;
    }
    for (k = 0; k < n; k++) {
        cbx_box b;
        cbx_status cs = ball_piece(&pieces[k], c, r, &b);
        st = st_worse(st, cs);
        box_grow(&acc, &b, k == 0U);
    }
    if (st == CBX_EINVAL) {
        set_whole(out);
    } else {
        *out = acc;
    }
    return st;
}

cbx_status cbx_motion_trs_ball(const cbx_trs *k0, const cbx_trs *k1, cbx_interp mode, double s0, double s1,
                               unsigned depth, const double c[3], double r, cbx_box *out)
{
    trs_path p;
    cbx_box acc;
    cbx_status st;
    set_empty(&acc); /* every path writes it before use; the analyzer cannot tell */
    if (ball_nan(c, r) != 0) {
        set_whole(out);
        return CBX_EINVAL;
    }
    st = path_setup(k0, k1, mode, s0, s1, depth, &p);
    if ((st == CBX_OK) && (ball_in_range(c, r) == 0)) {
        st = CBX_ERANGE;
    }
    if (st != CBX_OK) {
        set_whole(out);
        return st;
    }
    while (p.next <= p.last) {
        int firstcell = p.next == p.first;
        cbx_imat m;
        cbx_box bk;
        cbx_status cs;
        path_cell(&p, k0, k1, &m);
        cs = ball_piece(&m, c, r, &bk);
        st = st_worse(st, cs);
        box_grow(&acc, &bk, firstcell != 0);
    }
    *out = acc;
    return st;
}

cbx_status cbx_motion_trs_path(const cbx_trs *keys, size_t n, cbx_interp mode, double s0, double s1,
                               unsigned depth, const cbx_box *in, cbx_box *out)
{
    cbx_box src = *in; /* out may be in */
    cbx_box acc;
    cbx_status st = CBX_OK;
    int any = 0;
    size_t i;
    size_t nseg;
    int bad;
    double m;
    set_empty(&acc); /* every path writes it before use; the analyzer cannot tell */
    if (n < 2U) {
        if (n == 1U) {
            return cbx_motion_trs_box(keys, keys, mode, s0, s1, depth, in, out);
        }
        set_whole(out);
        return CBX_EINVAL;
    }
    bad = (s0 < 0.0) + (s0 > s1) + (s1 > 1.0) + (n > (1UL << 30));
    bad += cbx_is_nan(s0) + cbx_is_nan(s1);
    if (bad != 0) {
        set_whole(out);
        return CBX_EINVAL;
    }
    nseg = n - 1U;
    m = (double)nseg; /* segment i: global times [i/m, (i+1)/m] */
    for (i = 0; i < nseg; i++) {
        /* the local times s m - i of [s0, s1], enclosed */
        cbx_iv l0 = iv_add(iv_mul(iv_pt(s0), iv_pt(m)), iv_pt(-(double)i));
        cbx_iv l1 = iv_add(iv_mul(iv_pt(s1), iv_pt(m)), iv_pt(-(double)i));
        double a = cbx_max2(l0.lo, 0.0);
        double b = cbx_min2(l1.hi, 1.0);
        cbx_box bk;
        cbx_status cs;
        if (!(a <= b)) {
            continue; /* the shutter does not meet this segment */
        }
        cs = cbx_motion_trs_box(&keys[i], &keys[i + 1U], mode, a, b, depth, &src, &bk);
        st = st_worse(st, cs);
        box_grow(&acc, &bk, any == 0);
        any = 1;
    }
    if ((st == CBX_EINVAL) || (any == 0)) {
        set_whole(out);
        return CBX_EINVAL;
    }
    if (st == CBX_EMPTY) {
        set_empty(out);
        return CBX_EMPTY;
    }
    *out = acc;
    return st;
}
