/*
 * libFuzzer harness: cbx_sphere_box against the exact oracle.
 *
 * Input: a control byte, then 12 doubles m[0][0..3], m[1][0..3],
 * m[2][0..3] (encoding: fuzz_common.h).  Control bits:
 *   bit 0      cancellation: t_i = s * fl(sqrt(m_i0^2 + m_i1^2 + m_i2^2))
 *              (binary64), one end of each axis close to 0;
 *   bit 1      the sign s: - when set, + otherwise.
 * The exact image of the unit ball on axis i is t_i -+ sqrt(s_i), t_i =
 * m[i][3], s_i = m_i0^2 + m_i1^2 + m_i2^2.
 * Oracle (abort() on failure):
 *   always: status documented, every field written, no NaN in out, the
 *     input unchanged; NaN input -> CBX_EINVAL and [-inf, +inf]^3;
 *   finite inputs: status decided exactly from the contract (a row with
 *     |m_ij| > 2^509, j < 3, or |t_i| > 2^1018 -> CBX_ERANGE with that axis
 *     [-inf, +inf]); in-domain axes finite, lo <= hi, and
 *     lo <= t - sqrt(s), t + sqrt(s) <= hi decided exactly on integers
 *     (xu_sqrt_lo_ok / xu_sqrt_hi_ok, as in test_sphere);
 *   inputs with infinities: on every row, containment on every finite end
 *     (fz_check_ball_axis: an infinite m_ij makes both sides unbounded).
 */
#include "fuzz_common.h"

static cbx_affine A;
static cbx_box OUT;
static cbx_status ST;
static unsigned CTL;

static void dump(FILE *f)
{
    fprintf(f, "  control byte = 0x%02x\n", CTL);
    fprintf(f, "  cbx_sphere_box(a, out) with\n");
    fz_print_affine(f, &A);
    fz_print_status(f, ST);
    fz_print_box(f, "out", &OUT);
}

/* k->s = sum_j (m_ij 2^1074)^2 over the finite entries; returns 1 when some
 * m_ij (j < 3) is infinite */
static int row_s(fz_ctx *k, int i)
{
    int j, inf = 0;
    mpz_set_ui(k->s, 0);
    for (j = 0; j < 3; j++) {
        if (isinf(A.m[i][j])) {
            inf = 1;
            continue;
        }
        xu_scaled_sh(k->z, A.m[i][j], FZ_SH1);
        mpz_addmul(k->s, k->z, k->z);
    }
    return inf;
}

static int row_in_domain(int i)
{
    int j;
    for (j = 0; j < 3; j++)
        if (!(fabs(A.m[i][j]) <= 0x1p509)) return 0;
    return fabs(A.m[i][3]) <= 0x1p1018;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in;
    fz_ctx *k = fz_ctx_get();
    cbx_affine a0;
    int i, j, nan = 0, fin = 1;

    in.p = data;
    in.n = size;
    fz_harness = "fuzz_sphere_box";
    fz_dump_fn = dump;
    CTL = fz_byte(&in);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) A.m[i][j] = fz_double(&in);
    if (CTL & 1u)
        for (i = 0; i < 3; i++) {
            double r = sqrt(A.m[i][0] * A.m[i][0] + A.m[i][1] * A.m[i][1]
                            + A.m[i][2] * A.m[i][2]);
            A.m[i][3] = (CTL & 2u) ? -r : r;
        }

    for (i = 0; i < 3; i++) OUT.lo[i] = OUT.hi[i] = fz_fill();
    a0 = A;
    ST = cbx_sphere_box(&A, &OUT);

    if (memcmp(&a0, &A, sizeof A)) fz_fail("the call modified its input");
    fz_check_status_known(ST);
    fz_check_written(OUT.lo, 3, "out.lo");
    fz_check_written(OUT.hi, 3, "out.hi");
    for (i = 0; i < 3; i++) {
        nan |= fz_any_nan(A.m[i], 4);
        fin &= fz_all_finite(A.m[i], 4);
    }
    if (nan) {
        fz_check_status(ST, CBX_EINVAL);
        fz_check_box_whole(&OUT);
        return 0;
    }
    if (fin) {
        int oob = 0;
        for (i = 0; i < 3; i++)
            if (!row_in_domain(i)) oob |= 1 << i;
        fz_check_status(ST, oob ? CBX_ERANGE : CBX_OK);
        for (i = 0; i < 3; i++) {
            double lo = OUT.lo[i], hi = OUT.hi[i];
            if (oob & (1 << i)) {
                if (!fz_is_ninf(lo) || !fz_is_pinf(hi))
                    fz_fail("axis %d is outside the domain but not [-inf, +inf]", i);
                continue;
            }
            if (!isfinite(lo) || !isfinite(hi) || lo > hi)
                fz_fail("axis %d is in the domain but out = [%a, %a] (not finite, ordered)",
                        i, lo, hi);
            row_s(k, i);
            fz_check_ball_axis(k, i, A.m[i][3], k->s, 0, FZ_SH1, lo, hi);
        }
        return 0;
    }
    for (i = 0; i < 3; i++) {
        int s_inf = row_s(k, i);
        fz_check_ball_axis(k, i, A.m[i][3], k->s, s_inf, FZ_SH1, OUT.lo[i], OUT.hi[i]);
    }
    return 0;
}
