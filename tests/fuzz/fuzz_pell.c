/*
 * libFuzzer harness: an ellipsoid under a projective map
 * (cbx_project_ellipsoid, binary64) against the exact oracle of
 * tests/psph_oracle.c (pso_judge_ell).
 *
 * Input: a control byte, then 31 doubles (encoding: fuzz_common.h): the
 * 16 entries of the map, row by row, the center c0, c1, c2, the radii
 * s0, s1, s2, and rot's 9 entries, row by row.
 * Control bits: 0: W clear of the camera plane, row 3 replaced by
 * (0, 0, 0, |m33|) when m33 is finite and nonzero (a camera at infinity),
 * so that CBX_OK is frequent; 1: the center moved in front of a camera
 * looking down -z (c2 = -|c2| - 2 (|s0| + |s1| + |s2|) (|rot| + 1) - 1
 * when finite), with row 3 (0, 0, -1, 0); 2: rot replaced by the
 * identity (an axis-aligned ellipsoid).
 * Oracle (abort() on failure), for every input, infinities and NaN
 * included: the status is a documented one, every output field written
 * and no NaN, the inputs unchanged, the radii negated give the same
 * status and bits, and pso_judge_ell's exact verdict: the statuses and
 * special outputs, CBX_EBEHIND only near the camera plane, and with CBX_OK
 * every end against its exact value (MPFR) and 8 exact points of the
 * ellipsoid.
 */
#include "fuzz_common.h"
#include "psph_oracle.h"

static unsigned CTL;
static double V[31], P[4][4], C[3], RAD[3], ROT[3][3];
static cbx_status ST;

static void dump(FILE *f)
{
    fprintf(f, "  control byte = 0x%02x\n", CTL);
    fz_print_vec(f, "  map", &P[0][0], 16);
    fz_print_vec(f, "  c", C, 3);
    fz_print_vec(f, "  radii", RAD, 3);
    fz_print_vec(f, "  rot", &ROT[0][0], 9);
    fz_print_status(f, ST);
}

static void on_fail(const char *what)
{
    fz_fail("%s", what);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in;
    int i, j;
    double w[6], c0[3], s0[3], r0[3][3], neg[3];
    cbx_proj p, p0;
    cbx_box o, o2;
    cbx_status st2;
    static pso_stats S;
    in.p = data;
    in.n = size;
    fz_harness = "fuzz_pell";
    fz_dump_fn = dump;
    CTL = fz_byte(&in);
    for (i = 0; i < 31; i++)
        V[i] = fz_double(&in);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            P[i][j] = V[4 * i + j];
    for (i = 0; i < 3; i++) {
        C[i] = V[16 + i];
        RAD[i] = V[19 + i];
        for (j = 0; j < 3; j++)
            ROT[i][j] = (CTL & 4u) ? (double)(i == j) : V[22 + 3 * i + j];
    }
    if ((CTL & 1u) && isfinite(P[3][3]) && P[3][3] != 0) {
        P[3][0] = P[3][1] = P[3][2] = 0;
        P[3][3] = fabs(P[3][3]);
    }
    if (CTL & 2u) {
        double m = 1;
        for (i = 0; i < 3; i++)
            for (j = 0; j < 3; j++)
                m += fabs(ROT[i][j]);
        m *= 2 * (fabs(RAD[0]) + fabs(RAD[1]) + fabs(RAD[2]));
        if (isfinite(C[2]) && isfinite(m)) {
            C[2] = -fabs(C[2]) - m - 1;
            P[3][0] = P[3][1] = P[3][3] = 0;
            P[3][2] = -1;
        }
    }
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            p.m[i][j] = P[i][j];
    for (i = 0; i < 3; i++) {
        o.lo[i] = o.hi[i] = fz_fill();
        c0[i] = C[i];
        s0[i] = RAD[i];
        neg[i] = -RAD[i];
        for (j = 0; j < 3; j++)
            r0[i][j] = ROT[i][j];
    }
    p0 = p;
    ST = cbx_project_ellipsoid(&p, C, RAD, (const double (*)[3])ROT, &o);
    if (memcmp(&p, &p0, sizeof p) || memcmp(C, c0, sizeof c0) || memcmp(RAD, s0, sizeof s0)
        || memcmp(ROT, r0, sizeof r0))
        fz_fail("an input was changed");
    if (ST != CBX_OK && ST != CBX_EINVAL && ST != CBX_ERANGE && ST != CBX_EBEHIND)
        fz_fail("status %d is not a documented value", (int)ST);
    for (i = 0; i < 3; i++) {
        w[2 * i] = o.lo[i];
        w[2 * i + 1] = o.hi[i];
    }
    fz_check_written(w, 6, "output");
    st2 = cbx_project_ellipsoid(&p, C, neg, (const double (*)[3])ROT, &o2);
    if (st2 != ST || memcmp(&o2, &o, sizeof o))
        fz_fail("the radii negated (the same ellipsoid) give another status or other bits");
    if (S.rng == 0)
        pso_init(&S, 1);
    pso_judge_ell((const double (*)[4])P, C, RAD, (const double (*)[3])ROT, ST, &o, &S, on_fail);
    if (S.dist.n > 4096) /* the distances are kept for the tests' summary only */
        S.dist.n = 0;
    return 0;
}
