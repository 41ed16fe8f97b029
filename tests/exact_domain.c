/* exact_domain: the exact oracle's formats (binary64, binary32: units,
 * domain exponents, magnitude classes) and its domain rules, decided
 * exactly: NaN, empty input, the magnitude classes, the kinds of the ends
 * of cbx_transform_box (rules A, B, C) and of the axes of
 * cbx_transform_cbox (A, D, W), and the expected statuses.  No GMP here.
 * Part of the oracle declared in exact_util.h (see there for the map). */
#include "exact_util.h"
#include "exact_internal.h"

#include <math.h>
#include <float.h>

/* Same order as dom_pair in specs/cbx_spec.h; 509 is in the spec's list
 * even though the comment in certbox.h only names 0, 64, ..., 960, 1018. */
const int xu_class_k[XU_NCLASS] = {
    509, 0, 64, 128, 192, 256, 320, 384, 448, 512,
    576, 640, 704, 768, 832, 896, 960, 1018
};

/* The two formats (include/cbx_prec_begin.h has the library's side). */
const xu_format xu_binary64 = {
    "binary64", 53, 1074, 1018, 1065, 1000, 1023, -1022, 200, 900,
    { 509, 0, 64, 128, 192, 256, 320, 384, 448, 512,
      576, 640, 704, 768, 832, 896, 960, 1018 }
};
const xu_format xu_binary32 = {
    "binary32", 24, 149, 122, 140, 75, 127, -126, 24, 100,
    { 61, 0, 8, 16, 24, 32, 40, 48, 56, 64,
      72, 80, 88, 96, 104, 112, 120, 122 }
};
const xu_format *xu_fmt = &xu_binary64;
void xu_set_format(const xu_format *f) { xu_fmt = f; }

/* The next value of the format above x (x a value of the format). */
double xu_next_up(double x)
{
    if (xu_fmt->p == 24) return (double)nextafterf((float)x, HUGE_VALF);
    return nextafter(x, HUGE_VAL);
}

/* d rounded to the format (to nearest).  Through a volatile float: GCC
 * 12.2 at -O2 drops the rounding of (double)(float)(a * b) in loops its
 * SLP vectorizer packs (observed here; tests/test_ieee.c keeps the
 * reproducer), which would hand the library values that are not floats. */
double xu_round_fmt(double d)
{
    volatile float f;
    if (xu_fmt->p != 24) return d;
    f = (float)d;
    return f;
}

/* The largest finite value of the format. */
double xu_fmt_max(void) { return xu_fmt->p == 24 ? (double)FLT_MAX : DBL_MAX; }

const char xu_end_char[XU_NEND + 1] = "AFULW";

/* ---------------------------------------------------------------------- */
/* Domain and expected status                                             */
/* ---------------------------------------------------------------------- */

/* x != x is the portable NaN test; kept in one place so -ffast-math-like
 * surprises would show up in one spot. */
int xu_is_nan(double x) { return x != x; }

int xu_has_nan(const cbx_affine *a, const cbx_box *in)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++)
            if (xu_is_nan(a->m[i][j])) return 1;
    for (j = 0; j < 3; j++)
        if (xu_is_nan(in->lo[j]) || xu_is_nan(in->hi[j])) return 1;
    return 0;
}

/* isinf() and a sign test: exact, and independent of the library's
 * comparisons with DBL_MAX. */
int xu_is_pinf(double d) { return d > 0 && isinf(d); }
int xu_is_ninf(double d) { return d < 0 && isinf(d); }

int xu_is_empty(const cbx_box *in)
{
    int j;
    for (j = 0; j < 3; j++)
        if (in->lo[j] > in->hi[j] || xu_is_pinf(in->lo[j]) || xu_is_ninf(in->hi[j]))
            return 1;
    return 0;
}

int xu_severity(cbx_status s)
{
    return s == CBX_EINVAL ? 3 : s == CBX_ERANGE ? 2 : s == CBX_EMPTY ? 1 : 0;
}

/* ldexp(1, k) for 0 <= k <= 1018 is an exact power of two, and comparing
 * fabs(v) (exact) with it is an exact comparison; an infinity is never
 * <= a finite bound, so non-finite inputs fall out by themselves.  The
 * classes' bounds 2^k and 2^(rt - k) of the current format are computed
 * once per format (the oracles ask for them millions of times). */
int xu_pair_in_domain(double m, double c)
{
    static const xu_format *fmt;
    static double bm[XU_NCLASS], bc[XU_NCLASS];
    int n;
    double am = fabs(m), ac = fabs(c);
    if (fmt != xu_fmt) {
        for (n = 0; n < XU_NCLASS; n++) {
            bm[n] = ldexp(1.0, xu_fmt->class_k[n]);
            bc[n] = ldexp(1.0, xu_fmt->rt - xu_fmt->class_k[n]);
        }
        fmt = xu_fmt;
    }
    for (n = 0; n < XU_NCLASS; n++)
        if (am <= bm[n] && ac <= bc[n]) return 1;
    return 0;
}

int xu_row_in_domain(const cbx_affine *a, const cbx_box *in, int i)
{
    int j;
    for (j = 0; j < 3; j++) {
        if (!xu_pair_in_domain(a->m[i][j], in->lo[j])) return 0;
        if (!xu_pair_in_domain(a->m[i][j], in->hi[j])) return 0;
    }
    return fabs(a->m[i][3]) <= ldexp(1.0, xu_fmt->rt);
}

int xu_oob_mask(const cbx_affine *a, const cbx_box *in)
{
    int i, mask = 0;
    for (i = 0; i < 3; i++)
        if (!xu_row_in_domain(a, in, i)) mask |= 1 << i;
    return mask;
}

int xu_map_row_finite(const cbx_affine *a, int i)
{
    return isfinite(a->m[i][0]) && isfinite(a->m[i][1]) && isfinite(a->m[i][2])
           && isfinite(a->m[i][3]);
}

/* The rule-B vertex: for the lower end the box end where m_j x is least,
 * chosen by the sign of m_j (exact comparisons with 0; -0.0 == 0); m_j == 0
 * contributes 0 whatever the box (0 * inf = 0 over the reals). */
int xu_vertex(const cbx_affine *a, const cbx_box *in, int i, int upper, double v[3])
{
    int j;
    for (j = 0; j < 3; j++) {
        double m = a->m[i][j], c;
        if (m == 0) {
            v[j] = 0.0;
            continue;
        }
        if ((m > 0) != (upper != 0)) c = in->lo[j]; /* m > 0 lower, m < 0 upper */
        else c = in->hi[j];
        if (isinf(c)) return 0; /* -inf below / +inf above: no real point is
                                   outside it, so the image is unbounded */
        v[j] = c;
    }
    return 1;
}

int xu_end_kind(const cbx_affine *a, const cbx_box *in, int i, int upper)
{
    double v[3];
    int j;
    if (xu_row_in_domain(a, in, i)) return XU_END_FULL;
    if (!xu_map_row_finite(a, i)) return XU_END_WHOLE;
    if (!xu_vertex(a, in, i, upper, v)) return XU_END_UNB;
    for (j = 0; j < 3; j++)
        if (!xu_pair_in_domain(a->m[i][j], v[j])) return XU_END_LOST;
    if (!(fabs(a->m[i][3]) <= ldexp(1.0, xu_fmt->rt))) return XU_END_LOST;
    return XU_END_VERTEX;
}

static int xu_kind_is_loss(int k) { return k == XU_END_LOST || k == XU_END_WHOLE; }

int xu_row_loss(const cbx_affine *a, const cbx_box *in, int i)
{
    return xu_kind_is_loss(xu_end_kind(a, in, i, 0))
           || xu_kind_is_loss(xu_end_kind(a, in, i, 1));
}

int xu_loss_mask(const cbx_affine *a, const cbx_box *in)
{
    int i, mask = 0;
    for (i = 0; i < 3; i++)
        if (xu_row_loss(a, in, i)) mask |= 1 << i;
    return mask;
}

void xu_ends_str(const cbx_affine *a, const cbx_box *in, char s[9])
{
    int i, n = 0;
    for (i = 0; i < 3; i++) {
        if (i) s[n++] = ' ';
        s[n++] = xu_end_char[xu_end_kind(a, in, i, 0)];
        s[n++] = xu_end_char[xu_end_kind(a, in, i, 1)];
    }
    s[n] = '\0';
}

cbx_status xu_expected_status(const cbx_affine *a, const cbx_box *in)
{
    if (xu_has_nan(a, in)) return CBX_EINVAL;
    if (xu_is_empty(in)) return CBX_EMPTY;
    return xu_loss_mask(a, in) ? CBX_ERANGE : CBX_OK;
}

/* ---------------------------------------------------------------------- */
/* The centre/half-diagonal form (cbx_transform_cbox)                     */
/* ---------------------------------------------------------------------- */

int xu_cbox_has_nan(const cbx_affine *a, const cbx_cbox *in)
{
    int i, j;
    if (a)
        for (i = 0; i < 3; i++)
            for (j = 0; j < 4; j++)
                if (xu_is_nan(a->m[i][j])) return 1;
    for (j = 0; j < 3; j++)
        if (xu_is_nan(in->c[j]) || xu_is_nan(in->h[j])) return 1;
    return 0;
}

int xu_cbox_is_empty(const cbx_cbox *in)
{
    return in->h[0] < 0.0 || in->h[1] < 0.0 || in->h[2] < 0.0;
}

int xu_cbox_row_in_domain(const cbx_affine *a, const cbx_cbox *in, int i)
{
    int j;
    for (j = 0; j < 3; j++) {
        if (!xu_pair_in_domain(a->m[i][j], in->c[j])) return 0;
        if (!xu_pair_in_domain(a->m[i][j], in->h[j])) return 0;
    }
    return fabs(a->m[i][3]) <= ldexp(1.0, xu_fmt->rt);
}

const char xu_cax_char[XU_NCAX + 1] = "ADW";

void xu_cbox_dropped(const cbx_affine *a, const cbx_cbox *in, int i, cbx_cbox *d)
{
    int j;
    for (j = 0; j < 3; j++) {
        int z = a->m[i][j] == 0; /* exact; true for -0.0, false for NaN */
        d->c[j] = z ? 0.0 : in->c[j];
        d->h[j] = z ? 0.0 : in->h[j];
    }
}

int xu_cbox_axis_kind(const cbx_affine *a, const cbx_cbox *in, int i)
{
    cbx_cbox d;
    if (xu_cbox_row_in_domain(a, in, i)) return XU_CAX_FULL;
    /* xu_pair_in_domain is false for an infinite m or coordinate, and the
     * bound on t is false for an infinite t: no separate finiteness test */
    xu_cbox_dropped(a, in, i, &d);
    if (xu_cbox_row_in_domain(a, &d, i)) return XU_CAX_DROP;
    return XU_CAX_LOST;
}

int xu_cbox_loss_mask(const cbx_affine *a, const cbx_cbox *in)
{
    int i, mask = 0;
    for (i = 0; i < 3; i++)
        if (xu_cbox_axis_kind(a, in, i) == XU_CAX_LOST) mask |= 1 << i;
    return mask;
}

void xu_cbox_kinds_str(const cbx_affine *a, const cbx_cbox *in, char s[4])
{
    int i;
    for (i = 0; i < 3; i++) s[i] = xu_cax_char[xu_cbox_axis_kind(a, in, i)];
    s[3] = '\0';
}

cbx_status xu_cbox_expected_status(const cbx_affine *a, const cbx_cbox *in)
{
    if (xu_cbox_has_nan(a, in)) return CBX_EINVAL;
    if (xu_cbox_is_empty(in)) return CBX_EMPTY;
    return xu_cbox_loss_mask(a, in) ? CBX_ERANGE : CBX_OK;
}
