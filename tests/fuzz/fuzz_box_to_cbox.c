/*
 * libFuzzer harness: cbx_box_to_cbox against the exact oracle.
 *
 * Input: a control byte, then 6 doubles lo0, hi0, lo1, hi1, lo2, hi2
 * (encoding: fuzz_common.h).  Control bits, applied in this order:
 *   bit 3      point box: hi_j = lo_j;
 *   bit 4      one-ulp box: hi_j = nextafter(lo_j, +inf);
 *   bits 0..2  sort axis j (swap when lo_j > hi_j).
 * Output axis j means the real interval [c_j - h_j, c_j + h_j].
 * Oracle (abort() on failure):
 *   always: status documented, every field written, no NaN in out, the
 *     input unchanged; NaN input -> CBX_EINVAL, c = 0, h = +inf everywhere;
 *   every other input: an axis with no real point (lo_j > hi_j,
 *     lo_j = +inf or hi_j = -inf) -> CBX_EMPTY, c = 0, h = -inf
 *     everywhere; an axis with an infinite end or |lo_j| or |hi_j| > 2^1019
 *     -> CBX_ERANGE and that axis c = 0, h = +inf; otherwise CBX_OK;
 *     in-domain axes: c, h finite, h >= 0 and c - h <= lo_j, hi_j <= c + h
 *     exactly;
 *   inputs with infinities, in addition: the extended-real requirements
 *     of fuzz_common.h (fz_row_req) on every end.
 */
#include "fuzz_common.h"

static cbx_box IN;
static cbx_cbox OUT;
static cbx_status ST;
static unsigned CTL;

static void dump(FILE *f)
{
    fprintf(f, "  control byte = 0x%02x\n", CTL);
    fprintf(f, "  cbx_box_to_cbox(in, out) with\n");
    fz_print_box(f, "in", &IN);
    fz_print_status(f, ST);
    fz_print_cbox(f, "out", &OUT);
}

static void check_input(fz_ctx *k)
{
    fz_ival *iv = fz_ivals();
    fz_ext *e = fz_oends();
    double m[4];
    int j, oob = 0;

    if (xu_is_empty(&IN)) {
        fz_check_status(ST, CBX_EMPTY);
        for (j = 0; j < 3; j++) fz_check_caxis(&OUT, j, 0);
        return;
    }
    for (j = 0; j < 3; j++)
        if (!fz_in_conv_dom(IN.lo[j]) || !fz_in_conv_dom(IN.hi[j])) oob |= 1 << j;
    fz_check_status(ST, oob ? CBX_ERANGE : CBX_OK);
    if (!fz_ivals_box(iv, IN.lo, IN.hi)) fz_fail("oracle: non-empty box read as empty");
    for (j = 0; j < 3; j++) {
        double c = OUT.c[j], h = OUT.h[j];
        if (oob & (1 << j)) {
            fz_check_caxis(&OUT, j, 1);
            continue;
        }
        if (!isfinite(c) || !isfinite(h) || !(h >= 0))
            fz_fail("axis %d is in the domain but out c = %a, h = %a (not finite, h >= 0)",
                    j, c, h);
        fz_unit_row(m, j);
        fz_oends_cbox(k, e, c, h);
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
    if (!fz_ivals_box(iv, IN.lo, IN.hi)) return; /* empty real box */
    for (j = 0; j < 3; j++) {
        fz_unit_row(m, j);
        fz_row_req(k, m, iv, &r[0], &r[1]);
        fz_oends_cbox(k, e, OUT.c[j], OUT.h[j]);
        fz_check_req(j, &r[0], &r[1], e);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in;
    fz_ctx *k = fz_ctx_get();
    cbx_box in0;
    int j;

    in.p = data;
    in.n = size;
    fz_harness = "fuzz_box_to_cbox";
    fz_dump_fn = dump;
    CTL = fz_byte(&in);
    for (j = 0; j < 3; j++) {
        IN.lo[j] = fz_double(&in);
        IN.hi[j] = fz_double(&in);
    }
    for (j = 0; j < 3; j++) {
        if (CTL & 0x08u) IN.hi[j] = IN.lo[j];
        if (CTL & 0x10u) IN.hi[j] = nextafter(IN.lo[j], HUGE_VAL);
        if ((CTL >> j) & 1u && IN.lo[j] > IN.hi[j]) {
            double t = IN.lo[j];
            IN.lo[j] = IN.hi[j];
            IN.hi[j] = t;
        }
    }

    for (j = 0; j < 3; j++) OUT.c[j] = OUT.h[j] = fz_fill();
    in0 = IN;
    ST = cbx_box_to_cbox(&IN, &OUT);

    if (memcmp(&in0, &IN, sizeof IN)) fz_fail("the call modified its input");
    fz_check_status_known(ST);
    fz_check_written(OUT.c, 3, "out.c");
    fz_check_written(OUT.h, 3, "out.h");
    if (fz_any_nan(IN.lo, 3) || fz_any_nan(IN.hi, 3)) {
        fz_check_status(ST, CBX_EINVAL);
        for (j = 0; j < 3; j++) fz_check_caxis(&OUT, j, 1);
    } else {
        check_input(k);
        if (!fz_all_finite(IN.lo, 3) || !fz_all_finite(IN.hi, 3)) check_infinite_input(k);
    }
    return 0;
}
