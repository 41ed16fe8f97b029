/*
 * libFuzzer harness: a box under a projective map clipped at a near plane
 * (cbx_project_box_near, binary64) against the exact oracle of
 * tests/pnear_oracle.c.
 *
 * Input: a control byte, then 23 doubles (encoding: fuzz_common.h): the
 * 16 entries of the map, row by row, the box's lo[0], hi[0], lo[1], hi[1],
 * lo[2], hi[2], then wn.
 * Control bits: 0: row 3 replaced by (0, 0, -1, 0) (a camera looking down
 * -z, W = -z), so that the near plane cuts boxes often; 1: each box axis
 * ordered (lo and hi swapped when lo > hi), so that CBX_EMPTY is rare;
 * 2: wn replaced by |wn| (a near plane in front of the camera).
 * Oracle (abort() on failure), for every input, infinities and NaN
 * included: the status is a documented one, every output field written
 * and no NaN, the inputs unchanged, and pno_judge's exact verdict: the
 * statuses and special outputs, CBX_EMPTY in the domain only for a box
 * behind the near plane, and with CBX_OK every end against the exact end
 * (the clipped box's vertices, in rationals) and exact points.
 */
#include "fuzz_common.h"
#include "pnear_oracle.h"

static unsigned CTL;
static double V[23], P[4][4], WN;
static cbx_box B;
static cbx_status ST;

static void dump(FILE *f)
{
    fprintf(f, "  control byte = 0x%02x\n", CTL);
    fz_print_vec(f, "  map", &P[0][0], 16);
    fz_print_vec(f, "  box lo", B.lo, 3);
    fz_print_vec(f, "  box hi", B.hi, 3);
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
    double w[6];
    cbx_proj p, p0;
    cbx_box o, b0;
    static pno_stats S;
    in.p = data;
    in.n = size;
    fz_harness = "fuzz_pnear";
    fz_dump_fn = dump;
    CTL = fz_byte(&in);
    for (i = 0; i < 23; i++)
        V[i] = fz_double(&in);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            P[i][j] = V[4 * i + j];
    for (i = 0; i < 3; i++) {
        B.lo[i] = V[16 + 2 * i];
        B.hi[i] = V[17 + 2 * i];
        if ((CTL & 2u) && B.lo[i] > B.hi[i]) {
            double t = B.lo[i];
            B.lo[i] = B.hi[i];
            B.hi[i] = t;
        }
    }
    WN = V[22];
    if (CTL & 1u) {
        P[3][0] = P[3][1] = P[3][3] = 0;
        P[3][2] = -1;
    }
    if (CTL & 4u)
        WN = fabs(WN);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            p.m[i][j] = P[i][j];
    for (i = 0; i < 3; i++)
        o.lo[i] = o.hi[i] = fz_fill();
    p0 = p;
    b0 = B;
    ST = cbx_project_box_near(&p, &B, WN, &o);
    if (memcmp(&p, &p0, sizeof p) || memcmp(&B, &b0, sizeof B))
        fz_fail("an input was changed");
    if (ST != CBX_OK && ST != CBX_EINVAL && ST != CBX_ERANGE && ST != CBX_EMPTY)
        fz_fail("status %d is not a documented value", (int)ST);
    for (i = 0; i < 3; i++) {
        w[2 * i] = o.lo[i];
        w[2 * i + 1] = o.hi[i];
    }
    fz_check_written(w, 6, "output");
    if (S.rng == 0)
        pno_init(&S, 1);
    pno_judge((const double (*)[4])P, &B, WN, ST, &o, &S, on_fail);
    if (S.dist.n > 4096) /* the distances are kept for the tests' summary only */
        S.dist.n = 0;
    return 0;
}
