/*
 * libFuzzer harness: the binary32 twins of the binary64-only projective
 * bounds (cbx_project_spheref, cbx_project_box_nearf,
 * cbx_project_sphere_nearf, cbx_project_ellipsoidf; src/f32/cbx_pwide.c) against the binary64
 * functions on the widened inputs and the exact oracles of
 * tests/psph_oracle.c, pnear_oracle.c and pball_oracle.c, as
 * tests/test_pwide.c judges them.
 *
 * Input: a control byte, then floats, 4 bytes each (little-endian IEEE-754
 * binary32, any bit pattern: NaN, infinities, subnormals; a missing byte
 * reads as 0): the 16 entries of the map, row by row, then
 *   spheref (control & 3 = 0 or 3): c0, c1, c2, r (20 floats);
 *   box_nearf (1): lo[0], hi[0], lo[1], hi[1], lo[2], hi[2], wn (23 floats);
 *   sphere_nearf (2): c0, c1, c2, r, wn (21 floats);
 *   ellipsoidf (control bit 7, whatever bits 0-1): c0, c1, c2, the three
 *     radii, rot row by row (31 floats).
 * Control bits 0-1: the twin (above; bit 7 the ellipsoid).  Toward CBX_OK: 2: row 3 replaced by
 * (0, 0, -1, 0) (a camera looking down -z, W = -z); 3: the sphere twins:
 * the center's z moved in front of that camera (spheref: -|z| - 2 |r| - 1,
 * sphere_nearf: -|z|, ellipsoidf: -|z| - 2 (|s0| + |s1| + |s2|) - 1, in
 * float), box_nearf: each box axis ordered (lo and
 * hi swapped when lo > hi); 4: wn replaced by |wn|; 5: every finite
 * nonzero float's binary exponent (frexpf's) folded modulo 16 into
 * [-8, 7] (unchanged there; significand and sign kept), applied first, so
 * that the case is in the domain; 6: row 3 replaced by
 * (0, 0, 0, |m33|) when m33 is finite and nonzero (a camera at infinity;
 * after bit 2).
 * Oracle (abort() on failure, the decoded input shown), for every input:
 *   - the status is a documented one of the twin; every output field
 *     written (the pre-fill NaN gone) and no NaN; the inputs unchanged
 *     (bits);
 *   - the status is the binary64 function's on the widened inputs, and the
 *     twins' table: NaN -> CBX_EINVAL; else (box_nearf) an empty float box
 *     (hi < lo, lo = +inf or hi = -inf) -> CBX_EMPTY; else an infinite
 *     input -> CBX_ERANGE;
 *   - every status but CBX_OK gives the whole space (-inf, +inf), CBX_EMPTY
 *     the empty box (lo = +inf, hi = -inf);
 *   - with CBX_OK: every end finite, lo_f <= lo_d and hi_d <= hi_f, each
 *     within 2^-22 |end_d| + 2^-147 of the binary64 end (GMP rationals);
 *   - the exact oracle's verdict on the float result widened (its status
 *     rules, containment against the exact ends and at exact points), its
 *     binary64 tightness test at 2^-20 (1 + |end|) replaced, as in
 *     test_pwide, by the twins' 2^-19 (1 + |end|) on each end's distance to
 *     the exact end;
 *   - the same bits for the same set: box_nearf with out == in, the sphere
 *     twins with radius -r, the ellipsoid with rot's columns and the radii
 *     negated.
 */
#include "fuzz_common.h"
#include "psph_oracle.h"
#include "pnear_oracle.h"
#include "pball_oracle.h"

enum { FN_SPH, FN_NEAR, FN_BALL, FN_ELL };
static const char *const fn_name[4] = {"cbx_project_spheref", "cbx_project_box_nearf",
                                       "cbx_project_sphere_nearf", "cbx_project_ellipsoidf"};

#define PW_FILL_BITS UINT32_C(0x7fc0f00d) /* the output's pre-fill: a NaN */

static unsigned CTL;
static int FN, NV;
static float V[31];
static cbx_projf PF;
static float CF[3], RF, WF, EF[3], QF[3][3];
static cbx_boxf BF, OF;
static cbx_status SF, SD = (cbx_status)-1;
/* the float case widened (what the binary64 function and the oracles see),
 * and the binary64 result */
static double PD[4][4], CD[3], RD, WD, ED[3], QD[3][3];
static cbx_box BD, OD;
static pso_stats Ss;
static pno_stats Sn;
static pbo_stats Sb;
static pso_stats Se;

static uint32_t f_bits(float x)
{
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static float f_from_bits(uint32_t u)
{
    float x;
    memcpy(&x, &u, sizeof x);
    return x;
}

static int f_nan(float x) { return x != x; }
static int f_inf(float x) { return x == (float)INFINITY || x == -(float)INFINITY; }

static void print_f(FILE *f, const char *label, const float *v, int n)
{
    int k;
    fprintf(f, "  %s = {", label);
    for (k = 0; k < n; k++)
        fprintf(f, "%s%a (0x%08lx)", k ? ", " : "", (double)v[k], (unsigned long)f_bits(v[k]));
    fprintf(f, "}\n");
}

static void dump(FILE *f)
{
    int i;
    fprintf(f, "  control byte = 0x%02x: %s\n", CTL, fn_name[FN]);
    print_f(f, "raw floats", V, NV);
    for (i = 0; i < 4; i++) {
        char lab[16];
        snprintf(lab, sizeof lab, "map row %d", i);
        print_f(f, lab, PF.m[i], 4);
    }
    if (FN == FN_NEAR) {
        print_f(f, "box lo", BF.lo, 3);
        print_f(f, "box hi", BF.hi, 3);
    } else if (FN == FN_ELL) {
        print_f(f, "center", CF, 3);
        print_f(f, "radii", EF, 3);
        for (i = 0; i < 3; i++)
            print_f(f, "rot row", QF[i], 3);
    } else {
        print_f(f, "center", CF, 3);
        print_f(f, "radius", &RF, 1);
    }
    if (FN == FN_NEAR || FN == FN_BALL)
        print_f(f, "wn", &WF, 1);
    fprintf(f, "  twin status = %s (%d)\n", cbx_status_name(SF), (int)SF);
    print_f(f, "out lo", OF.lo, 3);
    print_f(f, "out hi", OF.hi, 3);
    if ((int)SD >= 0) {
        fprintf(f, "  binary64 status = %s (%d)\n", cbx_status_name(SD), (int)SD);
        fz_print_vec(f, "binary64 lo", OD.lo, 3);
        fz_print_vec(f, "binary64 hi", OD.hi, 3);
    }
}

/* the oracles' failures; their binary64 tightness test (2^-20 (1 + |end|))
 * is replaced by the twins' 2^-19 below (as in test_pwide): psph and pball
 * test the side apart, pnear's message joins side and distance, and that
 * end's signed distance (kept just before) tells which */
static void on_oracle_fail(const char *what)
{
    if (strstr(what, "2^-20 (1 + |end|)")
        && (FN != FN_NEAR || (Sn.dist.n > 0 && Sn.dist.v[Sn.dist.n - 1] > 0)))
        return;
    fz_fail("exact oracle: %s", what);
}

/* each end's distance to the exact end (units of 2^-52 (1 + |end|)) within
 * the twins' 2^-19 (1 + |end|) */
static void tight(xu_dists *d)
{
    long k;
    for (k = 0; k < d->n; k++)
        if (!(fabs(d->v[k]) <= 0x1p33))
            fz_fail("TIGHTNESS: an end %.6g units of 2^-52 (1 + |end|) from the exact end "
                    "(more than 2^-19 (1 + |end|))", d->v[k]);
    d->n = 0;
    d->worst = 0;
}

/* f against the binary64 end d (up: an upper end): both finite, f on the
 * outer side of d, by at most 2^-22 |d| + 2^-147 (GMP rationals) */
static int relation_ok(float f, double d, int up)
{
    static mpq_t g, b, t;
    static int init;
    if (!init) {
        mpq_inits(g, b, t, (mpq_ptr)0);
        init = 1;
    }
    if (!isfinite(f) || !isfinite(d))
        return 0;
    mpq_set_d(g, (double)f);
    mpq_set_d(t, d);
    if (up)
        mpq_sub(g, g, t);
    else
        mpq_sub(g, t, g);
    mpq_set_d(b, fabs(d));
    mpq_div_2exp(b, b, 22);
    mpq_set_ui(t, 1, 1);
    mpq_div_2exp(t, t, 147);
    mpq_add(b, b, t);
    return mpq_sgn(g) >= 0 && mpq_cmp(g, b) <= 0;
}

static float fold(float x)
{
    int e;
    float m;
    if (!isfinite(x) || x == 0)
        return x;
    m = frexpf(x, &e);
    return ldexpf(m, ((e + 8) & 15) - 8);
}


static void fill(cbx_boxf *o)
{
    int i;
    for (i = 0; i < 3; i++)
        o->lo[i] = o->hi[i] = f_from_bits(PW_FILL_BITS);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in;
    int i, j, nan = 0, inf = 0, empty = 0, table = -1;
    cbx_projf p0;
    cbx_proj pd;
    cbx_boxf b0, o2;
    float c0[3], r0, w0, e0[3], q0[3][3], ne[3], nq[3][3];
    cbx_status s2;
    cbx_box w;
    in.p = data;
    in.n = size;
    fz_harness = "fuzz_pwide";
    fz_dump_fn = dump;
    SD = (cbx_status)-1;
    CTL = fz_byte(&in);
    FN = (CTL & 128u) ? FN_ELL : (int)(CTL & 3u) == 3 ? FN_SPH : (int)(CTL & 3u);
    NV = FN == FN_ELL ? 31 : FN == FN_SPH ? 20 : FN == FN_NEAR ? 23 : 21;
    memset(V, 0, sizeof V);
    for (i = 0; i < NV; i++) {
        uint32_t u = 0;
        for (j = 0; j < 4; j++)
            u |= (uint32_t)fz_byte(&in) << (8 * j);
        V[i] = f_from_bits(u);
    }
    memset(&PF, 0, sizeof PF);
    memset(&BF, 0, sizeof BF);
    CF[0] = CF[1] = CF[2] = RF = WF = 0;
    memset(EF, 0, sizeof EF);
    memset(QF, 0, sizeof QF);
    for (i = 0; i < NV; i++) {
        float x = (CTL & 32u) ? fold(V[i]) : V[i];
        if (i < 16)
            PF.m[i / 4][i % 4] = x;
        else if (FN == FN_NEAR) {
            if (i < 22)
                ((i - 16) % 2 ? BF.hi : BF.lo)[(i - 16) / 2] = x;
            else
                WF = x;
        } else if (i < 19)
            CF[i - 16] = x;
        else if (FN == FN_ELL) {
            if (i < 22)
                EF[i - 19] = x;
            else
                QF[(i - 22) / 3][(i - 22) % 3] = x;
        }
        else if (i == 19)
            RF = x;
        else
            WF = x;
    }
    if (CTL & 4u) {
        PF.m[3][0] = PF.m[3][1] = PF.m[3][3] = 0;
        PF.m[3][2] = -1;
    }
    if ((CTL & 64u) && isfinite(PF.m[3][3]) && PF.m[3][3] != 0) {
        PF.m[3][0] = PF.m[3][1] = PF.m[3][2] = 0;
        PF.m[3][3] = fabsf(PF.m[3][3]);
    }
    if (CTL & 8u) {
        if (FN == FN_NEAR) {
            for (i = 0; i < 3; i++)
                if (BF.lo[i] > BF.hi[i]) {
                    float t = BF.lo[i];
                    BF.lo[i] = BF.hi[i];
                    BF.hi[i] = t;
                }
        } else if (FN == FN_SPH) {
            if (isfinite(CF[2]) && isfinite(RF))
                CF[2] = -fabsf(CF[2]) - 2 * fabsf(RF) - 1;
        } else if (FN == FN_ELL) {
            if (isfinite(CF[2]) && isfinite(EF[0]) && isfinite(EF[1]) && isfinite(EF[2]))
                CF[2] = -fabsf(CF[2]) - 2 * (fabsf(EF[0]) + fabsf(EF[1]) + fabsf(EF[2])) - 1;
        } else {
            CF[2] = -fabsf(CF[2]);
        }
    }
    if (CTL & 16u)
        WF = fabsf(WF);

    /* the twin, the table, the binary64 function on the widened inputs */
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            pd.m[i][j] = PD[i][j] = PF.m[i][j];
            nan |= f_nan(PF.m[i][j]);
            inf |= f_inf(PF.m[i][j]);
        }
    for (i = 0; i < 3; i++) {
        CD[i] = CF[i];
        BD.lo[i] = BF.lo[i];
        BD.hi[i] = BF.hi[i];
    }
    RD = RF;
    WD = WF;
    for (i = 0; i < 3; i++) {
        ED[i] = EF[i];
        for (j = 0; j < 3; j++)
            QD[i][j] = QF[i][j];
    }
    if (FN == FN_NEAR || FN == FN_BALL) {
        nan |= f_nan(WF);
        inf |= f_inf(WF);
    }
    if (FN == FN_NEAR) {
        for (i = 0; i < 3; i++) {
            nan |= f_nan(BF.lo[i]) | f_nan(BF.hi[i]);
            inf |= f_inf(BF.lo[i]) | f_inf(BF.hi[i]);
            empty |= BF.hi[i] < BF.lo[i] || BF.lo[i] == (float)INFINITY || BF.hi[i] == -(float)INFINITY;
        }
    } else if (FN == FN_ELL) {
        for (i = 0; i < 3; i++) {
            nan |= f_nan(CF[i]) | f_nan(EF[i]);
            inf |= f_inf(CF[i]) | f_inf(EF[i]);
            for (j = 0; j < 3; j++) {
                nan |= f_nan(QF[i][j]);
                inf |= f_inf(QF[i][j]);
            }
        }
    } else {
        for (i = 0; i < 4; i++) {
            float x = i < 3 ? CF[i] : RF;
            nan |= f_nan(x);
            inf |= f_inf(x);
        }
    }
    table = nan ? CBX_EINVAL : (FN == FN_NEAR && empty) ? CBX_EMPTY : inf ? CBX_ERANGE : -1;

    p0 = PF;
    b0 = BF;
    memcpy(c0, CF, sizeof c0);
    r0 = RF;
    w0 = WF;
    memcpy(e0, EF, sizeof e0);
    memcpy(q0, QF, sizeof q0);
    fill(&OF);
    SF = FN == FN_SPH ? cbx_project_spheref(&PF, CF, RF, &OF)
       : FN == FN_NEAR ? cbx_project_box_nearf(&PF, &BF, WF, &OF)
       : FN == FN_ELL ? cbx_project_ellipsoidf(&PF, CF, EF, (const float (*)[3])QF, &OF)
       : cbx_project_sphere_nearf(&PF, CF, RF, WF, &OF);
    if (memcmp(&PF, &p0, sizeof PF) || memcmp(&BF, &b0, sizeof BF) || memcmp(CF, c0, sizeof c0)
        || memcmp(&RF, &r0, sizeof RF) || memcmp(&WF, &w0, sizeof WF) || memcmp(EF, e0, sizeof e0)
        || memcmp(QF, q0, sizeof q0))
        fz_fail("an input was changed");
    if (SF != CBX_OK && SF != CBX_EINVAL && SF != CBX_ERANGE
        && SF != (FN == FN_SPH || FN == FN_ELL ? CBX_EBEHIND : CBX_EMPTY))
        fz_fail("status %d is not a documented value of %s", (int)SF, fn_name[FN]);
    for (i = 0; i < 3; i++) {
        if (f_bits(OF.lo[i]) == PW_FILL_BITS || f_bits(OF.hi[i]) == PW_FILL_BITS)
            fz_fail("output axis %d not written (pre-fill NaN left)", i);
        if (f_nan(OF.lo[i]) || f_nan(OF.hi[i]))
            fz_fail("output axis %d has a NaN end", i);
    }
    for (i = 0; i < 3; i++)
        OD.lo[i] = OD.hi[i] = fz_fill();
    SD = FN == FN_SPH ? cbx_project_sphere(&pd, CD, RD, &OD)
       : FN == FN_NEAR ? cbx_project_box_near(&pd, &BD, WD, &OD)
       : FN == FN_ELL ? cbx_project_ellipsoid(&pd, CD, ED, (const double (*)[3])QD, &OD)
       : cbx_project_sphere_near(&pd, CD, RD, WD, &OD);
    if (SF != SD)
        fz_fail("status differs from the binary64 function's on the widened inputs (%s)",
                cbx_status_name(SD));
    if (table >= 0 && (int)SF != table)
        fz_fail("%s", table == CBX_EINVAL ? "NaN without CBX_EINVAL"
                : table == CBX_EMPTY ? "an empty float box without CBX_EMPTY"
                : "an infinite input without CBX_ERANGE");
    if (SF == CBX_EMPTY && !xu_empty_boxf(&OF))
        fz_fail("CBX_EMPTY without the empty box (lo = +inf, hi = -inf)");
    if (SF != CBX_OK && SF != CBX_EMPTY && !xu_whole_boxf(&OF))
        fz_fail("%s without the whole space (-inf, +inf)", cbx_status_name(SF));
    if (SF == CBX_OK)
        for (i = 0; i < 3; i++) {
            if (!relation_ok(OF.lo[i], OD.lo[i], 0))
                fz_fail("axis %d: RELATION: lower end not finite, above the binary64 end or below it "
                        "by more than 2^-22 |end| + 2^-147", i);
            if (!relation_ok(OF.hi[i], OD.hi[i], 1))
                fz_fail("axis %d: RELATION: upper end not finite, below the binary64 end or above it "
                        "by more than 2^-22 |end| + 2^-147", i);
        }

    /* the same set: out == in (box), radius -r (balls) */
    if (FN == FN_NEAR) {
        o2 = BF;
        s2 = cbx_project_box_nearf(&PF, &o2, WF, &o2);
        if (s2 != SF || memcmp(&o2, &OF, sizeof o2))
            fz_fail("out == in gives another status or other bits");
    } else if (FN == FN_ELL) {
        for (i = 0; i < 3; i++) {
            ne[i] = -EF[i];
            for (j = 0; j < 3; j++)
                nq[i][j] = -QF[i][j];
        }
        fill(&o2);
        s2 = cbx_project_ellipsoidf(&PF, CF, ne, (const float (*)[3])nq, &o2);
        if (s2 != SF || memcmp(&o2, &OF, sizeof o2))
            fz_fail("rot's columns and the radii negated (the same ellipsoid) give another status or other bits");
    } else {
        fill(&o2);
        s2 = FN == FN_SPH ? cbx_project_spheref(&PF, CF, -RF, &o2)
           : cbx_project_sphere_nearf(&PF, CF, -RF, WF, &o2);
        if (s2 != SF || memcmp(&o2, &OF, sizeof o2))
            fz_fail("radius -r gives another status or other bits than r (the same ball)");
    }

    /* the exact oracle on the float result, widened */
    for (i = 0; i < 3; i++) {
        w.lo[i] = OF.lo[i];
        w.hi[i] = OF.hi[i];
    }
    if (Ss.rng == 0) {
        pso_init(&Ss, 1);
        pno_init(&Sn, 1);
        pbo_init(&Sb, 1);
        pso_init(&Se, 1);
    }
    if (FN == FN_SPH) {
        pso_judge((const double (*)[4])PD, CD, RD, SF, &w, &Ss, on_oracle_fail);
        tight(&Ss.dist);
    } else if (FN == FN_ELL) {
        pso_judge_ell((const double (*)[4])PD, CD, ED, (const double (*)[3])QD, SF, &w, &Se, on_oracle_fail);
        tight(&Se.dist);
    } else if (FN == FN_NEAR) {
        pno_judge((const double (*)[4])PD, &BD, WD, SF, &w, &Sn, on_oracle_fail);
        tight(&Sn.dist);
    } else {
        pbo_judge((const double (*)[4])PD, CD, RD, WD, SF, &w, &Sb, on_oracle_fail);
        tight(&Sb.dist);
    }
    return 0;
}
