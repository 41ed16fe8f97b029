/*
 * libFuzzer harness: cbx_transform_box against the exact oracle.
 *
 * Input: a control byte, then 12 doubles m[0][0..3], m[1][0..3],
 * m[2][0..3] and 6 doubles lo0, hi0, lo1, hi1, lo2, hi2 (encoding:
 * fuzz_common.h).  Control bits, applied in this order:
 *   bit 4      point box: hi_j = lo_j on every axis;
 *   bits 0..2  sort axis j (swap lo_j, hi_j when lo_j > hi_j), so that
 *              non-empty boxes are frequent;
 *   bit 3      cancellation: t_i = -fl(m_i0 lo_0 + m_i1 lo_1 + m_i2 lo_2),
 *              evaluated in binary64 (an end of the image close to 0);
 *   bit 6      in-place call, out == in (allowed by the contract): the
 *              oracle then reads the saved input; "every field written"
 *              cannot be told from the pre-fill there (NaN is still caught).
 * Oracle (abort() on failure):
 *   always: status documented, every field written, no NaN in out, the
 *     inputs unchanged; NaN input -> CBX_EINVAL and [-inf, +inf]^3;
 *   finite inputs: status == xu_expected_status (exact_util); EMPTY ->
 *     lo = +inf, hi = -inf; out-of-domain axes [-inf, +inf]; in-domain
 *     axes finite, lo <= hi, the 8 corner images inside [lo, hi] (exact,
 *     mpz and, independently, mpq: xu_corner_failures), and within the
 *     proven tightness 12 u S + 2^-1065 (xu_lo/hi_within_proven);
 *   inputs with infinities: containment on every finite end only (exact,
 *     on the unbounded image; see fuzz_common.h).
 */
#include "fuzz_common.h"

static cbx_affine A;
static cbx_box IN, OUT;
static cbx_status ST;
static unsigned CTL;

static void dump(FILE *f)
{
    fprintf(f, "  control byte = 0x%02x%s\n", CTL,
            CTL & 0x40u ? " (in-place call, out == in)" : "");
    fprintf(f, "  cbx_transform_box(a, in, out) with\n");
    fz_print_affine(f, &A);
    fz_print_box(f, "in", &IN);
    fz_print_status(f, ST);
    fz_print_box(f, "out", &OUT);
}

static int box_finite(void)
{
    int i;
    for (i = 0; i < 3; i++)
        if (!fz_all_finite(A.m[i], 4)) return 0;
    return fz_all_finite(IN.lo, 3) && fz_all_finite(IN.hi, 3);
}

static int box_has_nan(void) { return xu_has_nan(&A, &IN); }

static void check_finite_input(fz_ctx *k)
{
    cbx_status want = xu_expected_status(&A, &IN);
    fz_ival *iv = fz_ivals();
    fz_ext *e = fz_oends();
    int oob, i;

    fz_check_status(ST, want);
    if (want == CBX_EMPTY) {
        fz_check_box_empty(&OUT);
        return;
    }
    oob = xu_oob_mask(&A, &IN);
    if (!fz_ivals_box(iv, IN.lo, IN.hi)) fz_fail("oracle: non-empty box read as empty");
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
        fz_oends_box(e, lo, hi);
        fz_check_corners(k, i, A.m[i], iv, e);
        if (xu_corner_failures(&k->x, &A, &IN, i, lo, hi))
            fz_fail("axis %d: CONTAINMENT: mpq corner check failed", i);
        xu_row_bounds(&k->x, &A, &IN, i);
        if (xu_cmp_scaled_d(&k->x, k->x.L, lo) < 0 || xu_cmp_scaled_d(&k->x, k->x.H, hi) > 0)
            fz_fail("axis %d: CONTAINMENT: fixed-point L/H not inside [lo, hi]", i);
        if (!xu_lo_within_proven(&k->x, lo) || !xu_hi_within_proven(&k->x, hi))
            fz_fail("axis %d: beyond the proven tightness 12 u S + 2^-1065", i);
    }
}

static void check_infinite_input(fz_ctx *k)
{
    fz_ival *iv = fz_ivals();
    fz_req *r = fz_reqs();
    fz_ext *e = fz_oends();
    int i;
    if (!fz_ivals_box(iv, IN.lo, IN.hi)) return; /* empty real box */
    for (i = 0; i < 3; i++) {
        fz_row_req(k, A.m[i], iv, &r[0], &r[1]);
        fz_oends_box(e, OUT.lo[i], OUT.hi[i]);
        fz_check_req(i, &r[0], &r[1], e);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in;
    fz_ctx *k = fz_ctx_get();
    cbx_affine a0;
    cbx_box in0;
    int i, j;

    in.p = data;
    in.n = size;
    fz_harness = "fuzz_transform_box";
    fz_dump_fn = dump;
    CTL = fz_byte(&in);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) A.m[i][j] = fz_double(&in);
    for (j = 0; j < 3; j++) {
        IN.lo[j] = fz_double(&in);
        IN.hi[j] = fz_double(&in);
    }
    for (j = 0; j < 3; j++) {
        if (CTL & 0x10u) IN.hi[j] = IN.lo[j];
        if ((CTL >> j) & 1u && IN.lo[j] > IN.hi[j]) {
            double t = IN.lo[j];
            IN.lo[j] = IN.hi[j];
            IN.hi[j] = t;
        }
    }
    if (CTL & 0x08u)
        for (i = 0; i < 3; i++)
            A.m[i][3] = -(A.m[i][0] * IN.lo[0] + A.m[i][1] * IN.lo[1] + A.m[i][2] * IN.lo[2]);

    a0 = A;
    in0 = IN;
    if (CTL & 0x40u) { /* in place: the result overwrites IN */
        ST = cbx_transform_box(&A, &IN, &IN);
        OUT = IN;
        IN = in0;
        if (memcmp(&a0, &A, sizeof A)) fz_fail("the call modified *a");
    } else {
        for (i = 0; i < 3; i++) OUT.lo[i] = OUT.hi[i] = fz_fill();
        ST = cbx_transform_box(&A, &IN, &OUT);
        if (memcmp(&a0, &A, sizeof A) || memcmp(&in0, &IN, sizeof IN))
            fz_fail("the call modified its inputs");
    }
    fz_check_status_known(ST);
    fz_check_written(OUT.lo, 3, "out.lo");
    fz_check_written(OUT.hi, 3, "out.hi");
    if (box_has_nan()) {
        fz_check_status(ST, CBX_EINVAL);
        fz_check_box_whole(&OUT);
    } else if (box_finite()) {
        check_finite_input(k);
    } else {
        check_infinite_input(k);
    }
    return 0;
}
