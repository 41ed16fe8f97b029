/*
 * libFuzzer harness: cbx_transform_cbox against the exact oracle.
 *
 * Input: a control byte, then 12 doubles m[0][0..3], m[1][0..3],
 * m[2][0..3] and 6 doubles c0, h0, c1, h1, c2, h2 (encoding:
 * fuzz_common.h).  Control bits, applied in this order:
 *   bit 4      points: h_j = 0 on every axis;
 *   bits 0..2  h_j = |h_j| (non-empty boxes are frequent);
 *   bit 3      cancellation: t_i = -fl(m_i0 c_0 + m_i1 c_1 + m_i2 c_2);
 *   bit 6      in-place call, out == in (allowed by the contract): the
 *              oracle then reads the saved input; "every field written"
 *              cannot be told from the pre-fill there (NaN is still caught).
 * The input means the real box [c_j - h_j, c_j + h_j]; the output axis i
 * means [c'_i - h'_i, c'_i + h'_i].
 * Oracle (abort() on failure):
 *   always: status documented, every field written, no NaN in out, the
 *     inputs unchanged; NaN input -> CBX_EINVAL, c = 0, h = +inf on every
 *     axis;
 *   finite inputs: the status decided exactly from the contract (h < 0 ->
 *     EMPTY with c = 0, h = -inf; a row outside the domain, pairs
 *     (m_ij, c_j), (m_ij, h_j) and |m_i3| <= 2^1018: xu_cbox_row_in_domain,
 *     -> ERANGE, that axis c = 0, h = +inf); in-domain axes finite with
 *     h' >= 0, and the 8 exact corner images t_i + sum_j m_ij (c_j -+ h_j)
 *     inside [c' - h', c' + h'] (exact);
 *   inputs with infinities: containment on every finite end only (exact,
 *     on the unbounded image; see fuzz_common.h).
 */
#include "fuzz_common.h"

static cbx_affine A;
static cbx_cbox IN, OUT;
static cbx_status ST;
static unsigned CTL;

static void dump(FILE *f)
{
    fprintf(f, "  control byte = 0x%02x%s\n", CTL,
            CTL & 0x40u ? " (in-place call, out == in)" : "");
    fprintf(f, "  cbx_transform_cbox(a, in, out) with\n");
    fz_print_affine(f, &A);
    fz_print_cbox(f, "in", &IN);
    fz_print_status(f, ST);
    fz_print_cbox(f, "out", &OUT);
}

static int all_finite(void)
{
    int i;
    for (i = 0; i < 3; i++)
        if (!fz_all_finite(A.m[i], 4)) return 0;
    return fz_all_finite(IN.c, 3) && fz_all_finite(IN.h, 3);
}

static void check_finite_input(fz_ctx *k)
{
    fz_ival *iv = fz_ivals();
    fz_ext *e = fz_oends();
    int i, oob = 0;
    cbx_status want;

    if (xu_cbox_is_empty(&IN)) {
        fz_check_status(ST, CBX_EMPTY);
        for (i = 0; i < 3; i++) fz_check_caxis(&OUT, i, 0);
        return;
    }
    for (i = 0; i < 3; i++)
        if (!xu_cbox_row_in_domain(&A, &IN, i)) oob |= 1 << i;
    want = oob ? CBX_ERANGE : CBX_OK;
    fz_check_status(ST, want);
    if (!fz_ivals_cbox(k, iv, IN.c, IN.h)) fz_fail("oracle: non-empty cbox read as empty");
    for (i = 0; i < 3; i++) {
        double c = OUT.c[i], h = OUT.h[i];
        if (oob & (1 << i)) {
            fz_check_caxis(&OUT, i, 1);
            continue;
        }
        if (!isfinite(c) || !isfinite(h) || !(h >= 0))
            fz_fail("axis %d is in the domain but out c = %a, h = %a (not finite, h >= 0)",
                    i, c, h);
        fz_oends_cbox(k, e, c, h);
        fz_check_corners(k, i, A.m[i], iv, e);
    }
}

static void check_infinite_input(fz_ctx *k)
{
    fz_ival *iv = fz_ivals();
    fz_req *r = fz_reqs();
    fz_ext *e = fz_oends();
    int i;
    if (!fz_ivals_cbox(k, iv, IN.c, IN.h)) return; /* no real point */
    for (i = 0; i < 3; i++) {
        fz_row_req(k, A.m[i], iv, &r[0], &r[1]);
        fz_oends_cbox(k, e, OUT.c[i], OUT.h[i]);
        fz_check_req(i, &r[0], &r[1], e);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in;
    fz_ctx *k = fz_ctx_get();
    cbx_affine a0;
    cbx_cbox in0;
    int i, j;

    in.p = data;
    in.n = size;
    fz_harness = "fuzz_transform_cbox";
    fz_dump_fn = dump;
    CTL = fz_byte(&in);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) A.m[i][j] = fz_double(&in);
    for (j = 0; j < 3; j++) {
        IN.c[j] = fz_double(&in);
        IN.h[j] = fz_double(&in);
    }
    for (j = 0; j < 3; j++) {
        if (CTL & 0x10u) IN.h[j] = 0.0;
        if ((CTL >> j) & 1u) IN.h[j] = fabs(IN.h[j]);
    }
    if (CTL & 0x08u)
        for (i = 0; i < 3; i++)
            A.m[i][3] = -(A.m[i][0] * IN.c[0] + A.m[i][1] * IN.c[1] + A.m[i][2] * IN.c[2]);

    a0 = A;
    in0 = IN;
    if (CTL & 0x40u) { /* in place: the result overwrites IN */
        ST = cbx_transform_cbox(&A, &IN, &IN);
        OUT = IN;
        IN = in0;
        if (memcmp(&a0, &A, sizeof A)) fz_fail("the call modified *a");
    } else {
        for (i = 0; i < 3; i++) OUT.c[i] = OUT.h[i] = fz_fill();
        ST = cbx_transform_cbox(&A, &IN, &OUT);
        if (memcmp(&a0, &A, sizeof A) || memcmp(&in0, &IN, sizeof IN))
            fz_fail("the call modified its inputs");
    }
    fz_check_status_known(ST);
    fz_check_written(OUT.c, 3, "out.c");
    fz_check_written(OUT.h, 3, "out.h");
    if (xu_cbox_has_nan(&A, &IN)) {
        fz_check_status(ST, CBX_EINVAL);
        for (i = 0; i < 3; i++) fz_check_caxis(&OUT, i, 1);
    } else if (all_finite()) {
        check_finite_input(k);
    } else {
        check_infinite_input(k);
    }
    return 0;
}
