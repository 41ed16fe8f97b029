/*
 * Tight mode: the smallest double box that contains the exact image.
 *
 * The proven interval transform runs first: on the fast path (map and box
 * in cbx_fast.h's range, one check each) its branch-free kernel, else
 * cbx_transform_box, whose status, special cases and infinite ends are
 * kept.  Each finite end is then tightened at its vertex v (the point of
 * the box where the end is reached; on the fast path chosen by a select):
 * the exact end is E = t + m0 v0 + m1 v1 + m2 v2, a sum of seven doubles
 * once each product is split exactly (two_prod).  A candidate c replaces
 * the end only when a certificate shows c <= E (c >= E for an upper end).
 * Three tries, cheapest first: a compensated dot product with a proven
 * error bound (dot_sum: nearly every end), two distillation passes and a
 * sign decision (tighten_fast), and the full search (the last term after
 * three distillation passes, then its neighbours, each certified by
 * distilling the eight terms, E's seven and -c, with two_sum, which keeps
 * their exact sum, until the largest term decides the sign).  So
 * containment rests on the proven kernel and on the exactness of two_sum /
 * two_prod (src/core/cbx_eft.h); optimality (c = RD(E)) is what the GMP
 * tests check on every case.  On the fast path nothing branches on data but
 * the rare end dot_sum leaves undecided (a sign or a certificate is a
 * coin toss: a branch on it cost about one mispredicted jump per end;
 * docs/measurements.md).  When no certificate decides (some nonzero
 * product below 2^-968, magnitudes above 2^1015) the kernel's end stays:
 * sound, within its proven bound.
 */
#include "certbox.h"
#include "cbx_round.h"
#include "cbx_domain.h"
#include "cbx_vertex.h"
#include "cbx_eft.h"
#include "cbx_kernel.h"
#include "cbx_fast.h"

#ifdef __FRAMAC__
#include "cbx_tight.h"
#endif

/* two_sum where its range allows, else the pair unchanged (same sum). */
/*@ requires fin: \is_finite(a) && \is_finite(b);
    assigns \nothing;
    ensures fin: \is_finite(\result.hi) && \is_finite(\result.lo);
    ensures exact: \result.hi + \result.lo == a + b;
*/
static cbx_dd eft_sum(double a, double b)
{
    cbx_dd r;
    if ((a >= -0x1p1019) && (a <= 0x1p1019) && (b >= -0x1p1019) && (b <= 0x1p1019)) {
        return cbx_two_sum(a, b);
    }
    r.hi = a;
    r.lo = b;
    return r;
}

/* One distillation pass (Ogita, Rump, Oishi's VecSum): the running sum
 * moves to v7, the rounding errors stay behind; the exact sum is kept. */
/*@ requires fin: vfin(z);
    assigns \nothing;
    ensures fin: vfin(\result);
    ensures sum: vsum(\result) == vsum(z);
*/
static cbx_vec8 pass8(cbx_vec8 z)
{
    cbx_vec8 r;
    cbx_dd d1 = eft_sum(z.v1, z.v0);
    cbx_dd d2 = eft_sum(z.v2, d1.hi);
    cbx_dd d3 = eft_sum(z.v3, d2.hi);
    cbx_dd d4 = eft_sum(z.v4, d3.hi);
    cbx_dd d5 = eft_sum(z.v5, d4.hi);
    cbx_dd d6 = eft_sum(z.v6, d5.hi);
    cbx_dd d7 = eft_sum(z.v7, d6.hi);
    r.v0 = d1.lo; r.v1 = d2.lo; r.v2 = d3.lo; r.v3 = d4.lo;
    r.v4 = d5.lo; r.v5 = d6.lo; r.v6 = d7.lo; r.v7 = d7.hi;
    return r;
}

/* Sign of the exact sum when v7 dominates: 1 proves vsum(z) >= 0,
 * -1 says it is negative, 0 undecided. */
/*@ requires fin: vfin(z);
    assigns \nothing;
    ensures pos: \result > 0 ==> vsum(z) >= 0;
    ensures neg: \result < 0 ==> (z.v7 < 0 && 0x1.8p0 * z.v7 <= vsum(z));
*/
static int decide(cbx_vec8 z)
{
    if ((z.v0 == 0.0) && (z.v1 == 0.0) && (z.v2 == 0.0) && (z.v3 == 0.0) && (z.v4 == 0.0)
        && (z.v5 == 0.0) && (z.v6 == 0.0)) {
        return (z.v7 >= 0.0) ? 1 : -1;
    }
    double s = cbx_abs(z.v7);
    if (!((s >= 0x1p-1060) && (s <= 0x1p1020))) {
        return 0;
    }
    double p = cbx_mul_rn(s, 0x1p-4);
    /*@ assert pb: p <= s * 0x1p-4 + 0x1p-57 * s + 0x1p-1074; */
    if ((cbx_abs(z.v0) <= p) && (cbx_abs(z.v1) <= p) && (cbx_abs(z.v2) <= p) && (cbx_abs(z.v3) <= p)
        && (cbx_abs(z.v4) <= p) && (cbx_abs(z.v5) <= p) && (cbx_abs(z.v6) <= p)) {
        return (z.v7 > 0.0) ? 1 : -1;
    }
    return 0;
}

/* 1 only if c <= the exact sum of y (y.v7 == 0). */
/*@ requires fin: vfin(y) && \is_finite(c) && -0x1p1018 <= c <= 0x1p1018;
    requires free: y.v7 == 0;
    assigns \nothing;
    ensures ok: \result != 0 ==> c <= vsum(y);
*/
static int certify(cbx_vec8 y, double c)
{
    cbx_vec8 z = y;
    int i;
    z.v7 = -c;
    /*@ assert z0: vsum(z) == vsum(y) - c; */
    /*@ loop invariant rng: 0 <= i <= 6;
        loop invariant fin: vfin(z);
        loop invariant sum: vsum(z) == vsum(y) - c;
        loop assigns i, z;
        loop variant 6 - i;
    */
    for (i = 0; i < 6; i++) {
        int d = decide(z);
        if (d != 0) {
            return d > 0;
        }
        z = pass8(z);
    }
    return decide(z) > 0;
}

/* A candidate for the rounded sum: the distilled running sum. */
/*@ requires fin: vfin(y);
    assigns \nothing;
    ensures fin: \is_finite(\result);
*/
static double approx(cbx_vec8 y)
{
    cbx_vec8 z = pass8(pass8(pass8(y)));
    return z.v7;
}

/* The next double above c, or below (dn): c +- (RN(phi |c|) + eta) with
 * phi = u (1 + 2u) (Rump, Zimmermann, Boldo, Melquiond, BIT 2009).  Only
 * a candidate: the certificate decides. */
/*@ requires fin: \is_finite(c) && -0x1p1018 <= c <= 0x1p1018;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures rng: -0x1.01p1018 <= \result <= 0x1.01p1018;
*/
static double neighbour(double c, int dn)
{
    double e = cbx_mul_rn(cbx_abs(c), 0x1.0000000000001p-53);
    double f = cbx_add_rn(e, 0x1p-1074);
    return dn ? cbx_sub_rn(c, f) : cbx_add_rn(c, f);
}

/* two_prod's domain: the product is 0 or its error term is a double. */
/* proof: -wp-split */
/*@ requires fin: \is_finite(m) && \is_finite(v) && in_dom(m, v);
    assigns \nothing;
    ensures ok: \result != 0 ==> (m*v == 0 || m*v >= 0x1p-969 || m*v <= -0x1p-969);
*/
static int eft_ok(double m, double v)
{
    if ((m == 0.0) || (v == 0.0)) {
        return 1;
    }
    double p = cbx_mul_rn(m, v);
    return cbx_abs(p) >= 0x1p-968;
}

/* A candidate and whether it is certified. */
typedef struct cand { double c; int ok; } cand;

/* The fast certificate: two distillation passes and one sign decision on
 * the residual.  The first pass leaves the rounded sum s in v7; s moves
 * out (vsum(z) = E - s) and a second pass brings the residual's rounded
 * sum rho to v7.  c = RN(s + rho) with its error e (two_sum: c + e =
 * s + rho exactly) in v7 leaves vsum(w) = E - c, which decide settles
 * when e dominates the second-order terms: E >= c (then c = RD(E), as e
 * is at most half the gap above c), or E < c, and then pred(c) (Rump et
 * al.'s neighbour) is RD(E): decide bounds E - c below by 1.5 e, and
 * rounding to nearest leaves |e| at most half the gap below c, so the
 * check 1.75 |e| <= c - pred(c) (rounded, with room) certifies pred(c) <=
 * E.  Until 2026-11-29 the sum vsum(w) + (c - pred(c)) was certified
 * again, when exact in v7: it was not on 13% of the ends below (random
 * maps and boxes), which then took the full search.  ok == 0 (E within
 * the second-order terms of c): the full search decides. */
/*@ requires fin: vfin(y);
    assigns \nothing;
    ensures fin: \result.ok != 0 ==> \is_finite(\result.c);
    ensures ok: \result.ok != 0 ==> \result.c <= vsum(y);
*/
static cand tighten_fast(cbx_vec8 y)
{
    cand res;
    cbx_vec8 z = pass8(y);
    double s = z.v7;
    res.c = 0.0;
    res.ok = 0;
    z.v7 = 0.0;
    /*@ assert z1: vsum(z) == vsum(y) - s; */
    cbx_vec8 w = pass8(z);
    cbx_dd ce = eft_sum(s, w.v7);
    double c = ce.hi;
    w.v7 = ce.lo;
    /*@ assert w1: vsum(w) == vsum(y) - c; */
    int d = decide(w);
    if (d > 0) {
        res.c = c;
        res.ok = 1;
    } else if ((d < 0) && (c >= -0x1p1017) && (c <= 0x1p1017)) {
        double p = neighbour(c, 1);
        cbx_dd h = eft_sum(c, -p);
        double a = cbx_abs(w.v7);
        if ((h.lo == 0.0) && (a >= 0x1p-1060) && (a <= 0x1p1000) && (cbx_mul_rn(a, 0x1.cp0) <= h.hi)) {
            /*@ assert w2: vsum(y) >= p; */
            res.c = p;
            res.ok = 1;
        }
    }
    return res;
}

/* The largest certified double <= vsum(y), or r when none beats r: the
 * fast certificate, else the full search (three passes for the candidate,
 * each candidate certified from the start). */
/*@ requires fin: vfin(y) && \is_finite(r);
    requires free: y.v7 == 0;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures same_or_better: \result == r || (r < \result && \result <= vsum(y));
*/
static double tighten_core(double r, cbx_vec8 y)
{
    double best = r;
    cand f = tighten_fast(y);
    if (f.ok != 0) {
        return (f.c > r) ? f.c : r;
    }
    double c = approx(y);
    if (!((c >= -0x1p1017) && (c <= 0x1p1017))) {
        return r;
    }
    if (certify(y, c) != 0) {
        if (c > best) {
            best = c;
        }
        double u = neighbour(c, 0);
        if ((u >= -0x1p1018) && (u <= 0x1p1018) && (u > best) && certify(y, u)) {
            best = u;
        }
    } else {
        double d = neighbour(c, 1);
        if ((d >= -0x1p1018) && (d <= 0x1p1018) && (d > best) && certify(y, d)) {
            best = d;
        }
    }
    return best;
}

/* The first try at a tight end (tighten_lo, tighten_hi): Ogita, Rump and
 * Oishi's compensated dot product (Dot2, SIAM J. Sci. Comput. 26(6),
 * 2005) with a certified error bound, branch-light and without the
 * distillation's dependency chains.  E = t + m.v is split exactly into
 * s3 (three two_sums of t and the rounded products) plus a tail T of six
 * error terms; the tail is summed to nearest (r, off by at most d) and c
 * = RN(s3 + r) with its error e, so E - c = e + (T - r) lies within d of
 * e.  e >= d certifies c <= E (c is then RD(E): e is at most half the
 * gap above c); e < -d certifies E < c, and pred(c) <= E when c - pred(c)
 * >= d - e.  A tail of zeros means E = s3 exactly.  ok == 0 (products
 * outside [2^-968, 2^1014], |t| > 2^1015, or E within d of a double other
 * than s3): tighten_fast and the full search decide. */

/* One product's range for the fast end: 0, or its rounded value in
 * [2^-968, 2^1014] (two_prod's domain; sums that stay in two_sum's). */
/* proof: -wp-split */
/*@ requires fin: \is_finite(m) && \is_finite(v) && in_dom(m, v);
    assigns \nothing;
    ensures rng: 0 <= \result <= 1;
    ensures ok: \result != 0 ==> (m*v == 0 || 0x1p-969 <= \abs(m*v) <= 0x1p1015);
    ensures all: tprod(m, v) ==> \result == 1;
*/
static int fast_ok(double m, double v)
{
    double p = cbx_abs(cbx_mul_rn(m, v));
    /*@ assert lo: p >= 0x1p-968 ==> 0x1p-969 <= \abs(m*v); */
    /*@ assert hi: p <= 0x1p1014 ==> \abs(m*v) <= 0x1p1015; */
    /*@ assert z0: m == 0 ==> m*v == 0; */
    /*@ assert z1: v == 0 ==> m*v == 0; */
    /*@ assert pl: 0x1p-967 <= \abs(m*v) ==> p >= 0x1p-968; */
    /*@ assert ph: \abs(m*v) <= 0x1p1013 ==> p <= 0x1p1014; */
    /* counts, not && and ||: no branch on the product's sign or size */
    int z = (m == 0.0) + (v == 0.0);
    int n = (p >= 0x1p-968) + (p <= 0x1p1014);
    /*@ assert az: (m == 0 || v == 0) ==> z >= 1; */
    /*@ assert an: (0x1p-967 <= \abs(m*v) <= 0x1p1013) ==> n == 2; */
    /*@ assert nn: 0 <= z <= 2 && 0 <= n <= 2; */
    /*@ assert c2: (m == 0 || v == 0) ==> z + z + n >= 2; */
    /*@ assert c3: (0x1p-967 <= \abs(m*v) <= 0x1p1013) ==> z + z + n >= 2; */
    /*@ assert c4: tprod(m, v) ==> (m == 0 || v == 0 || (0x1p-967 <= \abs(m*v) <= 0x1p1013)); */
    return (z + z + n) >= 2;
}

/* Six doubles of magnitude at most M summed to nearest: five additions,
 * each off by at most u times its sum plus eta; step k's error and
 * magnitude carried in its assertions (23.1 u M + 9 eta in all).  The
 * multiples of eta are whole: an ACSL constant is a double, and 1.01 eta
 * would round to eta. */
/*@ requires fin: \is_finite(x0) && \is_finite(x1) && \is_finite(x2) && \is_finite(x3)
                  && \is_finite(x4) && \is_finite(x5) && \is_finite(M);
    requires mag: \abs(x0) <= M && \abs(x1) <= M && \abs(x2) <= M && \abs(x3) <= M
                  && \abs(x4) <= M && \abs(x5) <= M && M <= 0x1p1000;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures err: \abs(\result - (x0 + x1 + x2 + x3 + x4 + x5)) <= 0x1p-48 * M + 0x1.2p-1071;
*/
static double sum6(double x0, double x1, double x2, double x3, double x4, double x5, double M)
{
    double a1 = cbx_add_rn(x0, x1);
    (void)M; /* the bound's parameter: used by the contract only */
    /*@ assert e1: \abs(a1 - (x0 + x1)) <= 0x1p-52 * M + 0x1p-1074; */
    /*@ assert m1: \abs(a1) <= 0x1.001p1 * M + 0x1p-1074; */
    double a2 = cbx_add_rn(a1, x2);
    /*@ assert t2: \abs(a2 - (a1 + x2)) <= 0x1p-53 * (\abs(a1) + \abs(x2)) + 0x1p-1074; */
    /*@ assert s2: \abs(a1) + \abs(x2) <= 0x1.001p1 * M + M + 0x1p-1074; */
    /*@ assert w2: 0x1p-53 * (\abs(a1) + \abs(x2)) <= 0x1p-53 * (0x1.001p1 * M + M + 0x1p-1074); */
    /*@ assert u2: \abs(a2 - (a1 + x2)) <= 0x1.81p-52 * M + 0x1p-1073; */
    /*@ assert e2: \abs(a2 - (x0 + x1 + x2)) <= 0x1.8p-51 * M + 0x1.8p-1073; */
    /*@ assert m2: \abs(a2) <= 0x1.801p1 * M + 0x1.8p-1073; */
    double a3 = cbx_add_rn(a2, x3);
    /*@ assert t3: \abs(a3 - (a2 + x3)) <= 0x1p-53 * (\abs(a2) + \abs(x3)) + 0x1p-1074; */
    /*@ assert s3: \abs(a2) + \abs(x3) <= 0x1.801p1 * M + M + 0x1.8p-1073; */
    /*@ assert w3: 0x1p-53 * (\abs(a2) + \abs(x3)) <= 0x1p-53 * (0x1.801p1 * M + M + 0x1.8p-1073); */
    /*@ assert u3: \abs(a3 - (a2 + x3)) <= 0x1.01p-51 * M + 0x1p-1073; */
    /*@ assert e3: \abs(a3 - (x0 + x1 + x2 + x3)) <= 0x1.6p-50 * M + 0x1.4p-1072; */
    /*@ assert m3: \abs(a3) <= 0x1.001p2 * M + 0x1.4p-1072; */
    double a4 = cbx_add_rn(a3, x4);
    /*@ assert t4: \abs(a4 - (a3 + x4)) <= 0x1p-53 * (\abs(a3) + \abs(x4)) + 0x1p-1074; */
    /*@ assert s4: \abs(a3) + \abs(x4) <= 0x1.001p2 * M + M + 0x1.4p-1072; */
    /*@ assert w4: 0x1p-53 * (\abs(a3) + \abs(x4)) <= 0x1p-53 * (0x1.001p2 * M + M + 0x1.4p-1072); */
    /*@ assert u4: \abs(a4 - (a3 + x4)) <= 0x1.41p-51 * M + 0x1p-1073; */
    /*@ assert e4: \abs(a4 - (x0 + x1 + x2 + x3 + x4)) <= 0x1.1p-49 * M + 0x1.cp-1072; */
    /*@ assert m4: \abs(a4) <= 0x1.401p2 * M + 0x1.cp-1072; */
    double a5 = cbx_add_rn(a4, x5);
    /*@ assert t5: \abs(a5 - (a4 + x5)) <= 0x1p-53 * (\abs(a4) + \abs(x5)) + 0x1p-1074; */
    /*@ assert s5: \abs(a4) + \abs(x5) <= 0x1.401p2 * M + M + 0x1.cp-1072; */
    /*@ assert w5: 0x1p-53 * (\abs(a4) + \abs(x5)) <= 0x1p-53 * (0x1.401p2 * M + M + 0x1.cp-1072); */
    /*@ assert u5: \abs(a5 - (a4 + x5)) <= 0x1.81p-51 * M + 0x1p-1073; */
    return a5;
}

/* -(hi + lo), exactly. */
/*@ requires fin: \is_finite(a.hi) && \is_finite(a.lo);
    assigns \nothing;
    ensures fin: \is_finite(\result.hi) && \is_finite(\result.lo);
    ensures neg: \result.hi == -a.hi && \result.lo == -a.lo;
*/
static cbx_dd dd_neg(cbx_dd a)
{
    cbx_dd r;
    r.hi = -a.hi;
    r.lo = -a.lo;
    return r;
}

/* Lemma function (empty body): two_prod's low part is the high part's
 * rounding error, at most 2^-53 of the product plus the subnormal
 * spacing (proved alone: in dot_prods' context the provers time out). */
/*@ requires fin: \is_finite(hi) && \is_finite(lo);
    requires rng: -0x1p1018 <= m*v <= 0x1p1018;
    requires rn: hi == (double)(m*v);
    requires ex: hi + lo == m*v;
    assigns \nothing;
    ensures err: \abs(lo) <= 0x1p-53 * \abs(m*v) + 0x1p-1074;
*/
static void rn_err(double m, double v, double hi, double lo) { (void)m; (void)v; (void)hi; (void)lo; }

/* The three products of an end split exactly (two_prod), when all three
 * are in dot_sum's range; ok == 0 otherwise. */
typedef struct prods { cbx_dd p0; cbx_dd p1; cbx_dd p2; int ok; } prods;

/*@ requires fin: map_fin(m0, m1, m2, t) && \is_finite(v0) && \is_finite(v1) && \is_finite(v2);
    requires dom: in_dom(m0, v0) && in_dom(m1, v1) && in_dom(m2, v2);
    assigns \nothing;
    ensures ok: \result.ok != 0 ==> (dd_in(\result.p0) && dd_in(\result.p1) && dd_in(\result.p2)
                                    && -0x1p1015 <= t <= 0x1p1015);
    ensures ex: \result.ok != 0 ==> (\result.p0.hi + \result.p0.lo == m0*v0
                                    && \result.p1.hi + \result.p1.lo == m1*v1
                                    && \result.p2.hi + \result.p2.lo == m2*v2);
    ensures all: (tprod(m0, v0) && tprod(m1, v1) && tprod(m2, v2) && -0x1p1015 <= t <= 0x1p1015)
                 ==> \result.ok != 0;
*/
static prods dot_prods(double m0, double m1, double m2, double t, double v0, double v1, double v2)
{
    prods q;
    q.p0.hi = 0.0; q.p0.lo = 0.0; q.p1 = q.p0; q.p2 = q.p0;
    q.ok = 0;
    if ((fast_ok(m0, v0) + fast_ok(m1, v1) + fast_ok(m2, v2)
        + (t >= -0x1p1015) + (t <= 0x1p1015)) != 5) {
        return q;
    }
    q.p0 = cbx_two_prod(m0, v0);
    rn_err(m0, v0, q.p0.hi, q.p0.lo);
    /*@ assert r0: \abs(q.p0.lo) <= 0x1p-53 * \abs(m0*v0) + 0x1p-1074; */
    q.p1 = cbx_two_prod(m1, v1);
    rn_err(m1, v1, q.p1.hi, q.p1.lo);
    /*@ assert r1: \abs(q.p1.lo) <= 0x1p-53 * \abs(m1*v1) + 0x1p-1074; */
    q.p2 = cbx_two_prod(m2, v2);
    rn_err(m2, v2, q.p2.hi, q.p2.lo);
    /*@ assert r2: \abs(q.p2.lo) <= 0x1p-53 * \abs(m2*v2) + 0x1p-1074; */
    q.ok = 1;
    return q;
}

/* Ogita, Rump and Oishi's Dot2 on t + p0 + p1 + p2 (each pair exact),
 * with a proven error bound: three two_sums leave the exact sum E as s3 +
 * T, T the six error terms; sum6 sums T to nearest (within 2^-48 M + 9
 * eta, M the largest term), c = RN(s3 + r) with its error e, and d bounds
 * the rest.  e >= d certifies c <= E; e < -d with c - pred(c) >= 1.125
 * (d - e) (rounded up, on the exact difference) certifies pred(c); a tail
 * of zeros gives E = s3.  Which case holds is a coin toss: counts and
 * selects, and one branch, taken when none holds (rare).  ok != 0: the
 * certified end (the exact end rounded down: the tests check it).  In
 * every case c is at least f = c - (2^-52 |c| + 2 d), rounded: below E,
 * as |e| <= 2^-53 |c + e|, and within 2^-50 |E| + 4 d of it (near). */
/*@ requires fin: \is_finite(t);
    requires rng: dd_in(p0) && dd_in(p1) && dd_in(p2) && -0x1p1015 <= t <= 0x1p1015;
    assigns \nothing;
    ensures fin: \is_finite(\result.c);
    ensures below: \result.c <= p0.hi + p0.lo + p1.hi + p1.lo + p2.hi + p2.lo + t;
    ensures near: p0.hi + p0.lo + p1.hi + p1.lo + p2.hi + p2.lo + t - \result.c
                  <= 0x1p-50 * \abs(p0.hi + p0.lo + p1.hi + p1.lo + p2.hi + p2.lo + t)
                     + 0x1.1p-97 * (\abs(t) + \abs(p0.hi) + \abs(p1.hi) + \abs(p2.hi)) + 0x1p-1057;
*/
static cand dot_sum(cbx_dd p0, cbx_dd p1, cbx_dd p2, double t)
{
    cand res;
    cbx_dd s1 = cbx_two_sum(t, p0.hi);
    /*@ assert q1: \abs(s1.hi) <= 0x1.04p1016 && \abs(s1.lo) <= 0x1p1000; */
    /*@ assert a1: \abs(s1.lo) <= 0x1p-53 * (\abs(t) + \abs(p0.hi)) + 0x1p-1074
                   && \abs(s1.hi) <= 0x1.0000000000001p0 * (\abs(t) + \abs(p0.hi)) + 0x1p-1074; */
    cbx_dd s2 = cbx_two_sum(s1.hi, p1.hi);
    /*@ assert q2: \abs(s2.hi) <= 0x1.9p1016 && \abs(s2.lo) <= 0x1p1000; */
    /*@ assert a2: \abs(s2.lo) <= 0x1p-53 * (\abs(s1.hi) + \abs(p1.hi)) + 0x1p-1074
                   && \abs(s2.hi) <= 0x1.0000000000001p0 * (\abs(s1.hi) + \abs(p1.hi)) + 0x1p-1074; */
    cbx_dd s3 = cbx_two_sum(s2.hi, p2.hi);
    /*@ assert q3: \abs(s3.hi) <= 0x1.1p1017 && \abs(s3.lo) <= 0x1p1000; */
    /*@ assert a3: \abs(s3.lo) <= 0x1p-53 * (\abs(s2.hi) + \abs(p2.hi)) + 0x1p-1074; */
    /*@ assert ex: s3.hi + (p0.lo + p1.lo + p2.lo + s1.lo + s2.lo + s3.lo) == p0.hi + p0.lo + p1.hi + p1.lo + p2.hi + p2.lo + t; */
    double mx = cbx_max2(cbx_max2(cbx_max2(cbx_abs(p0.lo), cbx_abs(p1.lo)),
                                  cbx_max2(cbx_abs(p2.lo), cbx_abs(s1.lo))),
                         cbx_max2(cbx_abs(s2.lo), cbx_abs(s3.lo)));
    /*@ assert mxs: mx <= 0x1.01p-52 * (\abs(t) + \abs(p0.hi) + \abs(p1.hi) + \abs(p2.hi)) + 0x1p-1072; */
    double r = sum6(p0.lo, p1.lo, p2.lo, s1.lo, s2.lo, s3.lo, mx);
    double d = cbx_add_rn(cbx_mul_rn(mx, 0x1p-47), 0x1p-1060);
    /*@ assert dd: 0x1p-48 * mx + 0x1.2p-1071 <= d; */
    /*@ assert du: d <= 0x1.01p-47 * mx + 0x1.01p-1060; */
    /*@ assert d4: 4 * d <= 0x1.1p-97 * (\abs(t) + \abs(p0.hi) + \abs(p1.hi) + \abs(p2.hi)) + 0x1p-1057; */
    cbx_dd ce = cbx_two_sum(s3.hi, r);
    double c = ce.hi;
    double e = ce.lo;
    /*@ assert w: p0.hi + p0.lo + p1.hi + p1.lo + p2.hi + p2.lo + t - c >= e - d; */
    /*@ assert wu: p0.hi + p0.lo + p1.hi + p1.lo + p2.hi + p2.lo + t - c <= e + d; */
    /*@ assert cr: -0x1p1018 <= c <= 0x1p1018; */
    /*@ assert ea: \abs(e) <= 0x1p-53 * \abs(c + e) + 0x1p-1074; */
    /*@ assert eb: \abs(e) <= 0x1.01p-53 * \abs(c) + 0x1p-1073; */
    double p = neighbour(c, 1);
    cbx_dd h = cbx_two_sum(c, -p);
    double g = cbx_mul_rn(cbx_sub_rn(d, e), 0x1.2p0);
    double nd = -d; /* not in the comparison: -d inside an int sum made Why3 reject the goals */
    int dn = ((e < nd) + (h.lo == 0.0) + (g <= h.hi)) == 3;
    /*@ assert w2: dn != 0 ==> p0.hi + p0.lo + p1.hi + p1.lo + p2.hi + p2.lo + t >= p; */
    /*@ assert z: mx == 0 ==> s3.hi == p0.hi + p0.lo + p1.hi + p1.lo + p2.hi + p2.lo + t; */
    /* the lower end that holds in every case */
    double k1 = cbx_mul_rn(cbx_abs(c), 0x1.01p-52);
    double k2 = cbx_add_rn(d, d);
    double k = cbx_add_rn(k1, k2);
    /*@ assert kl: k >= 0x1.009p-52 * \abs(c) + 0x1.ffp0 * d; */
    /*@ assert ku: k <= 0x1.02p-52 * \abs(c) + 0x1.01p1 * d; */
    double f = cbx_sub_rn(c, k);
    /*@ assert fu: f <= c - k + 0x1p-53 * (\abs(c) + k) + 0x1p-1074; */
    /*@ assert fl: f >= c - k - 0x1p-53 * (\abs(c) + k) - 0x1p-1074; */
    /*@ assert fb: f <= p0.hi + p0.lo + p1.hi + p1.lo + p2.hi + p2.lo + t; */
    /*@ assert fc: p0.hi + p0.lo + p1.hi + p1.lo + p2.hi + p2.lo + t - f <= 0x1.03p-51 * \abs(c) + 0x1.9p1 * d; */
    /*@ assert cE: \abs(c) <= 0x1.0000001p0 * \abs(p0.hi + p0.lo + p1.hi + p1.lo + p2.hi + p2.lo + t) + 0x1.01p0 * d; */
    /*@ assert fE: p0.hi + p0.lo + p1.hi + p1.lo + p2.hi + p2.lo + t - f
                   <= 0x1p-50 * \abs(p0.hi + p0.lo + p1.hi + p1.lo + p2.hi + p2.lo + t) + 4 * d; */
    /*@ assert fn: p0.hi + p0.lo + p1.hi + p1.lo + p2.hi + p2.lo + t - f
                   <= 0x1p-50 * \abs(p0.hi + p0.lo + p1.hi + p1.lo + p2.hi + p2.lo + t)
                      + 0x1.1p-97 * (\abs(t) + \abs(p0.hi) + \abs(p1.hi) + \abs(p2.hi)) + 0x1p-1057; */
    res.ok = ((e >= d) + dn + (mx == 0.0)) != 0;
    if (res.ok == 0) {
        res.c = f;
        return res;
    }
    double x = (e >= d) ? c : p;
    double y = (mx == 0.0) ? s3.hi : x;
    res.c = cbx_max2(y, f);
    return res;
}

/* The seven exact terms of t + m.v, negated when neg != 0; ok == 0 when a
 * product is outside two_prod's domain. */
typedef struct terms { cbx_vec8 y; int ok; } terms;

/*@ requires fin: map_fin(m0, m1, m2, t) && \is_finite(v0) && \is_finite(v1) && \is_finite(v2);
    requires dom: in_dom(m0, v0) && in_dom(m1, v1) && in_dom(m2, v2) && -0x1p1018 <= t <= 0x1p1018;
    assigns \nothing;
    ensures fin: \result.ok != 0 ==> (vfin(\result.y) && \result.y.v7 == 0);
    ensures pos: (\result.ok != 0 && neg == 0) ==> vsum(\result.y) == m0*v0 + m1*v1 + m2*v2 + t;
    ensures neg: (\result.ok != 0 && neg != 0) ==> vsum(\result.y) == -(m0*v0 + m1*v1 + m2*v2 + t);
*/
static terms exact_terms(double m0, double m1, double m2, double t,
                         double v0, double v1, double v2, int neg)
{
    terms r;
    r.y.v0 = 0.0; r.y.v1 = 0.0; r.y.v2 = 0.0; r.y.v3 = 0.0;
    r.y.v4 = 0.0; r.y.v5 = 0.0; r.y.v6 = 0.0; r.y.v7 = 0.0;
    r.ok = 0;
    if (!eft_ok(m0, v0) || !eft_ok(m1, v1) || !eft_ok(m2, v2)) {
        return r;
    }
    cbx_dd q0 = cbx_two_prod(m0, v0);
    cbx_dd q1 = cbx_two_prod(m1, v1);
    cbx_dd q2 = cbx_two_prod(m2, v2);
    if (neg != 0) {
        r.y.v0 = -t; r.y.v1 = -q0.lo; r.y.v2 = -q1.lo; r.y.v3 = -q2.lo;
        r.y.v4 = -q0.hi; r.y.v5 = -q1.hi; r.y.v6 = -q2.hi;
    } else {
        r.y.v0 = t; r.y.v1 = q0.lo; r.y.v2 = q1.lo; r.y.v3 = q2.lo;
        r.y.v4 = q0.hi; r.y.v5 = q1.hi; r.y.v6 = q2.hi;
    }
    r.ok = 1;
    return r;
}

/* The largest certified double <= t + m.v, or r when none beats r; on
 * dot_sum's range, at least dot_sum's lower end (near). */
/*@ requires fin: map_fin(m0, m1, m2, t) && \is_finite(v0) && \is_finite(v1) && \is_finite(v2);
    requires finr: \is_finite(r);
    requires dom: in_dom(m0, v0) && in_dom(m1, v1) && in_dom(m2, v2) && -0x1p1018 <= t <= 0x1p1018;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures same_or_better: \result == r || (r < \result && \result <= m0*v0 + m1*v1 + m2*v2 + t);
    ensures near: (tprod(m0, v0) && tprod(m1, v1) && tprod(m2, v2) && -0x1p1015 <= t <= 0x1p1015)
                  ==> m0*v0 + m1*v1 + m2*v2 + t - \result
                      <= tgap(m0*v0 + m1*v1 + m2*v2 + t, \abs(t) + \abs(m0*v0) + \abs(m1*v1) + \abs(m2*v2));
*/
static double tighten_lo(double r, double m0, double m1, double m2, double t,
                         double v0, double v1, double v2)
{
    double b = r;
    prods q = dot_prods(m0, m1, m2, t, v0, v1, v2);
    if (q.ok != 0) {
        cand x = dot_sum(q.p0, q.p1, q.p2, t);
        /*@ assert hs: \abs(q.p0.hi) + \abs(q.p1.hi) + \abs(q.p2.hi)
                       <= 0x1.0000000000002p0 * (\abs(m0*v0) + \abs(m1*v1) + \abs(m2*v2)); */
        b = (x.c > r) ? x.c : r;
        if (x.ok != 0) {
            return b;
        }
    }
    terms e = exact_terms(m0, m1, m2, t, v0, v1, v2, 0);
    if (!e.ok) {
        return b;
    }
    return tighten_core(b, e.y);
}

/* The smallest certified double >= t + m.v, or r: the same on -(t + m.v). */
/*@ requires fin: map_fin(m0, m1, m2, t) && \is_finite(v0) && \is_finite(v1) && \is_finite(v2);
    requires finr: \is_finite(r);
    requires dom: in_dom(m0, v0) && in_dom(m1, v1) && in_dom(m2, v2) && -0x1p1018 <= t <= 0x1p1018;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures same_or_better: \result == r || (\result < r && m0*v0 + m1*v1 + m2*v2 + t <= \result);
    ensures near: (tprod(m0, v0) && tprod(m1, v1) && tprod(m2, v2) && -0x1p1015 <= t <= 0x1p1015)
                  ==> \result - (m0*v0 + m1*v1 + m2*v2 + t)
                      <= tgap(m0*v0 + m1*v1 + m2*v2 + t, \abs(t) + \abs(m0*v0) + \abs(m1*v1) + \abs(m2*v2));
*/
static double tighten_hi(double r, double m0, double m1, double m2, double t,
                         double v0, double v1, double v2)
{
    double b = r;
    prods q = dot_prods(m0, m1, m2, t, v0, v1, v2);
    if (q.ok != 0) {
        cand f = dot_sum(dd_neg(q.p0), dd_neg(q.p1), dd_neg(q.p2), -t);
        /*@ assert hs: \abs(q.p0.hi) + \abs(q.p1.hi) + \abs(q.p2.hi)
                       <= 0x1.0000000000002p0 * (\abs(m0*v0) + \abs(m1*v1) + \abs(m2*v2)); */
        double y = -f.c;
        b = (y < r) ? y : r;
        if (f.ok != 0) {
            return b;
        }
    }
    terms e = exact_terms(m0, m1, m2, t, v0, v1, v2, 1);
    if (!e.ok) {
        return b;
    }
    double x = tighten_core(-b, e.y);
    return -x;
}

/* Lemma functions (empty bodies): a tighter end certified at the vertex
 * keeps the whole axis promise. */
/*@ requires sound: axis_sound_s(lo, hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    requires nan: !\is_NaN(l0) && !\is_NaN(h0) && !\is_NaN(l1) && !\is_NaN(h1)
                  && !\is_NaN(l2) && !\is_NaN(h2);
    requires ne: !no_point(l0, h0) && !no_point(l1, h1) && !no_point(l2, h2);
    requires fin: \is_finite(lo) && \is_finite(c) && map_fin(m0, m1, m2, t);
    requires col: (\forall real p; ext_in(p, l0, h0) ==> m0*v0 <= m0*p) && (\forall real p; ext_in(p, l1, h1) ==> m1*v1 <= m1*p) && (\forall real p; ext_in(p, l2, h2) ==> m2*v2 <= m2*p);
    requires gt: lo < c && c <= m0*v0 + m1*v1 + m2*v2 + t;
    assigns \nothing;
    ensures axis_sound_s(c, hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
*/
static void tight_lo_sound(double lo, double hi, double c, double m0, double m1, double m2,
                           double t, double l0, double h0, double l1, double h1,
                           double l2, double h2, double v0, double v1, double v2)
{
    /*@ assert i0: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==> (ext_in(l0, l0, h0) && ext_in(h0, l0, h0)); */
    /*@ assert c0: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==> (m0*v0 <= m0*l0 && m0*v0 <= m0*h0); */
    /*@ assert i1: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==> (ext_in(l1, l1, h1) && ext_in(h1, l1, h1)); */
    /*@ assert c1: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==> (m1*v1 <= m1*l1 && m1*v1 <= m1*h1); */
    /*@ assert i2: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==> (ext_in(l2, l2, h2) && ext_in(h2, l2, h2)); */
    /*@ assert c2: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==> (m2*v2 <= m2*l2 && m2*v2 <= m2*h2); */
    /*@ assert b8: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==> below8(c, m0, m1, m2, t, l0, h0, l1, h1, l2, h2); */
    /*@ assert lt: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==> lo_tight(c, m0, m1, m2, t, l0, h0, l1, h1, l2, h2); */
    /*@ assert eb: ext_below(c, m0, m1, m2, t, l0, h0, l1, h1, l2, h2); */
    /*@ assert ee: (!row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) && map_fin(m0, m1, m2, t)) ==> ext_lo_end(c, m0, m1, m2, t, l0, h0, l1, h1, l2, h2); */
    (void)lo; (void)hi; (void)c; (void)m0; (void)m1; (void)m2; (void)t;
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2; (void)v0; (void)v1; (void)v2;
}

/*@ requires sound: axis_sound_s(lo, hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    requires nan: !\is_NaN(l0) && !\is_NaN(h0) && !\is_NaN(l1) && !\is_NaN(h1)
                  && !\is_NaN(l2) && !\is_NaN(h2);
    requires ne: !no_point(l0, h0) && !no_point(l1, h1) && !no_point(l2, h2);
    requires fin: \is_finite(hi) && \is_finite(c) && map_fin(m0, m1, m2, t);
    requires col: (\forall real p; ext_in(p, l0, h0) ==> m0*v0 >= m0*p) && (\forall real p; ext_in(p, l1, h1) ==> m1*v1 >= m1*p) && (\forall real p; ext_in(p, l2, h2) ==> m2*v2 >= m2*p);
    requires lt: c < hi && m0*v0 + m1*v1 + m2*v2 + t <= c;
    assigns \nothing;
    ensures axis_sound_s(lo, c, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
*/
static void tight_hi_sound(double lo, double hi, double c, double m0, double m1, double m2,
                           double t, double l0, double h0, double l1, double h1,
                           double l2, double h2, double v0, double v1, double v2)
{
    /*@ assert i0: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==> (ext_in(l0, l0, h0) && ext_in(h0, l0, h0)); */
    /*@ assert c0: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==> (m0*v0 >= m0*l0 && m0*v0 >= m0*h0); */
    /*@ assert i1: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==> (ext_in(l1, l1, h1) && ext_in(h1, l1, h1)); */
    /*@ assert c1: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==> (m1*v1 >= m1*l1 && m1*v1 >= m1*h1); */
    /*@ assert i2: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==> (ext_in(l2, l2, h2) && ext_in(h2, l2, h2)); */
    /*@ assert c2: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==> (m2*v2 >= m2*l2 && m2*v2 >= m2*h2); */
    /*@ assert b8: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==> above8(c, m0, m1, m2, t, l0, h0, l1, h1, l2, h2); */
    /*@ assert lt: row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) ==> hi_tight(c, m0, m1, m2, t, l0, h0, l1, h1, l2, h2); */
    /*@ assert eb: ext_above(c, m0, m1, m2, t, l0, h0, l1, h1, l2, h2); */
    /*@ assert ee: (!row_full(m0, m1, m2, t, l0, h0, l1, h1, l2, h2) && map_fin(m0, m1, m2, t)) ==> ext_hi_end(c, m0, m1, m2, t, l0, h0, l1, h1, l2, h2); */
    (void)lo; (void)hi; (void)c; (void)m0; (void)m1; (void)m2; (void)t;
    (void)l0; (void)h0; (void)l1; (void)h1; (void)l2; (void)h2; (void)v0; (void)v1; (void)v2;
}

typedef struct tight_result { double lo; double hi; } tight_result;

/* One axis: tighten each finite end of a sound axis at its vertex. */
/*@ requires sound: axis_sound_s(lo, hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    requires nan: !\is_NaN(l0) && !\is_NaN(h0) && !\is_NaN(l1) && !\is_NaN(h1)
                  && !\is_NaN(l2) && !\is_NaN(h2) && !\is_NaN(lo) && !\is_NaN(hi);
    requires ne: !no_point(l0, h0) && !no_point(l1, h1) && !no_point(l2, h2);
    assigns \nothing;
    ensures sound: axis_sound_s(\result.lo, \result.hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
*/
static tight_result tight_axis(double lo, double hi, double m0, double m1, double m2, double t,
                               double l0, double h0, double l1, double h1, double l2, double h2)
{
    tight_result r;
    r.lo = lo;
    r.hi = hi;
    if (!cbx_fin4(m0, m1, m2, t)) {
        return r;
    }
    if (cbx_is_fin(lo) != 0) {
        end_result w0 = vertex_lo(m0, l0, h0);
        end_result w1 = vertex_lo(m1, l1, h1);
        end_result w2 = vertex_lo(m2, l2, h2);
        if (w0.ok && w1.ok && w2.ok
            && cbx_row_ok(m0, m1, m2, t, w0.v, w0.v, w1.v, w1.v, w2.v, w2.v)) {
            double c = tighten_lo(lo, m0, m1, m2, t, w0.v, w1.v, w2.v);
            if (c > lo) {
                tight_lo_sound(lo, hi, c, m0, m1, m2, t, l0, h0, l1, h1, l2, h2, w0.v, w1.v, w2.v);
                r.lo = c;
            }
        }
    }
    if (cbx_is_fin(hi) != 0) {
        end_result w0 = vertex_hi(m0, l0, h0);
        end_result w1 = vertex_hi(m1, l1, h1);
        end_result w2 = vertex_hi(m2, l2, h2);
        if (w0.ok && w1.ok && w2.ok
            && cbx_row_ok(m0, m1, m2, t, w0.v, w0.v, w1.v, w1.v, w2.v, w2.v)) {
            double c = tighten_hi(hi, m0, m1, m2, t, w0.v, w1.v, w2.v);
            if (c < hi) {
                tight_hi_sound(r.lo, hi, c, m0, m1, m2, t, l0, h0, l1, h1, l2, h2, w0.v, w1.v, w2.v);
                r.hi = c;
            }
        }
    }
    return r;
}

/* The vertex of [l, h] where m*x is least (hi: greatest), chosen by a
 * select on m's sign (no branch): l or h even when m == 0, where every
 * point gives m*x == 0. */
/*@ requires fin: \is_finite(m) && \is_finite(l) && \is_finite(h) && l <= h;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures val: \result == l || \result == h;
    ensures col: \forall real p; ext_in(p, l, h) ==> m*\result <= m*p;
    ensures tm: m*\result == tmin(m, l, h);
    ensures tg: \abs(m*\result) <= tmag(m, l, h);
*/
static double vsel_lo(double m, double l, double h)
{
    double v = (m >= 0.0) ? l : h;
    /*@ assert z: m == 0 ==> \forall real p; m*v == m*p; */
    /* the lemmas on v itself: no product of v to rewrite as one of l */
    if (m > 0.0) {
        pos_below(m, v, h);
        /*@ assert ip: nn_prod(m, h - v); */
        /*@ assert dp: m*(h - v) == m*h - m*v; */
        /*@ assert tp: m*v == tmin(m, l, h) && \abs(m*v) <= tmag(m, l, h); */
    } else if (m < 0.0) {
        neg_below(m, l, v);
        /*@ assert in: nn_prod(-m, v - l); */
        /*@ assert dn: (-m)*(v - l) == m*l - m*v; */
        /*@ assert tn: m*v == tmin(m, l, h) && \abs(m*v) <= tmag(m, l, h); */
    } else {
        /*@ assert m0: m == 0; */
        /*@ assert m1: m*v == 0 && m*l == 0 && m*h == 0; */
        /*@ assert t0: m*v == tmin(m, l, h) && \abs(m*v) <= tmag(m, l, h); */
    }
    return v;
}

/*@ requires fin: \is_finite(m) && \is_finite(l) && \is_finite(h) && l <= h;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures val: \result == l || \result == h;
    ensures col: \forall real p; ext_in(p, l, h) ==> m*\result >= m*p;
    ensures tm: m*\result == tmax(m, l, h);
    ensures tg: \abs(m*\result) <= tmag(m, l, h);
*/
static double vsel_hi(double m, double l, double h)
{
    double v = (m >= 0.0) ? h : l;
    /*@ assert z: m == 0 ==> \forall real p; m*v == m*p; */
    /* the lemmas on v itself: no product of v to rewrite as one of h */
    if (m > 0.0) {
        pos_above(m, l, v);
        /*@ assert ip: nn_prod(m, v - l); */
        /*@ assert dp: m*(v - l) == m*v - m*l; */
        /*@ assert tp: m*v == tmax(m, l, h) && \abs(m*v) <= tmag(m, l, h); */
    } else if (m < 0.0) {
        neg_above(m, v, h);
        /*@ assert in: nn_prod(-m, h - v); */
        /*@ assert dn: (-m)*(h - v) == m*v - m*h; */
        /*@ assert tn: m*v == tmax(m, l, h) && \abs(m*v) <= tmag(m, l, h); */
    } else {
        /*@ assert m0: m == 0; */
        /*@ assert m1: m*v == 0 && m*l == 0 && m*h == 0; */
        /*@ assert t0: m*v == tmax(m, l, h) && \abs(m*v) <= tmag(m, l, h); */
    }
    return v;
}

/* One axis of the fast path (map and box in the fast range): both ends
 * tightened at their vertices with no branch on signs or on which
 * certificate holds; tighten_lo / tighten_hi branch only to the full
 * search, for the rare end dot_sum leaves undecided. */
/*@ requires sound: axis_sound_s(lo, hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    requires fin: map_fin(m0, m1, m2, t)
                  && \is_finite(l0) && \is_finite(h0) && \is_finite(l1) && \is_finite(h1)
                  && \is_finite(l2) && \is_finite(h2);
    requires rm: -CBX_SB <= m0 <= CBX_SB && -CBX_SB <= m1 <= CBX_SB && -CBX_SB <= m2 <= CBX_SB;
    requires rb: -CBX_SB <= l0 <= h0 <= CBX_SB && -CBX_SB <= l1 <= h1 <= CBX_SB
                 && -CBX_SB <= l2 <= h2 <= CBX_SB;
    requires rt: -CBX_RT <= t <= CBX_RT;
    assigns \nothing;
    ensures sound: axis_sound_s(\result.lo, \result.hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    ensures near: trow_dom(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
                  ==> trow_near(\result.lo, \result.hi, m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
*/
static tight_result tight_axis_fast(double lo, double hi, double m0, double m1, double m2, double t,
                                    double l0, double h0, double l1, double h1, double l2, double h2)
{
    tight_result r;
    cbx_fast_row(m0, m1, m2, t, l0, h0, l1, h1, l2, h2);
    /*@ assert lf: \is_finite(lo) && \is_finite(hi); */
    double v0 = vsel_lo(m0, l0, h0);
    double v1 = vsel_lo(m1, l1, h1);
    double v2 = vsel_lo(m2, l2, h2);
    double w0 = vsel_hi(m0, l0, h0);
    double w1 = vsel_hi(m1, l1, h1);
    double w2 = vsel_hi(m2, l2, h2);
    /*@ assert dl: trow_dom(m0, m1, m2, t, l0, h0, l1, h1, l2, h2)
                   ==> (tprod(m0, v0) && tprod(m1, v1) && tprod(m2, v2) && tprod(m0, w0) && tprod(m1, w1) && tprod(m2, w2)); */
    double c = tighten_lo(lo, m0, m1, m2, t, v0, v1, v2);
    double d = tighten_hi(hi, m0, m1, m2, t, w0, w1, w2);
    if (c > lo) {
        tight_lo_sound(lo, hi, c, m0, m1, m2, t, l0, h0, l1, h1, l2, h2, v0, v1, v2);
    }
    r.lo = c;
    if (d < hi) {
        tight_hi_sound(c, hi, d, m0, m1, m2, t, l0, h0, l1, h1, l2, h2, w0, w1, w2);
    }
    r.hi = d;
    return r;
}

/* The whole box on the fast path: the branch-free kernel's box, each end
 * then tightened (cbx_fast_box's promise, with CBX_OK).  out may be in
 * (the inputs are read first). */
/*@ requires valid: \valid_read(a) && \valid_read(in) && \valid(out);
    requires sep: \separated(out, a) && (\separated(out, in) || out == in);
    requires fast: map_fast(a) && box_fast(in);
    assigns *out;
    CBX_FAST_POST(a, in, out)
    CBX_TIGHT_NEAR(a, in, out)
*/
static cbx_status tight_box_fast(const cbx_affine *a, const cbx_box *in, cbx_box *out)
{
    double l0 = in->lo[0];
    double l1 = in->lo[1];
    double l2 = in->lo[2];
    double h0 = in->hi[0];
    double h1 = in->hi[1];
    double h2 = in->hi[2];
    double a00 = a->m[0][0];
    double a01 = a->m[0][1];
    double a02 = a->m[0][2];
    double a03 = a->m[0][3];
    double a10 = a->m[1][0];
    double a11 = a->m[1][1];
    double a12 = a->m[1][2];
    double a13 = a->m[1][3];
    double a20 = a->m[2][0];
    double a21 = a->m[2][1];
    double a22 = a->m[2][2];
    double a23 = a->m[2][3];
    (void)cbx_fast_box(a, in, out);
    tight_result r0 = tight_axis_fast(out->lo[0], out->hi[0], a00, a01, a02, a03, l0, h0, l1, h1, l2, h2);
    tight_result r1 = tight_axis_fast(out->lo[1], out->hi[1], a10, a11, a12, a13, l0, h0, l1, h1, l2, h2);
    tight_result r2 = tight_axis_fast(out->lo[2], out->hi[2], a20, a21, a22, a23, l0, h0, l1, h1, l2, h2);
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

/* Every other input: cbx_transform_box (status, special cases, infinite
 * ends), then each finite end tightened at its vertex. */
/*@ requires valid: \valid_read(a) && \valid_read(in) && \valid(out);
    requires sep: \separated(out, a) && (\separated(out, in) || out == in);
    assigns *out;
    CBX_BOX_BEHAVIORS(a, in, out)
*/
static cbx_status tight_box_slow(const cbx_affine *a, const cbx_box *in, cbx_box *out)
{
    double l0 = in->lo[0];
    double l1 = in->lo[1];
    double l2 = in->lo[2];
    double h0 = in->hi[0];
    double h1 = in->hi[1];
    double h2 = in->hi[2];
    double a00 = a->m[0][0];
    double a01 = a->m[0][1];
    double a02 = a->m[0][2];
    double a03 = a->m[0][3];
    double a10 = a->m[1][0];
    double a11 = a->m[1][1];
    double a12 = a->m[1][2];
    double a13 = a->m[1][3];
    double a20 = a->m[2][0];
    double a21 = a->m[2][1];
    double a22 = a->m[2][2];
    double a23 = a->m[2][3];
    cbx_status st = cbx_transform_box(a, in, out);
    if ((st != CBX_OK) && (st != CBX_ERANGE)) {
        return st;
    }
    tight_result r0 = tight_axis(out->lo[0], out->hi[0], a00, a01, a02, a03, l0, h0, l1, h1, l2, h2);
    tight_result r1 = tight_axis(out->lo[1], out->hi[1], a10, a11, a12, a13, l0, h0, l1, h1, l2, h2);
    tight_result r2 = tight_axis(out->lo[2], out->hi[2], a20, a21, a22, a23, l0, h0, l1, h1, l2, h2);
    out->lo[0] = r0.lo; out->hi[0] = r0.hi;
    out->lo[1] = r1.lo; out->hi[1] = r1.hi;
    out->lo[2] = r2.lo; out->hi[2] = r2.hi;
    return st;
}

/* One check per map and per box, as cbx_transform_box. */
/* proof: -wp-split */
cbx_status cbx_transform_box_tight(const cbx_affine *a, const cbx_box *in, cbx_box *out)
{
    if (cbx_map_fast(a) && cbx_box_fast(in)) {
        return tight_box_fast(a, in, out);
    }
    return tight_box_slow(a, in, out);
}
