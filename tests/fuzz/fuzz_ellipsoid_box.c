/*
 * libFuzzer harness: cbx_ellipsoid_box against the exact oracle.
 *
 * Input: a control byte, then 3 doubles center[0..2], 3 doubles
 * radii[0..2] and 9 doubles rot[0][0..2], rot[1][0..2], rot[2][0..2]
 * (encoding: fuzz_common.h).  Control bits, applied in this order:
 *   bit 2      rot = the rotation of the quaternion (rot[0][0], rot[0][1],
 *              rot[0][2], rot[1][0]) normalised in binary64 (when its norm
 *              is finite and nonzero): rotations with rounding errors;
 *   bit 0      cancellation: center_i = s * fl(sqrt(sum_j (rot_ij r_j)^2));
 *   bit 1      the sign s: - when set, + otherwise.
 * The exact image on axis i is center_i -+ sqrt(s_i), s_i = sum_j a_ij^2
 * with a_ij = rot[i][j] * radii[j] taken exactly.
 * Oracle (abort() on failure):
 *   always: status documented, every field written, no NaN in out, the
 *     inputs unchanged; NaN input -> CBX_EINVAL and [-inf, +inf]^3;
 *   finite inputs: status decided exactly from the contract (a row with
 *     |rot[i][j]| > 2^254, any |radii[j]| > 2^254 or |center[i]| > 2^1018
 *     -> CBX_ERANGE with that axis [-inf, +inf]); in-domain axes finite,
 *     lo <= hi, and lo <= c - sqrt(s), c + sqrt(s) <= hi decided exactly
 *     on integers (xu_sqrt_lo_ok / xu_sqrt_hi_ok, as in test_sphere);
 *   inputs with infinities: on every row, containment on every finite end
 *     (fz_check_ball_axis: a_ij infinite when one factor is infinite and
 *     the other nonzero, 0 when one factor is zero).
 */
#include "fuzz_common.h"

static double CEN[3], RAD[3], ROT[3][3];
static cbx_box OUT;
static cbx_status ST;
static unsigned CTL;

static void dump(FILE *f)
{
    char lab[16];
    int i;
    fprintf(f, "  control byte = 0x%02x\n", CTL);
    fprintf(f, "  cbx_ellipsoid_box(center, radii, rot, out) with\n");
    fz_print_vec(f, "center", CEN, 3);
    fz_print_vec(f, "radii", RAD, 3);
    for (i = 0; i < 3; i++) {
        snprintf(lab, sizeof lab, "rot[%d]", i);
        fz_print_vec(f, lab, ROT[i], 3);
    }
    fz_print_status(f, ST);
    fz_print_box(f, "out", &OUT);
}

/* k->s = sum_j (rot_ij radii_j 2^2148)^2 over the finite nonzero products;
 * returns 1 when some product is infinite (one factor infinite, the other
 * nonzero) */
static int row_s(fz_ctx *k, int i)
{
    int j, inf = 0;
    mpz_set_ui(k->s, 0);
    for (j = 0; j < 3; j++) {
        double r = ROT[i][j], d = RAD[j];
        if (r == 0 || d == 0) continue;
        if (isinf(r) || isinf(d)) {
            inf = 1;
            continue;
        }
        xu_scaled_mul(&k->x, k->z, r, d);
        mpz_addmul(k->s, k->z, k->z);
    }
    return inf;
}

static int row_in_domain(int i)
{
    int j;
    for (j = 0; j < 3; j++)
        if (!(fabs(ROT[i][j]) <= 0x1p254) || !(fabs(RAD[j]) <= 0x1p254)) return 0;
    return fabs(CEN[i]) <= 0x1p1018;
}

static void quat_rot(void)
{
    double w = ROT[0][0], x = ROT[0][1], y = ROT[0][2], z = ROT[1][0];
    double n = sqrt(w * w + x * x + y * y + z * z);
    if (!(n > 0) || !isfinite(n)) return;
    w /= n; x /= n; y /= n; z /= n;
    ROT[0][0] = 1 - 2 * (y * y + z * z);
    ROT[0][1] = 2 * (x * y - w * z);
    ROT[0][2] = 2 * (x * z + w * y);
    ROT[1][0] = 2 * (x * y + w * z);
    ROT[1][1] = 1 - 2 * (x * x + z * z);
    ROT[1][2] = 2 * (y * z - w * x);
    ROT[2][0] = 2 * (x * z - w * y);
    ROT[2][1] = 2 * (y * z + w * x);
    ROT[2][2] = 1 - 2 * (x * x + y * y);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in;
    fz_ctx *k = fz_ctx_get();
    double c0[3], r0[3], q0[3][3];
    int i, j, nan, fin;

    in.p = data;
    in.n = size;
    fz_harness = "fuzz_ellipsoid_box";
    fz_dump_fn = dump;
    CTL = fz_byte(&in);
    for (i = 0; i < 3; i++) CEN[i] = fz_double(&in);
    for (j = 0; j < 3; j++) RAD[j] = fz_double(&in);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) ROT[i][j] = fz_double(&in);
    if (CTL & 4u) quat_rot();
    if (CTL & 1u)
        for (i = 0; i < 3; i++) {
            double s = 0;
            for (j = 0; j < 3; j++) s += (ROT[i][j] * RAD[j]) * (ROT[i][j] * RAD[j]);
            CEN[i] = (CTL & 2u) ? -sqrt(s) : sqrt(s);
        }

    for (i = 0; i < 3; i++) OUT.lo[i] = OUT.hi[i] = fz_fill();
    memcpy(c0, CEN, sizeof c0);
    memcpy(r0, RAD, sizeof r0);
    memcpy(q0, ROT, sizeof q0);
    /* double[3][3] -> const double (*)[3] needs a cast in ISO C < C2X */
    ST = cbx_ellipsoid_box(CEN, RAD, (const double (*)[3])ROT, &OUT);

    if (memcmp(c0, CEN, sizeof c0) || memcmp(r0, RAD, sizeof r0) || memcmp(q0, ROT, sizeof q0))
        fz_fail("the call modified its inputs");
    fz_check_status_known(ST);
    fz_check_written(OUT.lo, 3, "out.lo");
    fz_check_written(OUT.hi, 3, "out.hi");
    nan = fz_any_nan(CEN, 3) || fz_any_nan(RAD, 3);
    fin = fz_all_finite(CEN, 3) && fz_all_finite(RAD, 3);
    for (i = 0; i < 3; i++) {
        nan |= fz_any_nan(ROT[i], 3);
        fin &= fz_all_finite(ROT[i], 3);
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
            fz_check_ball_axis(k, i, CEN[i], k->s, 0, FZ_SH2, lo, hi);
        }
        return 0;
    }
    for (i = 0; i < 3; i++) {
        int s_inf = row_s(k, i);
        fz_check_ball_axis(k, i, CEN[i], k->s, s_inf, FZ_SH2, OUT.lo[i], OUT.hi[i]);
    }
    return 0;
}
