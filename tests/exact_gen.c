/* exact_gen: the random draws of the tests: splitmix64 (xu_rng), the
 * format's magnitudes and signed values, a random rotation, and the random
 * cases of cbx_transform_box (test_exact) and of the float family
 * (test_float): in the domain by construction, pushed out of it,
 * half-spaces, NaN and empty inputs.
 * Part of the oracle declared in exact_util.h (see there for the map). */
#include "exact_util.h"

#include <math.h>

/* ---------------------------------------------------------------------- */
/* Random numbers                                                         */
/* ---------------------------------------------------------------------- */

uint64_t xu_rng_next(xu_rng *r)
{
    uint64_t z = (r->s += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

/* 64-bit arithmetic throughout: long is 32 bits on 32-bit targets, where
 * hi - lo + 1 overflows for spans above 2^31 (found by make check-cross) */
int xu_rng_int(xu_rng *r, int lo, int hi)
{
    uint64_t span = (uint64_t)((int64_t)hi - (int64_t)lo + 1);
    return (int)((int64_t)lo + (int64_t)(xu_rng_next(r) % span));
}

double xu_rng_sign(xu_rng *r) { return (xu_rng_next(r) >> 63) ? -1.0 : 1.0; }

double xu_rng_unit(xu_rng *r)
{
    return ldexp((double)(xu_rng_next(r) >> 11), -53);
}

double xu_gen_mag(xu_rng *r, int emin, int emax)
{
    int p = xu_rng_int(r, 0, 99), e;
    int mb = xu_fmt->p - 1; /* mantissa bits after the leading one */
    double frac;
    if (emin < -xu_fmt->emin) emin = -xu_fmt->emin;
    if (emax > xu_fmt->emax) emax = xu_fmt->emax;
    if (emax < emin) emax = emin;
    if (p < 4) return 0.0;
    if (p < 8) return ldexp(1.0, emax);
    if (p < 12 && emin <= xu_fmt->norm_min && emax >= xu_fmt->norm_min)
        return ldexp((double)((xu_rng_next(r) >> (64 - mb)) | 1u), -xu_fmt->emin);
    e = xu_rng_int(r, emin - 1, emax - 1);
    frac = 1.0 + ldexp((double)(xu_rng_next(r) >> (64 - mb)), -mb);
    /* < 2^emax; a subnormal result rounds in double, so round it to the
     * format (a no-op in binary64) */
    frac = ldexp(frac, e);
    return xu_round_fmt(frac);
}

/* Every draw of the generators below is its own statement: C leaves the
 * order of the operands of * and of function arguments unspecified, and
 * gcc orders them differently on x86-64 and ARM (found by check-cross). */
double xu_gen_signed(xu_rng *r, int emin, int emax)
{
    double s = xu_rng_sign(r);
    return s * xu_gen_mag(r, emin, emax);
}

void xu_rand_rotation(xu_rng *r, double R[3][3])
{
    double w, x, y, z, n;
    do {
        w = 2 * xu_rng_unit(r) - 1;
        x = 2 * xu_rng_unit(r) - 1;
        y = 2 * xu_rng_unit(r) - 1;
        z = 2 * xu_rng_unit(r) - 1;
        n = w * w + x * x + y * y + z * z;
    } while (n > 1 || n < 1e-6);
    n = sqrt(n);
    w /= n; x /= n; y /= n; z /= n;
    R[0][0] = 1 - 2 * (y * y + z * z);
    R[0][1] = 2 * (x * y - w * z);
    R[0][2] = 2 * (x * z + w * y);
    R[1][0] = 2 * (x * y + w * z);
    R[1][1] = 1 - 2 * (x * x + z * z);
    R[1][2] = 2 * (y * z - w * x);
    R[2][0] = 2 * (x * z - w * y);
    R[2][1] = 2 * (y * z + w * x);
    R[2][2] = 1 - 2 * (x * x + y * y);
}

/* ---------------------------------------------------------------------- */
/* Random cases of cbx_transform_box (test_exact) and of the float family  */
/* (test_float): the format's values, drawn the same way                   */
/* ---------------------------------------------------------------------- */

/* Interval on axis j with |lo|, |hi| <= 2^chi. */
static void xu_gen_interval(xu_rng *r, cbx_box *b, int j, int clo, int chi)
{
    int p = xu_rng_int(r, 0, 99);
    double u, v;
    if (p < 10) { /* point box */
        b->lo[j] = b->hi[j] = xu_gen_signed(r, clo, chi);
    } else if (p < 15) { /* signed zeros, any order: never empty */
        b->lo[j] = xu_rng_sign(r) * 0.0;
        b->hi[j] = xu_rng_sign(r) * 0.0;
    } else if (p < 25) { /* symmetric */
        u = xu_gen_mag(r, clo, chi);
        b->lo[j] = -u;
        b->hi[j] = u;
    } else if (p < 32) { /* one ulp wide */
        u = xu_gen_signed(r, clo, chi);
        v = xu_next_up(u);
        if (fabs(v) > ldexp(1.0, chi)) v = u;
        b->lo[j] = u;
        b->hi[j] = v;
    } else {
        u = xu_gen_signed(r, clo, chi);
        v = xu_gen_signed(r, clo, chi);
        b->lo[j] = u < v ? u : v;
        b->hi[j] = u < v ? v : u;
    }
}

/* t = -fl(sum_j m_j c_j) at a random corner: the image nearly cancels. */
static double xu_cancelling_t(xu_rng *r, const cbx_affine *a, const cbx_box *b, int i)
{
    double s = 0.0;
    int j;
    for (j = 0; j < 3; j++)
        s += a->m[i][j] * ((xu_rng_next(r) >> 63) ? b->hi[j] : b->lo[j]);
    return -xu_round_fmt(s); /* a value of the format */
}

/* A case inside the domain by construction: per column a magnitude class
 * k, entries within 2^k and coordinates within 2^(rt-k) (binary64:
 * 2^(1018-k)).  In "narrow"
 * mode all products share an exponent P (so terms are comparable and
 * cancellation happens); otherwise exponents are spread over the class. */
static void xu_gen_in_domain(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    int narrow = xu_rng_int(r, 0, 1);
    int E = xu_fmt->emin, RT = xu_fmt->rt;
    int P = xu_rng_int(r, -E + 4, RT - 2);
    int i, j;
    for (j = 0; j < 3; j++) {
        int k = xu_fmt->class_k[xu_rng_int(r, 0, XU_NCLASS - 1)];
        int mlo = -E, mhi = k, clo = -E, chi = RT - k;
        if (narrow) {
            int lo = P - RT + k > -E ? P - RT + k : -E;
            int hi = k < P + E ? k : P + E;
            int am = xu_rng_int(r, lo, hi);
            mhi = am;
            mlo = am - 4;
            chi = P - am;
            clo = chi - 4;
        }
        for (i = 0; i < 3; i++) a->m[i][j] = xu_gen_signed(r, mlo, mhi);
        xu_gen_interval(r, b, j, clo, chi);
    }
    for (i = 0; i < 3; i++) {
        int p = xu_rng_int(r, 0, 9);
        if (p < 2) a->m[i][3] = xu_cancelling_t(r, a, b, i);
        else if (p < 3) a->m[i][3] = xu_rng_sign(r) * 0.0;
        else if (narrow) a->m[i][3] = xu_gen_signed(r, P - 4, P);
        else a->m[i][3] = xu_gen_signed(r, -E, RT);
    }
}

/* Push one input out of (or to the edge of) the domain. */
static void xu_perturb_out(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    int i = xu_rng_int(r, 0, 2), j = xu_rng_int(r, 0, 2), k;
    double big;
    int RT = xu_fmt->rt, EX = xu_fmt->emax;
    switch (xu_rng_int(r, 0, 6)) {
    case 0: /* large entry: may or may not still fit a class */
        a->m[i][j] = xu_gen_signed(r, xu_fmt->big_entry, EX);
        break;
    case 1: /* large coordinate */
        big = xu_gen_mag(r, xu_fmt->big_coord, EX);
        if (xu_rng_int(r, 0, 1)) { if (big > b->lo[j]) b->hi[j] = big; }
        else if (-big < b->hi[j]) b->lo[j] = -big;
        break;
    case 2: /* infinite coordinate(s) */
        switch (xu_rng_int(r, 0, 3)) {
        case 0: b->lo[j] = -HUGE_VAL; break;
        case 1: b->hi[j] = HUGE_VAL; break;
        case 2: b->lo[j] = b->hi[j] = HUGE_VAL; break;
        default: b->lo[j] = -HUGE_VAL; b->hi[j] = HUGE_VAL; break;
        }
        break;
    case 3: /* infinite entry or translation */
        big = xu_rng_sign(r) * HUGE_VAL;
        k = xu_rng_int(r, 0, 3);
        a->m[i][k] = big;
        break;
    case 4: /* translation beyond 2^rt (binary64: 2^1018) */
        k = xu_rng_int(r, 0, 2);
        big = k == 0 ? xu_next_up(ldexp(1.0, RT))
            : k == 1 ? xu_fmt_max() : xu_gen_mag(r, RT + 1, EX);
        a->m[i][3] = xu_rng_sign(r) * big;
        break;
    case 5: /* one ulp outward on an entry: crosses a class boundary when
               the entry sat on it */
        a->m[i][j] = a->m[i][j] < 0 ? -xu_next_up(-a->m[i][j]) : xu_next_up(a->m[i][j]);
        break;
    default: /* exact class corner, then one coordinate one ulp beyond */
        k = xu_fmt->class_k[xu_rng_int(r, 0, XU_NCLASS - 1)];
        a->m[i][j] = xu_rng_sign(r) * ldexp(1.0, k);
        b->lo[j] = -ldexp(1.0, RT - k);
        b->hi[j] = ldexp(1.0, RT - k);
        if (xu_rng_int(r, 0, 1)) b->hi[j] = xu_next_up(b->hi[j]);
        break;
    }
}

/* Half-spaces (rule B): 1 to 4 box ends made infinite on their own side
 * (lo = -inf, hi = +inf), some map entries set to +-0 (a zero column
 * against an infinite end counts as 0) and, sometimes, one end of a
 * finite axis made huge (beyond every class: lost only where needed). */
static void xu_perturb_half(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    int n = xu_rng_int(r, 1, 4), k;
    for (k = 0; k < n; k++) {
        int j = xu_rng_int(r, 0, 2);
        if (xu_rng_int(r, 0, 1)) b->lo[j] = -HUGE_VAL;
        else b->hi[j] = HUGE_VAL;
    }
    n = xu_rng_int(r, 0, 4);
    for (k = 0; k < n; k++)
    {
        double z = xu_rng_sign(r) * 0.0;
        int i = xu_rng_int(r, 0, 2), j = xu_rng_int(r, 0, 2);
        a->m[i][j] = z;
    }
    if (xu_rng_int(r, 0, 3) == 0) {
        int j = xu_rng_int(r, 0, 2);
        double big = xu_rng_int(r, 0, 1) ? xu_fmt_max() : xu_gen_mag(r, xu_fmt->rt + 1, xu_fmt->emax);
        if (xu_rng_int(r, 0, 1)) { if (isfinite(b->lo[j])) b->hi[j] = big; }
        else if (isfinite(b->hi[j])) b->lo[j] = -big;
    }
}

void xu_inject_nan(xu_rng *r, cbx_affine *a, double v0[3], double v1[3])
{
    int p = xu_rng_int(r, 0, 17);
    double nan = xu_rng_sign(r) * NAN;
    if (p < 12) a->m[p / 4][p % 4] = nan;
    else if (p < 15) v0[p - 12] = nan;
    else v1[p - 15] = nan;
}

static void xu_inject_empty(xu_rng *r, cbx_box *b)
{
    int j = xu_rng_int(r, 0, 2);
    switch (xu_rng_int(r, 0, 4)) {
    case 0: /* one ulp inverted */
        b->lo[j] = xu_next_up(b->hi[j]);
        break;
    case 1: /* inverted infinities */
        b->lo[j] = HUGE_VAL;
        b->hi[j] = -HUGE_VAL;
        break;
    case 2: /* lo = +inf: no real point, even with hi = +inf */
        b->lo[j] = HUGE_VAL;
        if (xu_rng_int(r, 0, 1)) b->hi[j] = HUGE_VAL;
        break;
    case 3: /* hi = -inf: no real point, even with lo = -inf */
        b->hi[j] = -HUGE_VAL;
        if (xu_rng_int(r, 0, 1)) b->lo[j] = -HUGE_VAL;
        break;
    default: /* swapped ends, made distinct */
        b->lo[j] = 1.0;
        b->hi[j] = -1.0;
        break;
    }
}

/* ~82% in domain by construction, ~10% pushed out, ~5% half-spaces,
 * ~1.5% NaN, ~1.5% empty (some of those also NaN: EINVAL must win). */
void xu_gen_case(xu_rng *r, cbx_affine *a, cbx_box *b)
{
    int p = xu_rng_int(r, 0, 999);
    xu_gen_in_domain(r, a, b);
    if (p < 100) xu_perturb_out(r, a, b);
    else if (p < 115) xu_inject_nan(r, a, b->lo, b->hi);
    else if (p < 130) {
        xu_inject_empty(r, b);
        if (p < 118) xu_inject_nan(r, a, b->lo, b->hi);
    } else if (p < 180) {
        xu_perturb_half(r, a, b);
        if (p < 140) xu_perturb_out(r, a, b);
    }
}
