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
 *   every other input, infinities included: the status equals
 *     xu_cbox_expected_status (exact_util.h: h < 0 somewhere -> EMPTY with
 *     c = 0, h = -inf; else per output axis A full row, D full once the
 *     zero-coefficient columns are dropped, W lost; ERANGE iff some axis is
 *     W); W axes exactly c = 0, h = +inf; A and D axes finite with h' >= 0,
 *     the 8 exact corner images t_i + sum_j m_ij (c_j' -+ h_j') inside
 *     [c' - h', c' + h'] (exact; c_j' = h_j' = 0 where m_ij == 0, also
 *     -0.0, for D; the input itself for A), and each end within
 *     12 u S' + 2^-1065 of the exact end, S' = |t| + sum_j |m_ij c_j'| +
 *     |m_ij h_j'| (cbox_tight of specs/cbx_spec.h on the dropped row);
 *   and, independently of exact_util's kinds, fuzz_common.h's extended-real
 *     requirements (fz_row_req) on every axis whose input box has a real
 *     point: an A or D axis must have a bounded exact image there, and
 *     every finite end must contain it.
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

/* cbox_tight on box d (all finite): with C = t + sum m_j c_j,
 * H = sum |m_j h_j|, S' = |t| + sum |m_j c_j| + H (all scaled by 2^FZ_SH2,
 * integers): (oc - oh) >= C - H - tol and (oc + oh) <= C + H + tol,
 * tol = 12 u S' + 2^-1065, decided as 2^53 gap >= -(12 S' + 2^(FZ_SH2 -
 * 1065 + 53)). */
static void check_tight(fz_ctx *k, int i, const double m[4], const cbx_cbox *d,
                        double oc, double oh)
{
    static mpz_t C, H, S, g, tol;
    static int init;
    int j, sg;
    if (!init) {
        mpz_inits(C, H, S, g, tol, (mpz_ptr)0);
        init = 1;
    }
    xu_scaled_sh(C, m[3], FZ_SH2);
    mpz_abs(S, C);
    mpz_set_ui(H, 0);
    for (j = 0; j < 3; j++) {
        xu_scaled_mul(&k->x, k->z, m[j], d->c[j]);
        mpz_add(C, C, k->z);
        mpz_abs(k->z, k->z);
        mpz_add(S, S, k->z);
        xu_scaled_mul(&k->x, k->z, m[j], d->h[j]);
        mpz_abs(k->z, k->z);
        mpz_add(H, H, k->z);
    }
    mpz_add(S, S, H);
    mpz_set_ui(tol, 1);
    mpz_mul_2exp(tol, tol, FZ_SH2 - 1065 + 53);
    mpz_addmul_ui(tol, S, 12);
    mpz_neg(tol, tol);
    /* lower (sg = -1): (oc - oh) - (C - H);  upper (sg = +1): (C + H) - (oc + oh) */
    for (sg = -1; sg <= 1; sg += 2) {
        xu_scaled_sh(g, oc, FZ_SH2);
        xu_scaled_sh(k->w, oh, FZ_SH2);
        if (sg < 0) {
            mpz_sub(g, g, k->w);
            mpz_sub(g, g, C);
        } else {
            mpz_add(g, g, k->w);
            mpz_sub(g, C, g);
        }
        mpz_add(g, g, H);
        mpz_mul_2exp(g, g, 53);
        if (mpz_cmp(g, tol) < 0)
            fz_fail("axis %d: %s end beyond 12 u S' + 2^-1065 of the exact end (cbox_tight)", i,
                    sg < 0 ? "lower" : "upper");
    }
}

static void check_result(fz_ctx *k)
{
    fz_ival *iv = fz_ivals();
    fz_req *r = fz_reqs();
    fz_ext *e = fz_oends();
    int i, kind[3];
    cbx_status want = xu_cbox_expected_status(&A, &IN);

    fz_check_status(ST, want);
    if (want == CBX_EMPTY) {
        for (i = 0; i < 3; i++) fz_check_caxis(&OUT, i, 0);
        return;
    }
    for (i = 0; i < 3; i++) {
        double c = OUT.c[i], h = OUT.h[i];
        cbx_cbox d;
        kind[i] = xu_cbox_axis_kind(&A, &IN, i);
        if (kind[i] == XU_CAX_LOST) {
            fz_check_caxis(&OUT, i, 1);
            continue;
        }
        if (!isfinite(c) || !isfinite(h) || !(h >= 0))
            fz_fail("axis %d is of kind %c but out c = %a, h = %a (not finite, h >= 0)",
                    i, xu_cax_char[kind[i]], c, h);
        xu_cbox_dropped(&A, &IN, i, &d); /* kind A: the input itself */
        if (!fz_ivals_cbox(k, iv, d.c, d.h))
            fz_fail("oracle: axis %d: the (dropped) box of an A / D row read as empty", i);
        fz_oends_cbox(k, e, c, h);
        fz_check_corners(k, i, A.m[i], iv, e);
        check_tight(k, i, A.m[i], &d, c, h);
    }
    /* independent of exact_util's kinds: the extended-real reading */
    if (!fz_ivals_cbox(k, iv, IN.c, IN.h)) return; /* no real point */
    for (i = 0; i < 3; i++) {
        fz_row_req(k, A.m[i], iv, &r[0], &r[1]);
        if (kind[i] != XU_CAX_LOST && (r[0].kind != FZ_REQ_BOUND || r[1].kind != FZ_REQ_BOUND))
            fz_fail("oracles disagree: axis %d of kind %c but its exact image is not bounded",
                    i, xu_cax_char[kind[i]]);
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
    } else {
        check_result(k);
    }
    return 0;
}
