/*
 * libFuzzer harness: the 2D family (binary64) against the exact oracles.
 *
 * Input: a control byte, then 10 doubles (encoding: fuzz_common.h).  Bits
 * 0..1 of the control byte choose the function and how the doubles are
 * read:
 *   0  cbx_transform_box2: m[0][0..2], m[1][0..2], lo0, hi0, lo1, hi1
 *   1  cbx_transform_cbox2: the map, then c0, h0, c1, h1
 *   2  cbx_disk_box2: the map (the last 4 doubles unused)
 *   3  cbx_ellipse_box2: center[2], radii[2], rot[0][0..1], rot[1][0..1]
 *      (the last 2 unused)
 * bit 2: sort each box axis (swap lo, hi when lo > hi; for the center form
 * h = |h|), so that non-empty boxes are frequent; bit 3: cancellation,
 * t_i = -fl(m_i0 x_0 + m_i1 x_1) at the box's lower corner (or center).
 * Oracle (abort() on failure), for every input, infinities and NaN
 * included:
 *   every function: the status is a documented one, every field of the
 *   output is written, the inputs are unchanged, and the output is bit for
 *   bit the 3D function's on the embedding (the rows with a zero third
 *   column, a zero third row, the third box axis [0, 0]; for the ellipse
 *   the third radius and rotation entries 0) with the same status: the
 *   2D contracts are the 3D ones on that plane (specs/cbx_plane.h), and
 *   the 3D functions have exact harnesses of their own;
 *   box2, independently: exact_util's whole oracle on the embedding
 *   (xu_check_result with the mpq corner checks: status, special outputs,
 *   containment and the proven bound on full rows, vertex and infinite
 *   ends of half-planes and out-of-domain rows);
 *   disk and ellipse, independently: on every axis t -+ sqrt(s) inside the
 *   output, decided exactly on integers (fz_check_ball_axis; s exact).
 */
#include "fuzz_common.h"

static unsigned CTL;
static double V[10];
static cbx_status ST, ST3;

static void dump(FILE *f)
{
    static const char *const fn[4] = { "cbx_transform_box2", "cbx_transform_cbox2",
                                       "cbx_disk_box2", "cbx_ellipse_box2" };
    fprintf(f, "  control byte = 0x%02x: %s\n", CTL, fn[CTL & 3u]);
    fz_print_vec(f, "  inputs", V, 10);
    fz_print_status(f, ST);
    fprintf(f, "  3D function on the embedding: ");
    fz_print_status(f, ST3);
}

/* out (2 axes) equal bit for bit to r (the first 2 axes of the 3D output) */
static void same_bits(const double *o, const double *r, const char *what)
{
    if (memcmp(o, r, 2 * sizeof o[0]))
        fz_fail("%s differs from the 3D function's on the embedding", what);
}

static void run_box2(fz_ctx *k)
{
    cbx_affine2 a, a0;
    cbx_box2 b, b0, o;
    cbx_affine a3;
    cbx_box b3, r3, o3;
    xu_verdict v;
    int i, j;
    memset(&a3, 0, sizeof a3);
    for (i = 0; i < 2; i++) {
        for (j = 0; j < 3; j++) a.m[i][j] = V[3 * i + j];
        b.lo[i] = V[6 + 2 * i];
        b.hi[i] = V[7 + 2 * i];
        if ((CTL & 4u) && b.lo[i] > b.hi[i]) { double t = b.lo[i]; b.lo[i] = b.hi[i]; b.hi[i] = t; }
    }
    if (CTL & 8u)
        for (i = 0; i < 2; i++) a.m[i][2] = -(a.m[i][0] * b.lo[0] + a.m[i][1] * b.lo[1]);
    for (i = 0; i < 2; i++) {
        a3.m[i][0] = a.m[i][0]; a3.m[i][1] = a.m[i][1]; a3.m[i][3] = a.m[i][2];
        b3.lo[i] = b.lo[i]; b3.hi[i] = b.hi[i];
    }
    b3.lo[2] = b3.hi[2] = 0.0;
    a0 = a;
    b0 = b;
    for (i = 0; i < 2; i++) o.lo[i] = o.hi[i] = fz_fill();
    ST = cbx_transform_box2(&a, &b, &o);
    if (memcmp(&a, &a0, sizeof a) || memcmp(&b, &b0, sizeof b)) fz_fail("the call modified its inputs");
    fz_check_status_known(ST);
    fz_check_written(o.lo, 2, "out.lo");
    fz_check_written(o.hi, 2, "out.hi");
    ST3 = cbx_transform_box(&a3, &b3, &r3);
    if (ST != ST3) fz_fail("status differs from the 3D function's on the embedding");
    same_bits(o.lo, r3.lo, "out.lo");
    same_bits(o.hi, r3.hi, "out.hi");
    o3 = r3;
    if (xu_check_result(&k->x, &a3, &b3, &o3, ST, 1, &v)) fz_fail("exact_util: %s", v.why);
}

static void run_cbox2(void)
{
    cbx_affine2 a, a0;
    cbx_cbox2 b, b0, o;
    cbx_affine a3;
    cbx_cbox b3, r3;
    int i, j;
    memset(&a3, 0, sizeof a3);
    memset(&b3, 0, sizeof b3);
    for (i = 0; i < 2; i++) {
        for (j = 0; j < 3; j++) a.m[i][j] = V[3 * i + j];
        b.c[i] = V[6 + 2 * i];
        b.h[i] = (CTL & 4u) ? fabs(V[7 + 2 * i]) : V[7 + 2 * i];
    }
    if (CTL & 8u)
        for (i = 0; i < 2; i++) a.m[i][2] = -(a.m[i][0] * b.c[0] + a.m[i][1] * b.c[1]);
    for (i = 0; i < 2; i++) {
        a3.m[i][0] = a.m[i][0]; a3.m[i][1] = a.m[i][1]; a3.m[i][3] = a.m[i][2];
        b3.c[i] = b.c[i]; b3.h[i] = b.h[i];
    }
    a0 = a;
    b0 = b;
    for (i = 0; i < 2; i++) o.c[i] = o.h[i] = fz_fill();
    ST = cbx_transform_cbox2(&a, &b, &o);
    if (memcmp(&a, &a0, sizeof a) || memcmp(&b, &b0, sizeof b)) fz_fail("the call modified its inputs");
    fz_check_status_known(ST);
    fz_check_written(o.c, 2, "out.c");
    fz_check_written(o.h, 2, "out.h");
    ST3 = cbx_transform_cbox(&a3, &b3, &r3);
    if (ST != ST3) fz_fail("status differs from the 3D function's on the embedding");
    same_bits(o.c, r3.c, "out.c");
    same_bits(o.h, r3.h, "out.h");
}

/* The exact squared norm of (b0, b1), scaled by 2^(2 sh); 1 if infinite. */
static int norm2(fz_ctx *k, double b0, double b1, double d0, double d1, int ell)
{
    double bb[2] = { b0, b1 }, dd[2] = { d0, d1 };
    int j, inf = 0;
    mpz_set_ui(k->s, 0);
    for (j = 0; j < 2; j++) {
        if (isinf(bb[j]) || (ell && isinf(dd[j]))) {
            inf = 1;
            continue;
        }
        xu_scaled_sh(k->z, bb[j], FZ_SH1);
        if (ell) {
            xu_scaled_sh(k->w, dd[j], FZ_SH1);
            mpz_mul(k->z, k->z, k->w);
        }
        mpz_addmul(k->s, k->z, k->z);
    }
    return inf;
}

static void run_ball(fz_ctx *k, int ell)
{
    double lo[2], hi[2], rlo[2], rhi[2];
    int i, nan = 0;
    cbx_box r3;
    for (i = 0; i < (ell ? 8 : 6); i++) nan |= xu_is_nan(V[i]);
    if (!ell) {
        cbx_affine2 a, a0;
        cbx_box2 o;
        cbx_affine a3;
        int j;
        memset(&a3, 0, sizeof a3);
        for (i = 0; i < 2; i++) {
            for (j = 0; j < 3; j++) a.m[i][j] = V[3 * i + j];
            a3.m[i][0] = a.m[i][0]; a3.m[i][1] = a.m[i][1]; a3.m[i][3] = a.m[i][2];
        }
        a0 = a;
        for (i = 0; i < 2; i++) o.lo[i] = o.hi[i] = fz_fill();
        ST = cbx_disk_box2(&a, &o);
        if (memcmp(&a, &a0, sizeof a)) fz_fail("the call modified its input");
        ST3 = cbx_sphere_box(&a3, &r3);
        for (i = 0; i < 2; i++) { lo[i] = o.lo[i]; hi[i] = o.hi[i]; }
    } else {
        double c[2] = { V[0], V[1] }, r[2] = { V[2], V[3] }, R[2][2] = { { V[4], V[5] }, { V[6], V[7] } };
        double c3[3] = { V[0], V[1], 0 }, r3v[3] = { V[2], V[3], 0 };
        double R3[3][3] = { { V[4], V[5], 0 }, { V[6], V[7], 0 }, { 0, 0, 0 } };
        cbx_box2 o;
        for (i = 0; i < 2; i++) o.lo[i] = o.hi[i] = fz_fill();
        ST = cbx_ellipse_box2(c, r, (const double(*)[2])R, &o);
        if (c[0] != V[0] && !(xu_is_nan(c[0]) && xu_is_nan(V[0]))) fz_fail("the call modified its input");
        ST3 = cbx_ellipsoid_box(c3, r3v, (const double(*)[3])R3, &r3);
        for (i = 0; i < 2; i++) { lo[i] = o.lo[i]; hi[i] = o.hi[i]; }
    }
    fz_check_status_known(ST);
    fz_check_written(lo, 2, "out.lo");
    fz_check_written(hi, 2, "out.hi");
    if (ST != ST3) fz_fail("status differs from the 3D function's on the embedding");
    for (i = 0; i < 2; i++) { rlo[i] = r3.lo[i]; rhi[i] = r3.hi[i]; }
    same_bits(lo, rlo, "out.lo");
    same_bits(hi, rhi, "out.hi");
    if (nan) {
        fz_check_status(ST, CBX_EINVAL);
        for (i = 0; i < 2; i++)
            if (!fz_is_ninf(lo[i]) || !fz_is_pinf(hi[i])) fz_fail("NaN input but axis %d not whole", i);
        return;
    }
    for (i = 0; i < 2; i++) {
        int inf = ell ? norm2(k, V[4 + 2 * i], V[5 + 2 * i], V[2], V[3], 1)
                      : norm2(k, V[3 * i], V[3 * i + 1], 0, 0, 0);
        double t = ell ? V[i] : V[3 * i + 2];
        fz_check_ball_axis(k, i, t, k->s, inf, ell ? FZ_SH2 : FZ_SH1, lo[i], hi[i]);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in;
    fz_ctx *k = fz_ctx_get();
    int i;
    in.p = data;
    in.n = size;
    fz_harness = "fuzz_plane";
    fz_dump_fn = dump;
    CTL = fz_byte(&in);
    for (i = 0; i < 10; i++) V[i] = fz_double(&in);
    ST = ST3 = CBX_OK;
    switch (CTL & 3u) {
    case 0: run_box2(k); break;
    case 1: run_cbox2(); break;
    case 2: run_ball(k, 0); break;
    default: run_ball(k, 1); break;
    }
    return 0;
}
