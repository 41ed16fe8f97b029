/*
 * libFuzzer harness: the projective bound (cbx_project_box, binary64, and
 * cbx_project_boxf, binary32) against the exact oracle of
 * tests/proj_oracle.c.
 *
 * Input: a control byte, then 22 doubles (encoding: fuzz_common.h): the
 * 16 entries of the map, row by row, then lo0, hi0, lo1, hi1, lo2, hi2.
 * Control bits: 0: binary32 (every value rounded to float first);
 * 1: sort each box axis (swap lo, hi when lo > hi), so that non-empty
 * boxes are frequent; 2: W clear of the camera plane, row 3 replaced by
 * (0, 0, 0, |m33|) when m33 is finite and nonzero (a camera at infinity:
 * every quotient exists), so that CBX_OK is frequent.
 * Oracle (abort() on failure), for every input, infinities and NaN
 * included: the status is a documented one, every output field written
 * and no NaN, the inputs unchanged, out == in gives the same bits, and
 * po_judge's exact verdict: the statuses and special outputs, proj_ok =>
 * CBX_OK, CBX_EBEHIND only when a corner is not clear, and with CBX_OK
 * W > 0 and lo W <= X <= hi W at the 8 corners and 2 random points, the
 * proven tightness at some corner.
 */
#include "fuzz_common.h"
#include "proj_oracle.h"

static unsigned CTL;
static double V[22], P[4][4], L[3], H[3];
static cbx_status ST;

static void dump(FILE *f)
{
    fprintf(f, "  control byte = 0x%02x: %s\n", CTL, (CTL & 1u) ? "cbx_project_boxf" : "cbx_project_box");
    fz_print_vec(f, "  map", &P[0][0], 16);
    fz_print_vec(f, "  lo", L, 3);
    fz_print_vec(f, "  hi", H, 3);
    fz_print_status(f, ST);
}

static void on_fail(const char *what)
{
    fz_fail("%s", what);
}

/* One call in one format (FP, PROJ, BOX, FN): the map and box from P, L,
 * H, the output prefilled, the inputs checked unchanged; the output ends
 * in olo, ohi. */
#define CALL_ONE(FP, PROJ, BOX, FN) do {                                 \
        PROJ p, p0;                                                      \
        BOX b, b0, o;                                                    \
        for (i = 0; i < 4; i++)                                          \
            for (j = 0; j < 4; j++)                                      \
                p.m[i][j] = (FP)P[i][j];                                 \
        for (i = 0; i < 3; i++) {                                        \
            b.lo[i] = (FP)L[i];                                          \
            b.hi[i] = (FP)H[i];                                          \
            o.lo[i] = o.hi[i] = (FP)fz_fill();                           \
        }                                                                \
        p0 = p;                                                          \
        b0 = b;                                                          \
        st = in_place ? FN(&p, &b, &b) : FN(&p, &b, &o);                 \
        if (memcmp(&p, &p0, sizeof p))                                   \
            fz_fail("the map was changed");                              \
        if (in_place)                                                    \
            o = b;                                                       \
        else if (memcmp(&b, &b0, sizeof b))                              \
            fz_fail("the input box was changed");                        \
        for (i = 0; i < 3; i++) {                                        \
            olo[i] = o.lo[i];                                            \
            ohi[i] = o.hi[i];                                            \
        }                                                                \
    } while (0)

static cbx_status call(int is32, int in_place, double olo[3], double ohi[3])
{
    int i, j;
    cbx_status st;
    if (!is32)
        CALL_ONE(double, cbx_proj, cbx_box, cbx_project_box);
    else
        CALL_ONE(float, cbx_projf, cbx_boxf, cbx_project_boxf);
    return st;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in;
    int i, j, is32;
    double olo[3], ohi[3], ilo[3], ihi[3], w[6];
    cbx_status st2;
    static po_stats S;
    in.p = data;
    in.n = size;
    fz_harness = "fuzz_project";
    fz_dump_fn = dump;
    CTL = fz_byte(&in);
    for (i = 0; i < 22; i++)
        V[i] = fz_double(&in);
    is32 = (int)(CTL & 1u);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            P[i][j] = is32 ? (double)(float)V[4 * i + j] : V[4 * i + j];
    for (i = 0; i < 3; i++) {
        L[i] = is32 ? (double)(float)V[16 + 2 * i] : V[16 + 2 * i];
        H[i] = is32 ? (double)(float)V[17 + 2 * i] : V[17 + 2 * i];
        if ((CTL & 2u) && H[i] < L[i]) {
            double t = L[i];
            L[i] = H[i];
            H[i] = t;
        }
    }
    if ((CTL & 4u) && isfinite(P[3][3]) && P[3][3] != 0) {
        P[3][0] = P[3][1] = P[3][2] = 0;
        P[3][3] = fabs(P[3][3]);
    }
    ST = call(is32, 0, olo, ohi);
    if (ST != CBX_OK && ST != CBX_EMPTY && ST != CBX_EINVAL && ST != CBX_ERANGE && ST != CBX_EBEHIND)
        fz_fail("status %d is not a documented value", (int)ST);
    for (i = 0; i < 3; i++) {
        w[2 * i] = olo[i];
        w[2 * i + 1] = ohi[i];
    }
    fz_check_written(w, 6, "output");
    st2 = call(is32, 1, ilo, ihi);
    if (st2 != ST || memcmp(ilo, olo, sizeof olo) || memcmp(ihi, ohi, sizeof ohi))
        fz_fail("out == in gives other bits");
    S.npoints = 2;
    S.rng = 1;
    po_judge((const double (*)[4])P, L, H, is32, ST, olo, ohi, &S, on_fail);
    return 0;
}
