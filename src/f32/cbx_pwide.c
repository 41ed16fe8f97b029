/*
 * The binary32 twins of the binary64-only projective bounds:
 * cbx_project_spheref, cbx_project_box_nearf, cbx_project_sphere_nearf,
 * cbx_project_ellipsoidf.
 *
 * Each checks its float inputs (NaN -> CBX_EINVAL, an empty box ->
 * CBX_EMPTY, an infinite value -> CBX_ERANGE, as the binary64 function
 * would), widens them to double (exact: every float is a double), calls the
 * binary64 function (src/f64/cbx_psph.c, cbx_pnear.c, cbx_pball.c,
 * cbx_pell.c) and
 * rounds each end of its result outward to float (pw_down, pw_up: at most
 * 2^-22 |end| + 2^-147 further out).  The binary64 contracts carry over to
 * the float ends by the lemmas of specs/cbx_pwide.h: containment because
 * the interval only grows, tightness with twice the slack (2^-19 (1 + |end|)).
 * Proven in job PW (proofs/pwide.c), on the binary64 functions' contracts
 * (proven in jobs PS64, PN64, PB64).  Binary32 only by its interface: it
 * computes in binary64.
 */
#include "certbox.h"
#include "cbx_prec.h"  /* binary64: the rounding primitives' instance */
#include "cbx_round.h"

#define PW_FMAX 0x1.fffffep127F /* the largest finite float */
#define PW_EMAX 0x1p100         /* the largest end rounded to float */

#if defined(__FRAMAC__)
/* +-inf in float: the trusted fact of src/core/cbx_round.h (HUGE_VALF is
 * +inf, C99 7.12p3 with Annex F), under the same names. */
/*@ assigns \result \from \nothing;
    ensures \is_plus_infinity(\result); */
float cbx_pinf_f(void);
/*@ assigns \result \from \nothing;
    ensures \is_minus_infinity(\result); */
float cbx_ninf_f(void);
#else
#if defined(__GNUC__)
static inline float cbx_pinf_f(void) { return __builtin_huge_valf(); }
#else
#include <math.h>
static inline float cbx_pinf_f(void) { return HUGE_VALF; }
#endif
static inline float cbx_ninf_f(void) { return -cbx_pinf_f(); }
#endif

/* ---- input checks ----------------------------------------------------- */
/*@ assigns \nothing;
    ensures \result != 0 <==> \is_NaN(x);
*/
static int pw_nan(float x) { return x != x; }

/*@ assigns \nothing;
    ensures \result != 0 <==> \is_finite(x);
*/
static int pw_fin(float x) { return (x >= -PW_FMAX) && (x <= PW_FMAX); }

/*@ requires \valid_read(p);
    assigns \nothing;
    ensures \result != 0 <==> proj_nan_f(p);
*/
static int pw_proj_nan(const cbx_projf *p)
{
    return pw_nan(p->m[0][0]) | pw_nan(p->m[0][1]) | pw_nan(p->m[0][2]) | pw_nan(p->m[0][3])
         | pw_nan(p->m[1][0]) | pw_nan(p->m[1][1]) | pw_nan(p->m[1][2]) | pw_nan(p->m[1][3])
         | pw_nan(p->m[2][0]) | pw_nan(p->m[2][1]) | pw_nan(p->m[2][2]) | pw_nan(p->m[2][3])
         | pw_nan(p->m[3][0]) | pw_nan(p->m[3][1]) | pw_nan(p->m[3][2]) | pw_nan(p->m[3][3]);
}

/* The rows in the binary64 functions' domain (ps_row: linear entries at
 * most 2^60, translations at most 2^120), checked on the float values. */
/*@ assigns \nothing;
    ensures \result != 0 <==> (\is_finite(m0) && \is_finite(m1) && \is_finite(m2) && \is_finite(t)
                               && ps_row(m0, m1, m2, t));
*/
static int pw_row_ok(float m0, float m1, float m2, float t)
{
    return (m0 >= -0x1p60F) && (m0 <= 0x1p60F) && (m1 >= -0x1p60F) && (m1 <= 0x1p60F)
        && (m2 >= -0x1p60F) && (m2 <= 0x1p60F) && (t >= -0x1p120F) && (t <= 0x1p120F);
}

/*@ requires \valid_read(p);
    assigns \nothing;
    ensures \result != 0 <==> (pwf_fin(p) && pwf_rows(p));
*/
static int pw_proj_ok(const cbx_projf *p)
{
    return pw_row_ok(p->m[0][0], p->m[0][1], p->m[0][2], p->m[0][3])
        && pw_row_ok(p->m[1][0], p->m[1][1], p->m[1][2], p->m[1][3])
        && pw_row_ok(p->m[2][0], p->m[2][1], p->m[2][2], p->m[2][3])
        && pw_row_ok(p->m[3][0], p->m[3][1], p->m[3][2], p->m[3][3]);
}

/* No real point in [l, h] (no NaN): h < l, l = +inf or h = -inf. */
/*@ requires !\is_NaN(l) && !\is_NaN(h);
    assigns \nothing;
    ensures \result != 0 <==> no_point_f(l, h);
*/
static int pw_nopt(float l, float h) { return (h < l) || (l > PW_FMAX) || (h < -PW_FMAX); }

/* Each twin's inputs, checked in one call each: any NaN (the predicate
 * of its nan_input behavior), then every input finite with the map's rows
 * in range (psf_fin, ...).  Apart from the public functions so that WP's
 * simplifier meets the sixteen tests once, in one goal, and not again in
 * every postcondition of the caller (2026-11-30: cbx_project_ellipsoidf's
 * postconditions took 85 s of simplification with the tests inline). */
/*@ requires \valid_read(p) && \valid_read(c + (0 .. 2));
    assigns \nothing;
    ensures \result != 0 <==> psf_nan(p, c, r);
*/
static int ps_in_nan(const cbx_projf *p, const float c[3], float r)
{
    return pw_proj_nan(p) | pw_nan(c[0]) | pw_nan(c[1]) | pw_nan(c[2]) | pw_nan(r);
}

/*@ requires \valid_read(p) && \valid_read(c + (0 .. 2));
    assigns \nothing;
    ensures \result != 0 <==> psf_fin(p, c, r);
*/
static int ps_in_fin(const cbx_projf *p, const float c[3], float r)
{
    return pw_proj_ok(p) && pw_fin(c[0]) && pw_fin(c[1]) && pw_fin(c[2]) && pw_fin(r);
}

/*@ requires \valid_read(p) && \valid_read(b);
    assigns \nothing;
    ensures \result != 0 <==> pnf_nan(p, b, wn);
*/
static int pn_in_nan(const cbx_projf *p, const cbx_boxf *b, float wn)
{
    return pw_proj_nan(p) | pw_nan(b->lo[0]) | pw_nan(b->hi[0]) | pw_nan(b->lo[1]) | pw_nan(b->hi[1])
         | pw_nan(b->lo[2]) | pw_nan(b->hi[2]) | pw_nan(wn);
}

/*@ requires \valid_read(p) && \valid_read(b);
    assigns \nothing;
    ensures \result != 0 <==> pnf_fin(p, b, wn);
*/
static int pn_in_fin(const cbx_projf *p, const cbx_boxf *b, float wn)
{
    return pw_proj_ok(p) && pw_fin(b->lo[0]) && pw_fin(b->hi[0]) && pw_fin(b->lo[1]) && pw_fin(b->hi[1])
        && pw_fin(b->lo[2]) && pw_fin(b->hi[2]) && pw_fin(wn);
}

/*@ requires \valid_read(p) && \valid_read(c + (0 .. 2))
             && \valid_read(s + (0 .. 2)) && \valid_read(r + (0 .. 2));
    assigns \nothing;
    ensures \result != 0 <==> pef_nan(p, c, s, r);
*/
static int pe_in_nan(const cbx_projf *p, const float c[3], const float s[3], const float r[3][3])
{
    return pw_proj_nan(p) | pw_nan(c[0]) | pw_nan(c[1]) | pw_nan(c[2])
         | pw_nan(s[0]) | pw_nan(s[1]) | pw_nan(s[2])
         | pw_nan(r[0][0]) | pw_nan(r[0][1]) | pw_nan(r[0][2]) | pw_nan(r[1][0]) | pw_nan(r[1][1])
         | pw_nan(r[1][2]) | pw_nan(r[2][0]) | pw_nan(r[2][1]) | pw_nan(r[2][2]);
}

/*@ requires \valid_read(p) && \valid_read(c + (0 .. 2))
             && \valid_read(s + (0 .. 2)) && \valid_read(r + (0 .. 2));
    assigns \nothing;
    ensures \result != 0 <==> pef_fin(p, c, s, r);
*/
static int pe_in_fin(const cbx_projf *p, const float c[3], const float s[3], const float r[3][3])
{
    return pw_proj_ok(p) && pw_fin(c[0]) && pw_fin(c[1]) && pw_fin(c[2])
        && pw_fin(s[0]) && pw_fin(s[1]) && pw_fin(s[2])
        && pw_fin(r[0][0]) && pw_fin(r[0][1]) && pw_fin(r[0][2]) && pw_fin(r[1][0])
        && pw_fin(r[1][1]) && pw_fin(r[1][2]) && pw_fin(r[2][0]) && pw_fin(r[2][1])
        && pw_fin(r[2][2]);
}

/* ---- widening (exact) ------------------------------------------------- */
/* A float as a double: the same value (every float is a double). */
/*@ requires fin: \is_finite(x);
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures val: \result == x;
*/
static double pw_w(float x) { return x; }

/*@ requires \valid_read(p) && \valid(d);
    requires fin: pwf_fin(p);
    assigns *d;
    ensures pw_wide(d, p);
*/
static void pw_widen(const cbx_projf *p, cbx_proj *d)
{
    d->m[0][0] = p->m[0][0]; d->m[0][1] = p->m[0][1]; d->m[0][2] = p->m[0][2]; d->m[0][3] = p->m[0][3];
    d->m[1][0] = p->m[1][0]; d->m[1][1] = p->m[1][1]; d->m[1][2] = p->m[1][2]; d->m[1][3] = p->m[1][3];
    d->m[2][0] = p->m[2][0]; d->m[2][1] = p->m[2][1]; d->m[2][2] = p->m[2][2]; d->m[2][3] = p->m[2][3];
    d->m[3][0] = p->m[3][0]; d->m[3][1] = p->m[3][1]; d->m[3][2] = p->m[3][2]; d->m[3][3] = p->m[3][3];
}

/*@ requires \valid_read(in) && \valid(d) && \separated(in, d);
    requires fin: \is_finite(in->lo[0]) && \is_finite(in->hi[0]) && \is_finite(in->lo[1])
      && \is_finite(in->hi[1]) && \is_finite(in->lo[2]) && \is_finite(in->hi[2]);
    requires ne: !is_empty_f(in);
    assigns *d;
    ensures pw_wbox(d, in) && !is_empty(d) && !box_nan(d);
*/
static void pw_widen_box(const cbx_boxf *in, cbx_box *d)
{
    d->lo[0] = pw_w(in->lo[0]); d->hi[0] = pw_w(in->hi[0]);
    d->lo[1] = pw_w(in->lo[1]); d->hi[1] = pw_w(in->hi[1]);
    d->lo[2] = pw_w(in->lo[2]); d->hi[2] = pw_w(in->hi[2]);
}

/* ---- rounding outward to float ---------------------------------------- */
/* A double rounded to the nearest float: the one conversion of the unit,
 * with its error bound (2^-24 relative, 2^-150 absolute below 2^-126). */
/*@ requires fin: \is_finite(y) && -0x1p101 <= y <= 0x1p101;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures err: \abs(\result - y) <= 0x1p-24 * \abs(y) + 0x1p-150;
*/
static float pw_f32(double y) { return (float)y; }

/* x - (2^-23 |x| + 2^-149) in binary64 (two roundings of 2^-53), then
 * rounded to the nearest float: never above x, at most 2^-22 |x| + 2^-147
 * below it.  The constants are arguments (proofs/README.md, "Structure"). */
/*@ requires fin: \is_finite(x) && -PW_EMAX <= x <= PW_EMAX;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures dn: \result <= x && x - (0x1p-22 * \abs(x) + 0x1p-147) <= \result;
*/
static float pw_down(double x)
{
    double e = cbx_add_rn(cbx_mul_rn(cbx_abs(x), 0x1p-23), 0x1p-149);
    return pw_f32(cbx_sub_rn(x, e));
}

/*@ requires fin: \is_finite(x) && -PW_EMAX <= x <= PW_EMAX;
    assigns \nothing;
    ensures fin: \is_finite(\result);
    ensures up: x <= \result && \result <= x + (0x1p-22 * \abs(x) + 0x1p-147);
*/
static float pw_up(double x)
{
    double e = cbx_add_rn(cbx_mul_rn(cbx_abs(x), 0x1p-23), 0x1p-149);
    return pw_f32(cbx_add_rn(x, e));
}

/*@ requires \valid(o);
    assigns *o;
    ensures whole_space_f(o);
*/
static void pw_whole(cbx_boxf *o)
{
    o->lo[0] = cbx_ninf_f(); o->hi[0] = cbx_pinf_f();
    o->lo[1] = cbx_ninf_f(); o->hi[1] = cbx_pinf_f();
    o->lo[2] = cbx_ninf_f(); o->hi[2] = cbx_pinf_f();
}

/*@ requires \valid(o);
    assigns *o;
    ensures empty_out_f(o);
*/
static void pw_empty(cbx_boxf *o)
{
    o->lo[0] = cbx_pinf_f(); o->hi[0] = cbx_ninf_f();
    o->lo[1] = cbx_pinf_f(); o->hi[1] = cbx_ninf_f();
    o->lo[2] = cbx_pinf_f(); o->hi[2] = cbx_ninf_f();
}

/*@ assigns \nothing;
    ensures \result != 0 <==> (\is_finite(x) && -PW_EMAX <= x <= PW_EMAX);
*/
static int pw_small(double x) { return (x >= -PW_EMAX) && (x <= PW_EMAX); }

/* The binary64 result b with status st as a float box: CBX_OK rounded
 * outward (an end above 2^100: CBX_ERANGE instead), CBX_EMPTY empty, any
 * other status the whole space. */
/*@ requires \valid_read(b) && \valid(o) && \separated(b, o);
    requires fin: st == CBX_OK ==> \is_finite(b->lo[0]) && \is_finite(b->hi[0])
      && \is_finite(b->lo[1]) && \is_finite(b->hi[1]) && \is_finite(b->lo[2]) && \is_finite(b->hi[2]);
    assigns *o;
    ensures st: \result == st || (st == CBX_OK && \result == CBX_ERANGE);
    ensures ok0: \result == CBX_OK ==> \is_finite(o->lo[0]) && \is_finite(o->hi[0])
      && pw_near(o->lo[0], b->lo[0], o->hi[0], b->hi[0]);
    ensures ok1: \result == CBX_OK ==> \is_finite(o->lo[1]) && \is_finite(o->hi[1])
      && pw_near(o->lo[1], b->lo[1], o->hi[1], b->hi[1]);
    ensures ok2: \result == CBX_OK ==> \is_finite(o->lo[2]) && \is_finite(o->hi[2])
      && pw_near(o->lo[2], b->lo[2], o->hi[2], b->hi[2]);
    ensures empty: \result == CBX_EMPTY ==> empty_out_f(o);
    ensures whole: \result != CBX_OK && \result != CBX_EMPTY ==> whole_space_f(o);
*/
static cbx_status pw_narrow(cbx_status st, const cbx_box *b, cbx_boxf *o)
{
    if ((st == CBX_OK) && pw_small(b->lo[0]) && pw_small(b->hi[0]) && pw_small(b->lo[1])
        && pw_small(b->hi[1]) && pw_small(b->lo[2]) && pw_small(b->hi[2])) {
        o->lo[0] = pw_down(b->lo[0]); o->hi[0] = pw_up(b->hi[0]);
        o->lo[1] = pw_down(b->lo[1]); o->hi[1] = pw_up(b->hi[1]);
        o->lo[2] = pw_down(b->lo[2]); o->hi[2] = pw_up(b->hi[2]);
        return CBX_OK;
    }
    if (st == CBX_EMPTY) {
        pw_empty(o);
        return CBX_EMPTY;
    }
    pw_whole(o);
    return (st == CBX_OK) ? CBX_ERANGE : st;
}

/* ---- the twins -------------------------------------------------------- */
/* The arguments of output axis i's statements (specs/cbx_psph.h): row i,
 * row 3 (W), then the ball's (and the near plane's) on the float values. */
#define PW_PRE(x) \at(x, Pre)
#define PW_ROWS(i) PW_PRE(p->m[i][0]), PW_PRE(p->m[i][1]), PW_PRE(p->m[i][2]), PW_PRE(p->m[i][3]), \
                   PW_PRE(p->m[3][0]), PW_PRE(p->m[3][1]), PW_PRE(p->m[3][2]), PW_PRE(p->m[3][3])
#define PW_PS(i) PW_ROWS(i), PW_PRE(c[0]), PW_PRE(c[1]), PW_PRE(c[2]), r
#define PW_PB(i) PW_PS(i), wn
#define PW_ELL PW_PRE(center[0]), PW_PRE(center[1]), PW_PRE(center[2]), \
               PW_PRE(rot[0][0]), PW_PRE(rot[0][1]), PW_PRE(rot[0][2]), PW_PRE(rot[1][0]), PW_PRE(rot[1][1]), \
               PW_PRE(rot[1][2]), PW_PRE(rot[2][0]), PW_PRE(rot[2][1]), PW_PRE(rot[2][2]), \
               PW_PRE(radii[0]), PW_PRE(radii[1]), PW_PRE(radii[2])
#define PW_PE(i) PW_ROWS(i), PW_ELL
#define PW_PN(i) PW_ROWS(i), PW_PRE(in->lo[0]), PW_PRE(in->hi[0]), PW_PRE(in->lo[1]), PW_PRE(in->hi[1]), \
                 PW_PRE(in->lo[2]), PW_PRE(in->hi[2]), wn
/* The widened map's entries, equal to the float ones (stated at the call,
 * so that the binary64 contract's statements read the same reals). */
#define PW_EQ(i) d.m[i][0] == PW_PRE(p->m[i][0]) && d.m[i][1] == PW_PRE(p->m[i][1]) \
                 && d.m[i][2] == PW_PRE(p->m[i][2]) && d.m[i][3] == PW_PRE(p->m[i][3])
/* After the narrowing: output axis i's float ends next to the binary64
 * ones, which carry the binary64 statements. */
#define PW_NEAR(i) res == CBX_OK ==> \is_finite(out->lo[i]) && \is_finite(out->hi[i]) \
                   && pw_near(out->lo[i], b.lo[i], out->hi[i], b.hi[i])
#define PW_EQS PW_EQ(0) && PW_EQ(1) && PW_EQ(2) && PW_EQ(3)
#define PW_EQA1(i) a.d.m[i][0] == PW_PRE(p->m[i][0]) && a.d.m[i][1] == PW_PRE(p->m[i][1]) \
                   && a.d.m[i][2] == PW_PRE(p->m[i][2]) && a.d.m[i][3] == PW_PRE(p->m[i][3])
#define PW_EQA PW_EQA1(0) && PW_EQA1(1) && PW_EQA1(2) && PW_EQA1(3)
cbx_status cbx_project_spheref(const cbx_projf *p, const float c[3], float r, cbx_boxf *out)
{
    cbx_proj d;
    double cd[3];
    double rd;
    cbx_box b;
    cbx_status st;
    cbx_status res;
    if (ps_in_nan(p, c, r) != 0) {
        pw_whole(out);
        return CBX_EINVAL;
    }
    if (!ps_in_fin(p, c, r)) {
        pw_whole(out);
        return CBX_ERANGE;
    }
    pw_widen(p, &d);
    cd[0] = pw_w(c[0]); cd[1] = pw_w(c[1]); cd[2] = pw_w(c[2]);
    rd = pw_w(r);
    /*@ assert eq: PW_EQS && cd[0] == PW_PRE(c[0]) && cd[1] == PW_PRE(c[1]) && cd[2] == PW_PRE(c[2]) && rd == r; */
    st = cbx_project_sphere(&d, cd, rd, &b);
    /*@ assert w0: st == CBX_OK ==> ps_axis(b.lo[0], b.hi[0], PW_PS(0)) && ps_tight(b.lo[0], b.hi[0], PW_PS(0)); */
    /*@ assert w1: st == CBX_OK ==> ps_axis(b.lo[1], b.hi[1], PW_PS(1)) && ps_tight(b.lo[1], b.hi[1], PW_PS(1)); */
    /*@ assert w2: st == CBX_OK ==> ps_axis(b.lo[2], b.hi[2], PW_PS(2)) && ps_tight(b.lo[2], b.hi[2], PW_PS(2)); */
    res = pw_narrow(st, &b, out);
    /*@ assert n0: PW_NEAR(0) && ps_axis(b.lo[0], b.hi[0], PW_PS(0)) && ps_tight(b.lo[0], b.hi[0], PW_PS(0)); */
    /*@ assert n1: PW_NEAR(1) && ps_axis(b.lo[1], b.hi[1], PW_PS(1)) && ps_tight(b.lo[1], b.hi[1], PW_PS(1)); */
    /*@ assert n2: PW_NEAR(2) && ps_axis(b.lo[2], b.hi[2], PW_PS(2)) && ps_tight(b.lo[2], b.hi[2], PW_PS(2)); */
    return res;
}

cbx_status cbx_project_box_nearf(const cbx_projf *p, const cbx_boxf *in, float wn, cbx_boxf *out)
{
    cbx_proj d;
    cbx_box bd;
    cbx_box b;
    double wd;
    cbx_status st;
    cbx_status res;
    if (pn_in_nan(p, in, wn) != 0) {
        pw_whole(out);
        return CBX_EINVAL;
    }
    if ((pw_nopt(in->lo[0], in->hi[0]) | pw_nopt(in->lo[1], in->hi[1]) | pw_nopt(in->lo[2], in->hi[2])) != 0) {
        pw_empty(out);
        return CBX_EMPTY;
    }
    if (!pn_in_fin(p, in, wn)) {
        pw_whole(out);
        return CBX_ERANGE;
    }
    pw_widen(p, &d);
    pw_widen_box(in, &bd);
    wd = pw_w(wn);
    /*@ assert eq: PW_EQS && bd.lo[0] == PW_PRE(in->lo[0]) && bd.hi[0] == PW_PRE(in->hi[0])
          && bd.lo[1] == PW_PRE(in->lo[1]) && bd.hi[1] == PW_PRE(in->hi[1])
          && bd.lo[2] == PW_PRE(in->lo[2]) && bd.hi[2] == PW_PRE(in->hi[2]) && wd == wn
          && !is_empty(&bd) && !box_nan(&bd) && !proj_nan(&d) && !\is_NaN(wd); */
    st = cbx_project_box_near(&d, &bd, wd, &b);
    /*@ assert wdw: st != CBX_ERANGE ==> pn_wn(wn); */
    /*@ assert wdb: st != CBX_ERANGE ==> pn_bx(PW_PRE(in->lo[0]), PW_PRE(in->hi[0]), PW_PRE(in->lo[1]),
          PW_PRE(in->hi[1]), PW_PRE(in->lo[2]), PW_PRE(in->hi[2])); */
    /*@ assert w0: st == CBX_OK ==> pn_axis(b.lo[0], b.hi[0], PW_PN(0)) && pn_tight(b.lo[0], b.hi[0], PW_PN(0)); */
    /*@ assert w1: st == CBX_OK ==> pn_axis(b.lo[1], b.hi[1], PW_PN(1)) && pn_tight(b.lo[1], b.hi[1], PW_PN(1)); */
    /*@ assert w2: st == CBX_OK ==> pn_axis(b.lo[2], b.hi[2], PW_PN(2)) && pn_tight(b.lo[2], b.hi[2], PW_PN(2)); */
    /*@ assert wv: st == CBX_EMPTY ==> pn_void(wn, PW_PRE(p->m[3][0]), PW_PRE(p->m[3][1]), PW_PRE(p->m[3][2]),
          PW_PRE(p->m[3][3]), PW_PRE(in->lo[0]), PW_PRE(in->hi[0]), PW_PRE(in->lo[1]), PW_PRE(in->hi[1]),
          PW_PRE(in->lo[2]), PW_PRE(in->hi[2])); */
    /*@ assert wd: st != CBX_ERANGE ==> 0 < wn; */
    res = pw_narrow(st, &b, out);
    /*@ assert m0: PW_NEAR(0); */
    /*@ assert m1: PW_NEAR(1); */
    /*@ assert m2: PW_NEAR(2); */
    /*@ assert n0: res == CBX_OK ==> pn_axis(b.lo[0], b.hi[0], PW_PN(0)) && pn_tight(b.lo[0], b.hi[0], PW_PN(0)); */
    /*@ assert n1: res == CBX_OK ==> pn_axis(b.lo[1], b.hi[1], PW_PN(1)) && pn_tight(b.lo[1], b.hi[1], PW_PN(1)); */
    /*@ assert n2: res == CBX_OK ==> pn_axis(b.lo[2], b.hi[2], PW_PN(2)) && pn_tight(b.lo[2], b.hi[2], PW_PN(2)); */
    return res;
}

cbx_status cbx_project_sphere_nearf(const cbx_projf *p, const float c[3], float r, float wn, cbx_boxf *out)
{
    cbx_proj d;
    double cd[3];
    double rd;
    double wd;
    cbx_box b;
    cbx_status st;
    cbx_status res;
    if ((ps_in_nan(p, c, r) | pw_nan(wn)) != 0) {
        pw_whole(out);
        return CBX_EINVAL;
    }
    if (!(ps_in_fin(p, c, r) && pw_fin(wn))) {
        pw_whole(out);
        return CBX_ERANGE;
    }
    pw_widen(p, &d);
    cd[0] = pw_w(c[0]); cd[1] = pw_w(c[1]); cd[2] = pw_w(c[2]);
    rd = pw_w(r);
    wd = pw_w(wn);
    /*@ assert eq: PW_EQS && cd[0] == PW_PRE(c[0]) && cd[1] == PW_PRE(c[1]) && cd[2] == PW_PRE(c[2])
          && rd == r && wd == wn; */
    st = cbx_project_sphere_near(&d, cd, rd, wd, &b);
    /*@ assert wdw: st != CBX_ERANGE ==> pn_wn(wn); */
    /*@ assert wdc: st != CBX_ERANGE ==> ps_ctr(PW_PRE(c[0]), PW_PRE(c[1]), PW_PRE(c[2]), r); */
    /*@ assert w0: st == CBX_OK ==> pb_axis(b.lo[0], b.hi[0], PW_PB(0)) && pb_tight(b.lo[0], b.hi[0], PW_PB(0)); */
    /*@ assert w1: st == CBX_OK ==> pb_axis(b.lo[1], b.hi[1], PW_PB(1)) && pb_tight(b.lo[1], b.hi[1], PW_PB(1)); */
    /*@ assert w2: st == CBX_OK ==> pb_axis(b.lo[2], b.hi[2], PW_PB(2)) && pb_tight(b.lo[2], b.hi[2], PW_PB(2)); */
    /*@ assert wv: st == CBX_EMPTY ==> pb_void(wn, PW_PRE(p->m[3][0]), PW_PRE(p->m[3][1]), PW_PRE(p->m[3][2]),
          PW_PRE(p->m[3][3]), PW_PRE(c[0]), PW_PRE(c[1]), PW_PRE(c[2]), r); */
    /*@ assert wd: st != CBX_ERANGE ==> 0 < wn; */
    res = pw_narrow(st, &b, out);
    /*@ assert m0: PW_NEAR(0); */
    /*@ assert m1: PW_NEAR(1); */
    /*@ assert m2: PW_NEAR(2); */
    /*@ assert n0: res == CBX_OK ==> pb_axis(b.lo[0], b.hi[0], PW_PB(0)) && pb_tight(b.lo[0], b.hi[0], PW_PB(0)); */
    /*@ assert n1: res == CBX_OK ==> pb_axis(b.lo[1], b.hi[1], PW_PB(1)) && pb_tight(b.lo[1], b.hi[1], PW_PB(1)); */
    /*@ assert n2: res == CBX_OK ==> pb_axis(b.lo[2], b.hi[2], PW_PB(2)) && pb_tight(b.lo[2], b.hi[2], PW_PB(2)); */
    return res;
}

/* The ellipsoid's float arguments as doubles (exact), in one object. */
typedef struct { cbx_proj d; double c[3]; double s[3]; double r[3][3]; } pw_ell;
typedef struct { cbx_projf d; float c[3]; float s[3]; float r[3][3]; } pw_ellf;
/* Output axis i's promise (PW_PE: the arguments read at Pre, as \old). */
#define PE_OK(i) \result == CBX_OK ==> \is_finite(out->lo[i]) && \is_finite(out->hi[i]) \
    && pe_axis(out->lo[i], out->hi[i], PW_PE(i)) && pef_tight(out->lo[i], out->hi[i], PW_PE(i))
/* The binary32 ellipsoid once its arguments are known finite: the binary64
 * bound of the widened arguments, narrowed.  Apart from the checks of
 * cbx_project_ellipsoidf so that WP's simplifier meets the widened object
 * and the sixteen NaN tests in different goals (together, a minute of
 * simplification for each postcondition). */
/*@ requires valid: \valid_read(p) && \valid_read(center + (0 .. 2)) && \valid_read(radii + (0 .. 2))
                    && \valid_read(rot + (0 .. 2)) && \valid(out);
    requires sep: \separated(out, p) && \separated(out, center + (0 .. 2))
                  && \separated(out, radii + (0 .. 2)) && \separated(out, rot + (0 .. 2));
    requires fin: pef_fin(p, center, radii, rot);
    assigns *out;
    ensures st: \result == CBX_OK || \result == CBX_ERANGE || \result == CBX_EBEHIND;
    ensures whole: \result != CBX_OK ==> whole_space_f(out);
    ensures dom: \result != CBX_ERANGE ==> \old(pef_dom(p, center, radii, rot));
    ensures behind: \old(pef_dom(p, center, radii, rot)) && !pe_front(PW_PRE(p->m[3][0]), PW_PRE(p->m[3][1]),
        PW_PRE(p->m[3][2]), PW_PRE(p->m[3][3]), PW_ELL) ==> \result == CBX_EBEHIND;
    ensures ok0: PE_OK(0);
    ensures ok1: PE_OK(1);
    ensures ok2: PE_OK(2);
*/
static cbx_status pw_ell_wide(const cbx_projf *p, const float center[3], const float radii[3],
                              const float rot[3][3], cbx_boxf *out)
{
    /* the float inputs first, read in one go into a local whose address
     * is never taken (no memory for the proof: each read's validity is
     * checked before any call); then widened into one object, every entry
     * stored (no call that havocs a part of it), so that WP's simplifier
     * settles each read through stores to the same object at other
     * constant offsets; const, so that its arrays pass to the binary64
     * function without a cast */
    const pw_ellf f = {
        {{{p->m[0][0], p->m[0][1], p->m[0][2], p->m[0][3]},
          {p->m[1][0], p->m[1][1], p->m[1][2], p->m[1][3]},
          {p->m[2][0], p->m[2][1], p->m[2][2], p->m[2][3]},
          {p->m[3][0], p->m[3][1], p->m[3][2], p->m[3][3]}}},
        {center[0], center[1], center[2]},
        {radii[0], radii[1], radii[2]},
        {{rot[0][0], rot[0][1], rot[0][2]}, {rot[1][0], rot[1][1], rot[1][2]}, {rot[2][0], rot[2][1], rot[2][2]}}};
    const pw_ell a = {
        {{{pw_w(f.d.m[0][0]), pw_w(f.d.m[0][1]), pw_w(f.d.m[0][2]), pw_w(f.d.m[0][3])},
          {pw_w(f.d.m[1][0]), pw_w(f.d.m[1][1]), pw_w(f.d.m[1][2]), pw_w(f.d.m[1][3])},
          {pw_w(f.d.m[2][0]), pw_w(f.d.m[2][1]), pw_w(f.d.m[2][2]), pw_w(f.d.m[2][3])},
          {pw_w(f.d.m[3][0]), pw_w(f.d.m[3][1]), pw_w(f.d.m[3][2]), pw_w(f.d.m[3][3])}}},
        {pw_w(f.c[0]), pw_w(f.c[1]), pw_w(f.c[2])},
        {pw_w(f.s[0]), pw_w(f.s[1]), pw_w(f.s[2])},
        {{pw_w(f.r[0][0]), pw_w(f.r[0][1]), pw_w(f.r[0][2])},
         {pw_w(f.r[1][0]), pw_w(f.r[1][1]), pw_w(f.r[1][2])},
         {pw_w(f.r[2][0]), pw_w(f.r[2][1]), pw_w(f.r[2][2])}}};
    cbx_box b;
    cbx_status st;
    cbx_status res;
    /*@ assert eq: PW_EQA && a.c[0] == PW_PRE(center[0]) && a.c[1] == PW_PRE(center[1])
          && a.c[2] == PW_PRE(center[2]) && a.s[0] == PW_PRE(radii[0]) && a.s[1] == PW_PRE(radii[1])
          && a.s[2] == PW_PRE(radii[2]); */
    /*@ assert eqr: a.r[0][0] == PW_PRE(rot[0][0]) && a.r[0][1] == PW_PRE(rot[0][1]) && a.r[0][2] == PW_PRE(rot[0][2])
          && a.r[1][0] == PW_PRE(rot[1][0]) && a.r[1][1] == PW_PRE(rot[1][1]) && a.r[1][2] == PW_PRE(rot[1][2])
          && a.r[2][0] == PW_PRE(rot[2][0]) && a.r[2][1] == PW_PRE(rot[2][1]) && a.r[2][2] == PW_PRE(rot[2][2]); */
    /*@ assert b1: \at(pef_dom(p, center, radii, rot), Pre) <==> pe_dom(&a.d, &a.c[0], &a.s[0], &a.r[0]); */
    /*@ assert nn: !pe_nan(&a.d, &a.c[0], &a.s[0], &a.r[0]); */
    st = cbx_project_ellipsoid(&a.d, a.c, a.s, a.r, &b);
    /*@ assert s0: st == CBX_OK || st == CBX_ERANGE || st == CBX_EBEHIND; */
    /*@ assert w0: st == CBX_OK ==> pe_axis(b.lo[0], b.hi[0], PW_PE(0)) && pe_tight(b.lo[0], b.hi[0], PW_PE(0)); */
    /*@ assert w1: st == CBX_OK ==> pe_axis(b.lo[1], b.hi[1], PW_PE(1)) && pe_tight(b.lo[1], b.hi[1], PW_PE(1)); */
    /*@ assert w2: st == CBX_OK ==> pe_axis(b.lo[2], b.hi[2], PW_PE(2)) && pe_tight(b.lo[2], b.hi[2], PW_PE(2)); */
    res = pw_narrow(st, &b, out);
    /*@ assert n0: PW_NEAR(0) && pe_axis(b.lo[0], b.hi[0], PW_PE(0)) && pe_tight(b.lo[0], b.hi[0], PW_PE(0)); */
    /*@ assert n1: PW_NEAR(1) && pe_axis(b.lo[1], b.hi[1], PW_PE(1)) && pe_tight(b.lo[1], b.hi[1], PW_PE(1)); */
    /*@ assert n2: PW_NEAR(2) && pe_axis(b.lo[2], b.hi[2], PW_PE(2)) && pe_tight(b.lo[2], b.hi[2], PW_PE(2)); */
    return res;
}

cbx_status cbx_project_ellipsoidf(const cbx_projf *p, const float center[3], const float radii[3],
                                  const float rot[3][3], cbx_boxf *out)
{
    if (pe_in_nan(p, center, radii, rot) != 0) {
        pw_whole(out);
        return CBX_EINVAL;
    }
    if (!pe_in_fin(p, center, radii, rot)) {
        pw_whole(out);
        return CBX_ERANGE;
    }
    return pw_ell_wide(p, center, radii, rot, out);
}
