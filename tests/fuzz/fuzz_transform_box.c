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
 *   every other input, infinities included: exact_util's checks
 *     (xu_check_result, with the mpq corner checks): status ==
 *     xu_expected_status; EMPTY (hi < lo, lo = +inf or hi = -inf) ->
 *     lo = +inf, hi = -inf; full rows (rule A) finite, containing the exact
 *     image (fixed point and mpq corners), within 12 u S + 2^-1065; other
 *     rows with a finite map (rule B: half-spaces, boxes outside the
 *     domain) end by end: exactly -inf / +inf where the image is unbounded
 *     or the vertex is outside the domain, else finite, containing the
 *     exact vertex value and within 12 u S_v + 2^-1065; rows with an
 *     infinite map entry (rule C) [-inf, +inf];
 *   and, independently of exact_util's vertex rule, fuzz_common.h's
 *     extended-real requirements (fz_row_req: an end must be infinite where
 *     the exact image is unbounded, else contain its exact inf / sup) on
 *     every end; for finite map rows the kind (unbounded or not) and the
 *     exact inf / sup must also agree with the vertex rule; on full rows
 *     the 8 corners once more (fz_check_corners).
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

static int box_has_nan(void) { return xu_has_nan(&A, &IN); }

static void check_result(fz_ctx *k)
{
    xu_verdict v;
    fz_ival *iv = fz_ivals();
    fz_req *r = fz_reqs();
    fz_ext *e = fz_oends();
    int i, upper;

    if (xu_check_result(&k->x, &A, &IN, &OUT, ST, 1, &v))
        fz_fail("exact_util: %s", v.why);
    if (v.expected == CBX_EMPTY) {
        if (fz_ivals_box(iv, IN.lo, IN.hi)) fz_fail("oracles disagree: EMPTY box with a point");
        return;
    }
    if (!fz_ivals_box(iv, IN.lo, IN.hi)) fz_fail("oracles disagree: non-empty box read as empty");
    for (i = 0; i < 3; i++) {
        fz_row_req(k, A.m[i], iv, &r[0], &r[1]);
        fz_oends_box(e, OUT.lo[i], OUT.hi[i]);
        fz_check_req(i, &r[0], &r[1], e);
        if (!xu_map_row_finite(&A, i)) continue;
        for (upper = 0; upper < 2; upper++) {
            int kind = xu_end_kind(&A, &IN, i, upper);
            int unb = r[upper].kind == FZ_REQ_INF;
            if (r[upper].kind == FZ_REQ_NONE)
                fz_fail("axis %d: finite map row but no requirement on an end", i);
            if (unb != (kind == XU_END_UNB))
                fz_fail("axis %d: fz_row_req says %s on the %s side, exact_util says %c", i,
                        unb ? "unbounded" : "bounded", upper ? "upper" : "lower",
                        xu_end_char[kind]);
            if (kind == XU_END_VERTEX) {
                xu_vertex_bounds(&k->x, &A, &IN, i, upper);
                if (mpz_cmp(upper ? k->x.H : k->x.L, r[upper].v) != 0)
                    fz_fail("axis %d: vertex value != fz_row_req's exact %s", i,
                            upper ? "sup" : "inf");
            }
        }
        if (xu_end_kind(&A, &IN, i, 0) == XU_END_FULL) fz_check_corners(k, i, A.m[i], iv, e);
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
    } else {
        check_result(k);
    }
    return 0;
}
