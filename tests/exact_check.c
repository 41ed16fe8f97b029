/* exact_check: checking one call of cbx_transform_box against the exact
 * oracle: the status, the special outputs (EINVAL, EMPTY), rule A's full
 * rows (containment, proven tightness, mpq corners), rule B's ends (vertex
 * value, unbounded and lost ends, extended mpq corners) and rule C;
 * xu_check_result and xu_run_case, and the names of the checks.
 * Part of the oracle declared in exact_util.h (see there for the map). */
#include "exact_util.h"
#include "exact_internal.h"

#include <math.h>
#include <string.h>

const char *const xu_flag_name[XU_NFLAGS] = {
    "status", "out-set", "special-out", "oob-axes", "finite",
    "containment", "proven-tight", "corners", "cross-LH",
    "inf-end", "end-finite", "end-contain", "end-proven", "end-corners",
    "end-cross", "inputs"
};

/* ---------------------------------------------------------------------- */
/* Checking one call                                                      */
/* ---------------------------------------------------------------------- */

static void xu_fail(xu_verdict *v, int flag, const char *why)
{
    v->flag[flag]++;
    if (!v->failed) {
        size_t n = sizeof v->why - 1;
        strncpy(v->why, why, n);
        v->why[n] = '\0';
    }
    v->failed = 1;
}

/* The whole output must be lo = L0, hi = H0 on every axis (EINVAL/EMPTY). */
static void xu_check_special(xu_verdict *v, const cbx_box *out, int whole)
{
    int i;
    v->applied[XU_F_SPECIAL]++;
    for (i = 0; i < 3; i++) {
        int ok = whole ? xu_is_ninf(out->lo[i]) && xu_is_pinf(out->hi[i])
                       : xu_is_pinf(out->lo[i]) && xu_is_ninf(out->hi[i]);
        if (!ok) {
            xu_fail(v, XU_F_SPECIAL, whole ? "EINVAL: out is not [-inf,+inf]^3"
                                           : "EMPTY: out is not lo=+inf hi=-inf");
            return;
        }
    }
}

/* One in-domain axis: finite, contains [L, H] exactly, within the proven
 * tightness, and (optionally) the mpq corner checks. */
static void xu_check_axis(xu_exact *x, xu_verdict *v, const cbx_affine *a,
                          const cbx_box *in, const cbx_box *out, int i,
                          int corners)
{
    double lo = out->lo[i], hi = out->hi[i];
    char why[160];
    int glo, ghi;

    v->applied[XU_F_FINITE]++;
    if (!isfinite(lo) || !isfinite(hi) || lo > hi) {
        snprintf(why, sizeof why, "axis %d in domain but out = [%.17g, %.17g]", i, lo, hi);
        xu_fail(v, XU_F_FINITE, why);
        return;
    }
    xu_row_bounds(x, a, in, i);
    xu_unit_den(x);

    v->applied[XU_F_CONTAIN]++;
    v->applied[XU_F_PROVEN]++;
    xu_gap_lo(x, lo);
    glo = mpz_sgn(x->d);
    v->ax[i].ex_lo = xu_ratio53(x->d, x->e);
    if (!xu_gap_within_proven(x)) {
        snprintf(why, sizeof why, "axis %d: lo beyond 12uS+2^-%d (excess %.3g)", i, xu_fmt->tight_e,
                v->ax[i].ex_lo);
        xu_fail(v, XU_F_PROVEN, why);
    }
    xu_unit_den(x);
    xu_gap_hi(x, hi);
    ghi = mpz_sgn(x->d);
    v->ax[i].ex_hi = xu_ratio53(x->d, x->e);
    if (!xu_gap_within_proven(x)) {
        snprintf(why, sizeof why, "axis %d: hi beyond 12uS+2^-%d (excess %.3g)", i, xu_fmt->tight_e,
                v->ax[i].ex_hi);
        xu_fail(v, XU_F_PROVEN, why);
    }
    if (glo < 0 || ghi < 0) {
        snprintf(why, sizeof why, "axis %d: not contained (excess lo %.3g, hi %.3g)", i,
                v->ax[i].ex_lo, v->ax[i].ex_hi);
        xu_fail(v, XU_F_CONTAIN, why);
    }
    v->ax[i].checked = 1;
    v->ax[i].exact = glo == 0 && ghi == 0;
    /* u S < 2^XU_TINY eta  <=>  S 2^XU_SHIFT < 2^(XU_SHIFT - emin + p + XU_TINY) */
    v->ax[i].tiny = mpz_sizeinbase(x->S, 2) <= (size_t)(XU_SHIFT - xu_fmt->emin + xu_fmt->p + XU_TINY);

    if (corners) {
        v->applied[XU_F_CROSS]++;
        if (!xu_bounds_match_corners(x, a, in, i)) {
            snprintf(why, sizeof why, "axis %d: mpq corner min/max != fixed-point L/H", i);
            xu_fail(v, XU_F_CROSS, why);
        }
        v->applied[XU_F_CORNER]++;
        if (xu_corner_failures(x, a, in, i, lo, hi)) {
            snprintf(why, sizeof why, "axis %d: a corner image is outside out (mpq)", i);
            xu_fail(v, XU_F_CORNER, why);
        }
    }
}

/* Rule B, the mpq path (independent of xu_vertex): the 8 corners of the
 * box in extended arithmetic.  Term j of corner c is 0 for m_j == 0 (0 * inf
 * = 0), +-inf for an infinite coordinate (the sign of m_j times that of the
 * coordinate), else the exact m_j c_j.  A corner with both a +inf and a
 * -inf term has no value (skipped; such a row is unbounded on both sides,
 * which other corners show).  The least (greatest) corner value is the
 * exact inf (sup) of the image over the real points of the box.
 * Sets x->qmin / x->qmax when finite; *min_inf = 1 when the inf is -inf,
 * *max_inf = 1 when the sup is +inf. */
static void xu_ext_corners(xu_exact *x, const cbx_affine *a, const cbx_box *in,
                           int i, int *min_inf, int *max_inf)
{
    unsigned c;
    int j, have_min = 0, have_max = 0;
    *min_inf = *max_inf = 0;
    for (c = 0; c < 8; c++) {
        int neg = 0, pos = 0;
        mpq_set_d(x->q, a->m[i][3]);
        for (j = 0; j < 3; j++) {
            double m = a->m[i][j], cj = (c >> j) & 1u ? in->hi[j] : in->lo[j];
            if (m == 0) continue;
            if (isinf(cj)) {
                if ((m > 0) == (cj > 0)) pos = 1;
                else neg = 1;
                continue;
            }
            mpq_set_d(x->qa, m);
            mpq_set_d(x->qb, cj);
            mpq_mul(x->qa, x->qa, x->qb);
            mpq_add(x->q, x->q, x->qa);
        }
        if (neg && pos) continue;
        if (neg) *min_inf = 1;
        else if (pos) *max_inf = 1;
        else {
            if (!have_min || mpq_cmp(x->q, x->qmin) < 0) mpq_set(x->qmin, x->q);
            if (!have_max || mpq_cmp(x->q, x->qmax) > 0) mpq_set(x->qmax, x->q);
            have_min = have_max = 1;
        }
    }
    /* every column has an end whose term is not +inf (not -inf): the
     * corner of those ends has a value, so a finite inf exists whenever
     * *min_inf is 0 (have_min); the same for the sup */
    if (!have_min) *min_inf = 1;
    if (!have_max) *max_inf = 1;
}

static const char *const xu_end_word[XU_NEND] = {
    "full-row", "vertex", "unbounded", "lost", "whole-line"
};

/* Rule B, one end (upper = 0: lower end). */
static void xu_check_end(xu_exact *x, xu_verdict *v, const cbx_affine *a,
                         const cbx_box *in, const cbx_box *out, int i, int upper,
                         int corners)
{
    double e = upper ? out->hi[i] : out->lo[i];
    const char *nm = upper ? "hi" : "lo";
    int k = v->ax[i].end_kind[upper];
    char why[200];

    if (k == XU_END_UNB || k == XU_END_LOST) {
        v->applied[XU_F_INFEND]++;
        if (!(upper ? xu_is_pinf(e) : xu_is_ninf(e))) {
            snprintf(why, sizeof why, "axis %d: %s end must be %s (%s) but is %.17g", i, nm,
                     upper ? "+inf" : "-inf", xu_end_word[k], e);
            xu_fail(v, XU_F_INFEND, why);
        }
    } else {
        int g;
        v->applied[XU_F_ENDFIN]++;
        if (!isfinite(e)) {
            snprintf(why, sizeof why, "axis %d: %s end must be finite (vertex in the domain) "
                     "but is %.17g", i, nm, e);
            xu_fail(v, XU_F_ENDFIN, why);
            return;
        }
        xu_vertex_bounds(x, a, in, i, upper);
        xu_unit_den(x);
        v->applied[XU_F_ENDCONT]++;
        v->applied[XU_F_ENDPROVEN]++;
        if (upper) xu_gap_hi(x, e);
        else xu_gap_lo(x, e);
        g = mpz_sgn(x->d);
        v->ax[i].ex_end[upper] = xu_ratio53(x->d, x->e);
        v->ax[i].end_checked[upper] = 1;
        v->ax[i].end_tiny[upper] = mpz_sizeinbase(x->S, 2) <= (size_t)(XU_SHIFT - xu_fmt->emin + xu_fmt->p + XU_TINY);
        if (g < 0) {
            snprintf(why, sizeof why, "axis %d: %s end %s the exact vertex value (excess %.3g)",
                     i, nm, upper ? "below" : "above", v->ax[i].ex_end[upper]);
            xu_fail(v, XU_F_ENDCONT, why);
        }
        if (!xu_gap_within_proven(x)) {
            snprintf(why, sizeof why, "axis %d: %s end beyond 12uS_v+2^-%d (excess %.3g)", i,
                     nm, xu_fmt->tight_e, v->ax[i].ex_end[upper]);
            xu_fail(v, XU_F_ENDPROVEN, why);
        }
    }

    if (corners) {
        int min_inf, max_inf, unb;
        xu_ext_corners(x, a, in, i, &min_inf, &max_inf);
        unb = upper ? max_inf : min_inf;
        v->applied[XU_F_ENDCROSS]++;
        if (unb != (k == XU_END_UNB)) {
            snprintf(why, sizeof why, "axis %d: mpq corners say the image is %s on the %s "
                     "side, the vertex rule says %s", i, unb ? "unbounded" : "bounded", nm,
                     xu_end_word[k]);
            xu_fail(v, XU_F_ENDCROSS, why);
        } else if (k == XU_END_VERTEX) {
            xu_vertex_bounds(x, a, in, i, upper);
            xu_scaled_to_q(x->qa, upper ? x->H : x->L);
            if (!mpq_equal(x->qa, upper ? x->qmax : x->qmin)) {
                snprintf(why, sizeof why, "axis %d: mpq corner %s != the fixed-point vertex "
                         "value", i, upper ? "sup" : "inf");
                xu_fail(v, XU_F_ENDCROSS, why);
            }
        }
        if (isfinite(e)) {
            v->applied[XU_F_ENDCORNER]++;
            mpq_set_d(x->qb, e);
            if (unb || (upper ? mpq_cmp(x->qb, x->qmax) < 0 : mpq_cmp(x->qb, x->qmin) > 0)) {
                snprintf(why, sizeof why, "axis %d: an extended corner image is %s the finite "
                         "%s end (mpq)", i, upper ? "above" : "below", nm);
                xu_fail(v, XU_F_ENDCORNER, why);
            }
        }
    }
}

static void xu_check_box_result(xu_exact *x, xu_verdict *v,
                                const cbx_affine *a, const cbx_box *in,
                                const cbx_box *out, int corners)
{
    int i;
    char why[96];
    v->oob_mask = xu_oob_mask(a, in);
    v->loss_mask = xu_loss_mask(a, in);
    for (i = 0; i < 3; i++) {
        int klo = xu_end_kind(a, in, i, 0), khi = xu_end_kind(a, in, i, 1);
        v->ax[i].end_kind[0] = klo;
        v->ax[i].end_kind[1] = khi;
        if (klo == XU_END_WHOLE) {
            v->applied[XU_F_OOB]++;
            if (!xu_is_ninf(out->lo[i]) || !xu_is_pinf(out->hi[i])) {
                snprintf(why, sizeof why, "axis %d: infinite map entry but not [-inf,+inf]", i);
                xu_fail(v, XU_F_OOB, why);
            }
        } else if (klo == XU_END_FULL) {
            xu_check_axis(x, v, a, in, out, i, corners);
        } else {
            xu_check_end(x, v, a, in, out, i, 0, corners);
            xu_check_end(x, v, a, in, out, i, 1, corners);
        }
    }
}

int xu_check_result(xu_exact *x, const cbx_affine *a, const cbx_box *in,
                    const cbx_box *out, cbx_status got, int corners,
                    xu_verdict *v)
{
    int i;
    char why[96];

    memset(v, 0, sizeof *v);
    for (i = 0; i < 3; i++) v->ax[i].end_kind[0] = v->ax[i].end_kind[1] = -1;
    v->got = got;
    v->expected = xu_expected_status(a, in);

    v->applied[XU_F_STATUS]++;
    if (v->got != v->expected) {
        snprintf(why, sizeof why, "status %s (%d), expected %s", cbx_status_name(v->got),
                (int)v->got, cbx_status_name(v->expected));
        xu_fail(v, XU_F_STATUS, why);
    }
    v->applied[XU_F_UNSET]++;
    for (i = 0; i < 3; i++)
        if (xu_is_nan(out->lo[i]) || xu_is_nan(out->hi[i])) {
            xu_fail(v, XU_F_UNSET, "NaN left in out (field not written)");
            break;
        }

    if (v->expected == CBX_EINVAL) xu_check_special(v, out, 1);
    else if (v->expected == CBX_EMPTY) xu_check_special(v, out, 0);
    else xu_check_box_result(x, v, a, in, out, corners);
    return v->failed;
}

int xu_run_case(xu_exact *x, const cbx_affine *a, const cbx_box *in,
                cbx_box *out, int corners, xu_verdict *v)
{
    cbx_affine a0 = *a;
    cbx_box in0 = *in;
    cbx_status got;
    int i, changed;

    /* NaN pre-fill: any field the library forgets to write stays NaN */
    for (i = 0; i < 3; i++) out->lo[i] = out->hi[i] = NAN;

    got = cbx_transform_box(a, in, out);
    changed = memcmp(&a0, a, sizeof a0) != 0 || memcmp(&in0, in, sizeof in0) != 0;
    /* check against the inputs as given (a call that changed them is
     * reported below; the oracle must not read the changed ones) */
    xu_check_result(x, &a0, &in0, out, got, corners, v);
    v->applied[XU_F_INPUT]++;
    if (changed) xu_fail(v, XU_F_INPUT, "the call modified its inputs");
    return v->failed;
}
