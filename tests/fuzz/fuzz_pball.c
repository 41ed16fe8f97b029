/*
 * libFuzzer harness: a ball under a projective map clipped at a near plane
 * (cbx_project_sphere_near, binary64) against the exact oracle of
 * tests/pball_oracle.c.
 *
 * Input: a control byte, then 21 doubles (encoding: fuzz_common.h): the
 * 16 entries of the map, row by row, the center, the radius, then wn.
 * Control bits: 0: row 3 replaced by (0, 0, -1, 0) (a camera looking down
 * -z, W = -z), so that the near plane cuts balls often; 1: the center's z
 * replaced by -|z| (in front of that camera); 2: wn replaced by |wn| (a
 * near plane in front of the camera).
 * Oracle (abort() on failure), for every input, infinities and NaN
 * included: the status is a documented one, every output field written
 * and no NaN, the inputs unchanged, and pbo_judge's exact verdict: the
 * statuses and special outputs, CBX_EMPTY in the domain only for a ball
 * behind the near plane, and with CBX_OK every end against the exact end
 * (its closed form in MPFR) and exact points.
 */
#include "fuzz_common.h"
#include "pball_oracle.h"

static unsigned CTL;
static double V[21], P[4][4], C[3], R, WN;
static cbx_status ST;

static void dump(FILE *f)
{
    fprintf(f, "  control byte = 0x%02x\n", CTL);
    fz_print_vec(f, "  map", &P[0][0], 16);
    fz_print_vec(f, "  center", C, 3);
    fz_print_vec(f, "  radius", &R, 1);
    fz_print_vec(f, "  wn", &WN, 1);
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
    double w[6], c0[3];
    cbx_proj p, p0;
    cbx_box o;
    static pbo_stats S;
    in.p = data;
    in.n = size;
    fz_harness = "fuzz_pball";
    fz_dump_fn = dump;
    CTL = fz_byte(&in);
    for (i = 0; i < 21; i++)
        V[i] = fz_double(&in);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            P[i][j] = V[4 * i + j];
    for (i = 0; i < 3; i++)
        C[i] = V[16 + i];
    R = V[19];
    WN = V[20];
    if (CTL & 1u) {
        P[3][0] = P[3][1] = P[3][3] = 0;
        P[3][2] = -1;
    }
    if (CTL & 2u)
        C[2] = -fabs(C[2]);
    if (CTL & 4u)
        WN = fabs(WN);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            p.m[i][j] = P[i][j];
    for (i = 0; i < 3; i++)
        o.lo[i] = o.hi[i] = fz_fill();
    p0 = p;
    memcpy(c0, C, sizeof c0);
    ST = cbx_project_sphere_near(&p, C, R, WN, &o);
    if (memcmp(&p, &p0, sizeof p) || memcmp(C, c0, sizeof c0))
        fz_fail("an input was changed");
    if (ST != CBX_OK && ST != CBX_EINVAL && ST != CBX_ERANGE && ST != CBX_EMPTY)
        fz_fail("status %d is not a documented value", (int)ST);
    for (i = 0; i < 3; i++) {
        w[2 * i] = o.lo[i];
        w[2 * i + 1] = o.hi[i];
    }
    fz_check_written(w, 6, "output");
    if (S.rng == 0)
        pbo_init(&S, 1);
    pbo_judge((const double (*)[4])P, C, R, WN, ST, &o, &S, on_fail);
    if (S.dist.n > 4096) /* the distances are kept for the tests' summary only */
        S.dist.n = 0;
    return 0;
}
