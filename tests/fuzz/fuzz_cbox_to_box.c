/*
 * libFuzzer harness: cbx_cbox_to_box against the exact oracle.
 *
 * Input: a control byte, then 6 doubles c0, h0, c1, h1, c2, h2 (encoding:
 * fuzz_common.h).  Control bits, applied in this order:
 *   bit 3      points: h_j = 0;
 *   bit 4      cancellation: h_j = |c_j| (one end of the axis exactly 0);
 *   bits 0..2  h_j = |h_j| (non-empty boxes are frequent).
 * The input axis j means the real interval [c_j - h_j, c_j + h_j].
 * Oracle (abort() on failure):
 *   always: status documented, every field written, no NaN in out, the
 *     input unchanged; NaN input -> CBX_EINVAL and [-inf, +inf]^3;
 *   finite inputs: h_j < 0 somewhere -> CBX_EMPTY, lo = +inf, hi = -inf
 *     everywhere; an axis with |c_j| or |h_j| > 2^1019 -> CBX_ERANGE and
 *     that axis [-inf, +inf]; otherwise CBX_OK; in-domain axes finite,
 *     lo <= hi, lo <= c_j - h_j and c_j + h_j <= hi exactly;
 *   inputs with infinities: containment on every finite end only (exact;
 *     see fuzz_common.h).
 */
#include "fuzz_common.h"

static cbx_cbox IN;
static cbx_box OUT;
static cbx_status ST;
static unsigned CTL;

static void dump(FILE *f)
{
    fprintf(f, "  control byte = 0x%02x\n", CTL);
    fprintf(f, "  cbx_cbox_to_box(in, out) with\n");
    fz_print_cbox(f, "in", &IN);
    fz_print_status(f, ST);
    fz_print_box(f, "out", &OUT);
}

static void check_finite_input(fz_ctx *k)
{
    fz_ival *iv = fz_ivals();
    fz_ext *e = fz_oends();
    double m[4];
    int j, oob = 0;

    if (xu_cbox_is_empty(&IN)) {
        fz_check_status(ST, CBX_EMPTY);
        fz_check_box_empty(&OUT);
        return;
    }
    for (j = 0; j < 3; j++)
        if (!fz_in_conv_dom(IN.c[j]) || !fz_in_conv_dom(IN.h[j])) oob |= 1 << j;
    fz_check_status(ST, oob ? CBX_ERANGE : CBX_OK);
    if (!fz_ivals_cbox(k, iv, IN.c, IN.h)) fz_fail("oracle: non-empty cbox read as empty");
    for (j = 0; j < 3; j++) {
        double lo = OUT.lo[j], hi = OUT.hi[j];
        if (oob & (1 << j)) {
            if (!fz_is_ninf(lo) || !fz_is_pinf(hi))
                fz_fail("axis %d is outside the domain but not [-inf, +inf]", j);
            continue;
        }
        if (!isfinite(lo) || !isfinite(hi) || lo > hi)
            fz_fail("axis %d is in the domain but out = [%a, %a] (not finite, ordered)",
                    j, lo, hi);
        fz_unit_row(m, j);
        fz_oends_box(e, lo, hi);
        fz_check_corners(k, j, m, iv, e);
    }
}

static void check_infinite_input(fz_ctx *k)
{
    fz_ival *iv = fz_ivals();
    fz_req *r = fz_reqs();
    fz_ext *e = fz_oends();
    double m[4];
    int j;
    if (!fz_ivals_cbox(k, iv, IN.c, IN.h)) return; /* no real point */
    for (j = 0; j < 3; j++) {
        fz_unit_row(m, j);
        fz_row_req(k, m, iv, &r[0], &r[1]);
        fz_oends_box(e, OUT.lo[j], OUT.hi[j]);
        fz_check_req(j, &r[0], &r[1], e);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in;
    fz_ctx *k = fz_ctx_get();
    cbx_cbox in0;
    int j;

    in.p = data;
    in.n = size;
    fz_harness = "fuzz_cbox_to_box";
    fz_dump_fn = dump;
    CTL = fz_byte(&in);
    for (j = 0; j < 3; j++) {
        IN.c[j] = fz_double(&in);
        IN.h[j] = fz_double(&in);
    }
    for (j = 0; j < 3; j++) {
        if (CTL & 0x08u) IN.h[j] = 0.0;
        if (CTL & 0x10u) IN.h[j] = fabs(IN.c[j]);
        if ((CTL >> j) & 1u) IN.h[j] = fabs(IN.h[j]);
    }

    for (j = 0; j < 3; j++) OUT.lo[j] = OUT.hi[j] = fz_fill();
    in0 = IN;
    ST = cbx_cbox_to_box(&IN, &OUT);

    if (memcmp(&in0, &IN, sizeof IN)) fz_fail("the call modified its input");
    fz_check_status_known(ST);
    fz_check_written(OUT.lo, 3, "out.lo");
    fz_check_written(OUT.hi, 3, "out.hi");
    if (xu_cbox_has_nan(NULL, &IN)) {
        fz_check_status(ST, CBX_EINVAL);
        fz_check_box_whole(&OUT);
    } else if (fz_all_finite(IN.c, 3) && fz_all_finite(IN.h, 3)) {
        check_finite_input(k);
    } else {
        check_infinite_input(k);
    }
    return 0;
}
