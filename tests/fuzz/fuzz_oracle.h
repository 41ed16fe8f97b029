/*
 * fuzz_oracle.h: the exact oracle of the certbox libFuzzer harnesses,
 * included by fuzz_common.h (after its decoding and printing helpers)
 * unless FZ_DECODE_ONLY is defined.
 *
 * Exact GMP arithmetic on the doubles as given.  Every double is
 * k * 2^-1074, so values times 2^1074 (FZ_SH1) and products of two values
 * times 2^2148 (FZ_SH2 = XU_SHIFT) are integers: all comparisons are exact.
 *
 *    Inputs with infinite entries.  fuzz_transform_box and
 *    fuzz_box_to_cbox assert the status and every end for them too (the
 *    half-space rules, see exact_util.h and those harnesses); for every
 *    harness, and independently of those rules: every field written,
 *    nothing NaN, and containment on every finite output end, decided
 *    exactly with this reading of the input:
 *      - a box bound is a bound of a real set: lo = -inf / hi = +inf means
 *        unbounded on that side; lo = +inf or hi = -inf (or lo > hi) is an
 *        empty set, whose image is empty (nothing to contain);
 *      - a cbox axis with h = +inf and a finite c is the whole line; a cbox
 *        axis with an infinite c has no real points (nothing to contain);
 *      - a coefficient (matrix entry, translation, centre, radius,
 *        rotation entry) of +-inf stands for an arbitrarily large real of
 *        that sign (0 * inf = 0: a zero factor is an exact real zero); an
 *        end must then be infinite when the exact image is unbounded on that
 *        side for every large value, and carries no obligation when the
 *        image is pushed to the other infinity.
 *    Under this reading a lower end lo must be -inf when some term of the
 *    row is unbounded below; otherwise, unless some term is +inf everywhere,
 *    lo <= L exactly, L = t + sum_j min(m_j x_j) over the box (0 for
 *    m_j == 0); the same for hi.  An infinite end is always fine on its own
 *    side; an end at the wrong infinity (lo = +inf, hi = -inf) fails.
 *
 *    NaN inputs: CBX_EINVAL with the documented whole-space output, also
 *    when the input has infinities (NaN is the first rule of the contract).
 */

#ifndef FUZZ_ORACLE_H
#define FUZZ_ORACLE_H

#include "fuzz_common.h"

/* ---------------------------------------------------------------------- */
/* The oracle                                                             */
/* ---------------------------------------------------------------------- */

#include <gmp.h>
#include "certbox.h"
#include "exact_util.h"

#define FZ_SH1 1074UL
#define FZ_SH2 2148UL

/* the pre-fill of every output field: a NaN nobody else produces */
#define FZ_FILL_BITS UINT64_C(0x7ff8f00df00df00d)

static const char *fz_harness = "?";
static void (*fz_dump_fn)(FILE *f);

FZ_FN void fz_fail(const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "\n==== certbox fuzz oracle FAILURE in %s: ", fz_harness);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, "\n---- decoded input and output:\n");
    if (fz_dump_fn) fz_dump_fn(stderr);
    fprintf(stderr, "====\n");
    fflush(stderr);
    abort();
}

FZ_FN double fz_fill(void) { return fz_from_bits(FZ_FILL_BITS); }

FZ_FN int fz_isnan(double v) { return v != v; }

/* every output field written and not NaN */
FZ_FN void fz_check_written(const double *v, int n, const char *what)
{
    int k;
    for (k = 0; k < n; k++) {
        if (fz_to_bits(v[k]) == FZ_FILL_BITS)
            fz_fail("%s field %d not written (pre-fill NaN left)", what, k);
        if (fz_isnan(v[k])) fz_fail("%s field %d is NaN", what, k);
    }
}

FZ_FN void fz_check_status_known(cbx_status st)
{
    if (xu_status_index(st) < 0) fz_fail("status %d is not a documented value", (int)st);
}

FZ_FN int fz_is_pinf(double d) { return d > 0 && isinf(d); }
FZ_FN int fz_is_ninf(double d) { return d < 0 && isinf(d); }

/* all finite? */
FZ_FN int fz_all_finite(const double *v, int n)
{
    int k;
    for (k = 0; k < n; k++)
        if (!isfinite(v[k])) return 0;
    return 1;
}

FZ_FN int fz_any_nan(const double *v, int n)
{
    int k;
    for (k = 0; k < n; k++)
        if (fz_isnan(v[k])) return 1;
    return 0;
}

/* ---- exact context (initialised once; never freed: libFuzzer runs the
 * harness in one process, and LeakSanitizer ignores reachable memory) --- */

typedef struct fz_ctx {
    xu_exact x;
    mpz_t z, w, s;
} fz_ctx;

FZ_FN fz_ctx *fz_ctx_get(void)
{
    static fz_ctx k;
    static int init;
    if (!init) {
        xu_init(&k.x);
        mpz_inits(k.z, k.w, k.s, (mpz_ptr)0);
        init = 1;
    }
    return &k;
}

/* An extended real: inf = -1 (-inf), +1 (+inf) or 0 (v, scaled). */
typedef struct fz_ext { int inf; mpz_t v; } fz_ext;

FZ_FN void fz_ext_init(fz_ext *e) { e->inf = 0; mpz_init(e->v); }

/* e = d * 2^sh (d not NaN) */
FZ_FN void fz_ext_d(fz_ext *e, double d, unsigned long sh)
{
    if (isinf(d)) {
        e->inf = d > 0 ? 1 : -1;
        mpz_set_ui(e->v, 0);
    } else {
        e->inf = 0;
        xu_scaled_sh(e->v, d, sh);
    }
}

/* e = (c + sg*h) * 2^sh, c and h finite */
FZ_FN void fz_ext_ch(fz_ctx *k, fz_ext *e, double c, double h, int sg, unsigned long sh)
{
    e->inf = 0;
    xu_scaled_sh(e->v, c, sh);
    xu_scaled_sh(k->z, h, sh);
    if (sg > 0) mpz_add(e->v, e->v, k->z);
    else mpz_sub(e->v, e->v, k->z);
}

/* sign of an extended real */
FZ_FN int fz_ext_sgn(const fz_ext *e) { return e->inf ? e->inf : mpz_sgn(e->v); }

/* a <= b (same scale) */
FZ_FN int fz_ext_le(const fz_ext *a, const fz_ext *b)
{
    if (a->inf < 0 || b->inf > 0) return 1;
    if (a->inf > 0 || b->inf < 0) return 0;
    return mpz_cmp(a->v, b->v) <= 0;
}

/* One input axis as a real interval [lo, hi] (ends scaled by 2^FZ_SH1). */
typedef struct fz_ival { fz_ext lo, hi; } fz_ival;

FZ_FN fz_ival *fz_ivals(void)
{
    static fz_ival iv[3];
    static int init;
    if (!init) {
        int j;
        for (j = 0; j < 3; j++) {
            fz_ext_init(&iv[j].lo);
            fz_ext_init(&iv[j].hi);
        }
        init = 1;
    }
    return iv;
}

/* Real box [lo, hi] (no NaN) into iv[]; returns 0 when the real set is
 * empty (lo > hi, lo = +inf or hi = -inf on some axis). */
FZ_FN int fz_ivals_box(fz_ival *iv, const double lo[3], const double hi[3])
{
    int j, nonempty = 1;
    for (j = 0; j < 3; j++) {
        fz_ext_d(&iv[j].lo, lo[j], FZ_SH1);
        fz_ext_d(&iv[j].hi, hi[j], FZ_SH1);
        if (iv[j].lo.inf > 0 || iv[j].hi.inf < 0 || !fz_ext_le(&iv[j].lo, &iv[j].hi))
            nonempty = 0;
    }
    return nonempty;
}

/* Real box [c - h, c + h] (no NaN) into iv[]; returns 0 when the real set
 * is empty: h < 0 on some axis, or c infinite (no real point). */
FZ_FN int fz_ivals_cbox(fz_ctx *k, fz_ival *iv, const double c[3], const double h[3])
{
    int j, nonempty = 1;
    for (j = 0; j < 3; j++) {
        if (h[j] < 0 || isinf(c[j])) {
            nonempty = 0;
            fz_ext_d(&iv[j].lo, 0.0, FZ_SH1);
            fz_ext_d(&iv[j].hi, 0.0, FZ_SH1);
        } else if (isinf(h[j])) {
            fz_ext_d(&iv[j].lo, -HUGE_VAL, FZ_SH1);
            fz_ext_d(&iv[j].hi, HUGE_VAL, FZ_SH1);
        } else {
            fz_ext_ch(k, &iv[j].lo, c[j], h[j], -1, FZ_SH1);
            fz_ext_ch(k, &iv[j].hi, c[j], h[j], +1, FZ_SH1);
        }
    }
    return nonempty;
}

/* What one side of an output axis must satisfy (values scaled 2^FZ_SH2). */
enum { FZ_REQ_NONE, FZ_REQ_INF, FZ_REQ_BOUND };
typedef struct fz_req { int kind; mpz_t v; } fz_req;

FZ_FN fz_req *fz_reqs(void)
{
    static fz_req r[2];
    static int init;
    if (!init) {
        mpz_init(r[0].v);
        mpz_init(r[1].v);
        init = 1;
    }
    return r;
}

/* Requirements on the two ends of the image of a nonempty real box under
 * y = m[0] x_0 + m[1] x_1 + m[2] x_2 + m[3] (see the top of this file).
 * rl: lo must be -inf (INF), or lo <= rl->v (BOUND), or nothing (NONE);
 * rh: hi must be +inf, or hi >= rh->v, or nothing.  Finite m and a
 * bounded box give BOUND on both sides with the exact min and max over the
 * 8 corners. */
FZ_FN void fz_row_req(fz_ctx *k, const double m[4], const fz_ival iv[3],
                      fz_req *rl, fz_req *rh)
{
    int neg_lo = 0, pos_lo = 0, neg_hi = 0, pos_hi = 0, j;
    mpz_set_ui(rl->v, 0);
    mpz_set_ui(rh->v, 0);
    if (isinf(m[3])) {
        if (m[3] < 0) neg_lo = neg_hi = 1;
        else pos_lo = pos_hi = 1;
    } else {
        xu_scaled_sh(k->z, m[3], FZ_SH2);
        mpz_add(rl->v, rl->v, k->z);
        mpz_add(rh->v, rh->v, k->z);
    }
    for (j = 0; j < 3; j++) {
        double mj = m[j];
        const fz_ext *el, *eh;
        if (mj == 0) continue;            /* 0 * x = 0 for every real x */
        el = mj > 0 ? &iv[j].lo : &iv[j].hi; /* where m x is smallest     */
        eh = mj > 0 ? &iv[j].hi : &iv[j].lo; /* where m x is largest      */
        if (isinf(mj)) {
            /* m = K * sign, K -> +inf: the term's inf/sup have the sign of
             * m times the sign of the minimising/maximising x */
            int sl = fz_ext_sgn(el) * (mj > 0 ? 1 : -1);
            int sh = fz_ext_sgn(eh) * (mj > 0 ? 1 : -1);
            if (sl < 0) neg_lo = 1;
            else if (sl > 0) pos_lo = 1;
            if (sh > 0) pos_hi = 1;
            else if (sh < 0) neg_hi = 1;
            continue;
        }
        xu_scaled_sh(k->w, mj, FZ_SH1);
        if (el->inf) {
            if (el->inf * (mj > 0 ? 1 : -1) < 0) neg_lo = 1;
            else pos_lo = 1;
        } else {
            mpz_mul(k->z, k->w, el->v);
            mpz_add(rl->v, rl->v, k->z);
        }
        if (eh->inf) {
            if (eh->inf * (mj > 0 ? 1 : -1) > 0) pos_hi = 1;
            else neg_hi = 1;
        } else {
            mpz_mul(k->z, k->w, eh->v);
            mpz_add(rh->v, rh->v, k->z);
        }
    }
    rl->kind = neg_lo ? FZ_REQ_INF : pos_lo ? FZ_REQ_NONE : FZ_REQ_BOUND;
    rh->kind = pos_hi ? FZ_REQ_INF : neg_hi ? FZ_REQ_NONE : FZ_REQ_BOUND;
}

/* The two ends of an output axis as extended reals scaled by 2^FZ_SH2. */
FZ_FN fz_ext *fz_oends(void)
{
    static fz_ext e[2];
    static int init;
    if (!init) {
        fz_ext_init(&e[0]);
        fz_ext_init(&e[1]);
        init = 1;
    }
    return e;
}

/* box output axis [lo, hi] (not NaN) */
FZ_FN void fz_oends_box(fz_ext e[2], double lo, double hi)
{
    fz_ext_d(&e[0], lo, FZ_SH2);
    fz_ext_d(&e[1], hi, FZ_SH2);
}

/* cbox output axis [c - h, c + h] (not NaN): h = +inf is the whole line
 * (whatever c), h < 0 an empty axis, an infinite c with a finite h a set
 * with no real point (both ends at c). */
FZ_FN void fz_oends_cbox(fz_ctx *k, fz_ext e[2], double c, double h)
{
    if (fz_is_pinf(h)) {
        fz_ext_d(&e[0], -HUGE_VAL, FZ_SH2);
        fz_ext_d(&e[1], HUGE_VAL, FZ_SH2);
    } else if (h < 0) {
        fz_ext_d(&e[0], HUGE_VAL, FZ_SH2);
        fz_ext_d(&e[1], -HUGE_VAL, FZ_SH2);
    } else if (isinf(c)) {
        fz_ext_d(&e[0], c, FZ_SH2);
        fz_ext_d(&e[1], c, FZ_SH2);
    } else {
        fz_ext_ch(k, &e[0], c, h, -1, FZ_SH2);
        fz_ext_ch(k, &e[1], c, h, +1, FZ_SH2);
    }
}

/* Check the ends e[] of output axis i against the requirements. */
FZ_FN void fz_check_req(int i, const fz_req *rl, const fz_req *rh, const fz_ext e[2])
{
    if (rl->kind == FZ_REQ_INF && e[0].inf >= 0)
        fz_fail("axis %d: the exact image is unbounded below but the lower end is %s",
                i, e[0].inf > 0 ? "+inf" : "finite");
    if (rl->kind == FZ_REQ_BOUND && e[0].inf >= 0) {
        if (e[0].inf > 0) fz_fail("axis %d: lower end +inf above a bounded image", i);
        if (mpz_cmp(e[0].v, rl->v) > 0)
            fz_fail("axis %d: CONTAINMENT: lower end above the exact infimum of the image", i);
    }
    if (rh->kind == FZ_REQ_INF && e[1].inf <= 0)
        fz_fail("axis %d: the exact image is unbounded above but the upper end is %s",
                i, e[1].inf < 0 ? "-inf" : "finite");
    if (rh->kind == FZ_REQ_BOUND && e[1].inf <= 0) {
        if (e[1].inf < 0) fz_fail("axis %d: upper end -inf below a bounded image", i);
        if (mpz_cmp(e[1].v, rh->v) < 0)
            fz_fail("axis %d: CONTAINMENT: upper end below the exact supremum of the image", i);
    }
}

/* The 8 corner images of row m over a bounded box (iv[] all finite), each
 * compared exactly with the finite output ends e[] (scaled 2^FZ_SH2); an
 * infinite end on its own side contains everything.  Independent of
 * fz_row_req (no min/max reasoning). */
FZ_FN void fz_check_corners(fz_ctx *k, int i, const double m[4], const fz_ival iv[3],
                            const fz_ext e[2])
{
    unsigned c;
    int j;
    for (c = 0; c < 8; c++) {
        xu_scaled_sh(k->s, m[3], FZ_SH2);
        for (j = 0; j < 3; j++) {
            const fz_ext *x = (c >> j) & 1u ? &iv[j].hi : &iv[j].lo;
            xu_scaled_sh(k->w, m[j], FZ_SH1);
            mpz_mul(k->z, k->w, x->v);
            mpz_add(k->s, k->s, k->z);
        }
        if (e[0].inf > 0 || (e[0].inf == 0 && mpz_cmp(e[0].v, k->s) > 0))
            fz_fail("axis %d: CONTAINMENT: corner %u of the input box maps below the lower end",
                    i, c);
        if (e[1].inf < 0 || (e[1].inf == 0 && mpz_cmp(e[1].v, k->s) < 0))
            fz_fail("axis %d: CONTAINMENT: corner %u of the input box maps above the upper end",
                    i, c);
    }
}

/* Box output: EINVAL whole space [-inf, +inf]^3, EMPTY lo = +inf, hi = -inf */
FZ_FN void fz_check_box_whole(const cbx_box *o)
{
    int i;
    for (i = 0; i < 3; i++)
        if (!fz_is_ninf(o->lo[i]) || !fz_is_pinf(o->hi[i]))
            fz_fail("axis %d is not [-inf, +inf] (documented whole-space output)", i);
}

FZ_FN void fz_check_box_empty(const cbx_box *o)
{
    int i;
    for (i = 0; i < 3; i++)
        if (!fz_is_pinf(o->lo[i]) || !fz_is_ninf(o->hi[i]))
            fz_fail("axis %d is not lo = +inf, hi = -inf (documented empty output)", i);
}

/* cbox output axis: c = 0 (either sign), h = +inf (whole) / -inf (empty) */
FZ_FN void fz_check_caxis(const cbx_cbox *o, int i, int whole)
{
    if (o->c[i] != 0.0 || !(whole ? fz_is_pinf(o->h[i]) : fz_is_ninf(o->h[i])))
        fz_fail("axis %d is not c = 0, h = %s (documented %s output)", i,
                whole ? "+inf" : "-inf", whole ? "whole-line" : "empty");
}

FZ_FN void fz_check_status(cbx_status got, cbx_status want)
{
    if (got != want)
        fz_fail("status %s (%d), expected %s (%d)", cbx_status_name(got), (int)got,
                cbx_status_name(want), (int)want);
}

/* One axis of a ball image t -+ sqrt(s) (s = the exact squared row norm,
 * an integer scaled by 2^(2 sh); s_inf: some coefficient of the row is
 * infinite, so the image is unbounded on both sides), checked exactly as
 * in test_sphere: lo <= t - sqrt(s) iff t - lo >= 0 and (t - lo)^2 >= s.
 * t = +-inf pushes the image to that infinity: the end on that side must
 * be infinite, the other end carries no obligation. */
FZ_FN void fz_check_ball_axis(fz_ctx *k, int i, double t, const mpz_t s, int s_inf,
                              unsigned long sh, double lo, double hi)
{
    if (s_inf || fz_is_ninf(t)) {
        if (!fz_is_ninf(lo))
            fz_fail("axis %d: the exact image is unbounded below but lo = %a", i, lo);
    } else if (!fz_is_pinf(t) && !fz_is_ninf(lo)) {
        if (fz_is_pinf(lo)) fz_fail("axis %d: lo = +inf above a bounded image", i);
        if (!xu_sqrt_lo_ok(&k->x, s, sh, t, lo))
            fz_fail("axis %d: CONTAINMENT: lo > t - sqrt(s) (exact)", i);
    }
    if (s_inf || fz_is_pinf(t)) {
        if (!fz_is_pinf(hi))
            fz_fail("axis %d: the exact image is unbounded above but hi = %a", i, hi);
    } else if (!fz_is_ninf(t) && !fz_is_pinf(hi)) {
        if (fz_is_ninf(hi)) fz_fail("axis %d: hi = -inf below a bounded image", i);
        if (!xu_sqrt_hi_ok(&k->x, s, sh, t, hi))
            fz_fail("axis %d: CONTAINMENT: hi < t + sqrt(s) (exact)", i);
    }
}

FZ_FN void fz_print_affine(FILE *f, const cbx_affine *a)
{
    int i;
    char lab[16];
    for (i = 0; i < 3; i++) {
        snprintf(lab, sizeof lab, "m[%d]", i);
        fz_print_vec(f, lab, a->m[i], 4);
    }
}

FZ_FN void fz_print_box(FILE *f, const char *label, const cbx_box *b)
{
    char lab[32];
    snprintf(lab, sizeof lab, "%s.lo", label);
    fz_print_vec(f, lab, b->lo, 3);
    snprintf(lab, sizeof lab, "%s.hi", label);
    fz_print_vec(f, lab, b->hi, 3);
}

FZ_FN void fz_print_cbox(FILE *f, const char *label, const cbx_cbox *b)
{
    char lab[32];
    snprintf(lab, sizeof lab, "%s.c", label);
    fz_print_vec(f, lab, b->c, 3);
    snprintf(lab, sizeof lab, "%s.h", label);
    fz_print_vec(f, lab, b->h, 3);
}

FZ_FN void fz_print_status(FILE *f, cbx_status st)
{
    fprintf(f, "  status = %s (%d)\n", cbx_status_name(st), (int)st);
}

#endif /* FUZZ_ORACLE_H */
