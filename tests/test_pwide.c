/*
 * test_pwide [N] [seed]: the binary32 twins of the binary64-only projective
 * bounds (cbx_project_spheref, cbx_project_box_nearf,
 * cbx_project_sphere_nearf; src/f32/cbx_pwide.c) against the binary64
 * functions and against exact arithmetic: the oracles of test_psphere,
 * test_pnear and test_pball (tests/psph_oracle.c, pnear_oracle.c,
 * pball_oracle.c: GMP rationals, MPFR with directed rounding).
 *
 * A case is drawn as those tests draw theirs (their hard-case tables, random
 * cameras and random general maps), then every input is rounded to float
 * (to nearest; beyond the largest float, to +-inf), so that the float case
 * is exact in double.  The twin is called on the float case, the binary64
 * function on the same values widened to double.  Checked, per call:
 *   1. status: the twin's status is the binary64 function's on the widened
 *      inputs, and the twins' table: NaN -> CBX_EINVAL; else (box_near) an
 *      empty box (hi < lo, lo = +inf or hi = -inf) -> CBX_EMPTY; else an
 *      infinite input -> CBX_ERANGE;
 *   2. special: every status but CBX_OK gives the whole space (float -inf,
 *      +inf), CBX_EMPTY the empty box (lo = +inf, hi = -inf);
 *   3. relation: with CBX_OK, every end finite, lo_f <= lo_d, hi_d <= hi_f,
 *      each within 2^-22 |end_d| + 2^-147 of the binary64 end (in GMP
 *      rationals: exact);
 *   4. exact: the oracle's verdict on the float result (widened, exact):
 *      the status rules (CBX_EBEHIND only near the camera plane, CBX_EMPTY
 *      only with nothing in front of the near plane, ...), every end finite
 *      and on the right side of the exact end (containment), and
 *      lo W <= X <= hi W at exact rational points of the ball or box;
 *   5. tight: each end within 2^-19 (1 + |end|) of the exact end (the
 *      twins' promise), from the oracle's distance of the end to the exact
 *      end; the oracle's own binary64 test at 2^-20 is replaced by this one
 *      (an end it flags there counts neither as passed nor as failed under
 *      exact, unless it is on the wrong side); the distances are printed in
 *      units of 2^-23 (1 + |end|) (a float ulp for 1 <= |end| < 2; proven:
 *      at most 16);
 *   6. input: the inputs unchanged (bits);
 *   7. same: box_near: out == in gives the same status and bits; the sphere
 *      twins: radius -r gives the same status and bits as r (the same
 *      ball).
 * Cases: test_psphere's, test_pnear's and test_pball's hard-case tables;
 * then float hard cases (each input in turn +-inf, +-FLT_MAX, +-2^-149;
 * empty float boxes alone and with NaN, an infinity or a bad wn; ends in
 * float's subnormal range, near 0 and near 2^98); then, N times, for each
 * twin a random camera and a random general map, and every 8th time a box
 * wholly in front of the camera with wn = 2^-90.  Per twin and per check
 * a line "check NAME N UNIT checked, F failed".  The last line is
 * "P passed, F failed".
 * This file is the driver (the twins' runs and checks, the random cases in
 * order, the summary); the hard cases are in tests/pwide_cases.c
 * (tests/pwide_parts.h).
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gmp.h>

#include "certbox.h"
#include "exact_util.h"
#include "psph_oracle.h"
#include "pnear_oracle.h"
#include "pball_oracle.h"
#include "proj_cases.h"
#include "pwide_parts.h"

enum { FN_SPH, FN_NEAR, FN_BALL, FN_ELL, NFN };
enum { K_STATUS, K_SPECIAL, K_RELATION, K_EXACT, K_TIGHT, K_INPUT, K_SAME, NK };
static const char *const fn_name[NFN] = {"cbx_project_spheref", "cbx_project_box_nearf", "cbx_project_sphere_nearf",
                                          "cbx_project_ellipsoidf"};
static const char *const fn_short[NFN] = {"spheref", "box_nearf", "sphere_nearf", "ellipsoidf"};
static const char *const k_name[NK] = {"status", "special", "relation", "exact", "tight", "input", "same"};
static const char *const k_unit[NK] = {"calls", "calls", "ends", "checks", "ends", "calls", "calls"};

/* the case in binary64, as the generators draw it */
double pwt_P[4][4], pwt_C[3], pwt_R, pwt_WN;
cbx_box pwt_B;
/* the float case widened (what the oracles and on_fail see) */
static double PD[4][4], CD[3], RD, WND;
/* the ellipsoid: radii E and rot Q (its center C), and their float values widened */
double pwt_E[3], pwt_Q[3][3];
static double ED[3], QD[3][3];
static cbx_box BD;

static int cur_fn;
static const char *case_name;
static long n_chk[NFN][NK], n_fail[NFN][NK], shown;
static long n_calls[NFN], contain_fail[NFN], t20[NFN];
static xu_dists dist[NFN];        /* units of 2^-23 (1 + |end|) */
static pso_stats Ss;
static pno_stats Sn;
static pbo_stats Sb;
static pso_stats Se;
static long ex_t20;               /* this call's ends flagged only by the oracle's 2^-20 */

/* ---- reporting ---------------------------------------------------------------- */
static void show_case(const char *what)
{
    int i;
    if (shown++ >= 20)
        return;
    printf("FAIL %s: %s (%s)\n  map:", fn_name[cur_fn], what, case_name);
    for (i = 0; i < 4; i++)
        printf(" [%a %a %a %a]", PD[i][0], PD[i][1], PD[i][2], PD[i][3]);
    if (cur_fn == FN_NEAR)
        printf("\n  box: [%a %a] [%a %a] [%a %a]  wn: %a\n", BD.lo[0], BD.hi[0], BD.lo[1], BD.hi[1], BD.lo[2], BD.hi[2], WND);
    else if (cur_fn == FN_SPH)
        printf("\n  c: %a %a %a  r: %a\n", CD[0], CD[1], CD[2], RD);
    else
        printf("\n  c: %a %a %a  r: %a  wn: %a\n", CD[0], CD[1], CD[2], RD, WND);
}

static void check(int k, int cond, const char *what)
{
    n_chk[cur_fn][k]++;
    if (!cond) {
        n_fail[cur_fn][k]++;
        show_case(what);
    }
}

/* The oracles' failures.  Their tightness test is binary64's, 2^-20
 * (1 + |end|): an end it flags is judged by the twins' 2^-19 instead (the
 * tight check, from the same end's distance).  psph and pball test the side
 * and the distance apart; pnear's message joins them, and the end's signed
 * distance (the oracle keeps it just before) tells which: positive, on the
 * right side and only too far; zero or negative, on the wrong side. */
static void on_oracle_fail(const char *what)
{
    if (strstr(what, "2^-20 (1 + |end|)")) {
        if (cur_fn != FN_NEAR || (Sn.dist.n > 0 && Sn.dist.v[Sn.dist.n - 1] > 0)) {
            ex_t20++;
            return;
        }
    }
    if (strstr(what, "exact lower end") || strstr(what, "exact upper end") || strstr(what, "the exact end")
        || strstr(what, "W <= X") || strstr(what, "X <= hi W") || strstr(what, "outside [lo, hi]"))
        contain_fail[cur_fn]++;
    show_case(what);
}

/* ---- float helpers ------------------------------------------------------------ */
/* x rounded to float, to nearest; beyond the largest float's rounding
 * range, +-inf (the conversion itself would be out of range in C99) */
static float f32(double x)
{
    if (x >= 0x1.ffffffp127)
        return (float)INFINITY;
    if (x <= -0x1.ffffffp127)
        return -(float)INFINITY;
    return (float)x;
}

static int f_nan(float x) { return x != x; }
static int f_inf(float x) { return x == (float)INFINITY || x == -(float)INFINITY; }


/* the map rounded to float, and that widened */
static void map_f(cbx_projf *pf, cbx_proj *pd)
{
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            pf->m[i][j] = f32(pwt_P[i][j]);
            pd->m[i][j] = PD[i][j] = pf->m[i][j];
        }
}

static int map_nan(const cbx_projf *p)
{
    int i, j, n = 0;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            n |= f_nan(p->m[i][j]);
    return n;
}

static int map_inf(const cbx_projf *p)
{
    int i, j, n = 0;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            n |= f_inf(p->m[i][j]);
    return n;
}

/* one end f of the twin against the binary64 end d (up: an upper end):
 * both finite, f on the outer side of d, by at most 2^-22 |d| + 2^-147
 * (GMP rationals) */
static int relation_ok(float f, double d, int up)
{
    mpq_t g, b, t;
    int ok;
    if (!isfinite(f) || !isfinite(d))
        return 0;
    mpq_inits(g, b, t, NULL);
    mpq_set_d(g, (double)f);
    mpq_set_d(t, d);
    if (up)
        mpq_sub(g, g, t);      /* f - d */
    else
        mpq_sub(g, t, g);      /* d - f */
    mpq_set_d(b, fabs(d));
    mpq_div_2exp(b, b, 22);
    mpq_set_ui(t, 1, 1);
    mpq_div_2exp(t, t, 147);
    mpq_add(b, b, t);
    ok = mpq_sgn(g) >= 0 && mpq_cmp(g, b) <= 0;
    mpq_clears(g, b, t, NULL);
    return ok;
}

/* checks 1 to 3 of a call, once the table's status is known (-1: none
 * applies); *w the float result widened, for the oracle */
static void common(cbx_status sf, cbx_status sd, int table, const cbx_boxf *of, const cbx_box *od, cbx_box *w)
{
    int i;
    n_calls[cur_fn]++;
    check(K_STATUS, sf == sd, "the status differs from the binary64 function's on the widened inputs");
    if (table >= 0)
        check(K_STATUS, (int)sf == table, table == CBX_EINVAL ? "NaN without CBX_EINVAL"
              : table == CBX_EMPTY ? "an empty box without CBX_EMPTY" : "an infinite input without CBX_ERANGE");
    if (sf != CBX_OK)
        check(K_SPECIAL, sf == CBX_EMPTY ? xu_empty_boxf(of) : xu_whole_boxf(of),
              sf == CBX_EMPTY ? "CBX_EMPTY without the empty box" : "a status other than CBX_OK without the whole space");
    else if (sd == CBX_OK)
        for (i = 0; i < 3; i++) {
            check(K_RELATION, relation_ok(of->lo[i], od->lo[i], 0),
                  "a lower end not finite, above the binary64 end or below it by more than 2^-22 |end| + 2^-147");
            check(K_RELATION, relation_ok(of->hi[i], od->hi[i], 1),
                  "an upper end not finite, below the binary64 end or above it by more than 2^-22 |end| + 2^-147");
        }
    for (i = 0; i < 3; i++) {
        w->lo[i] = of->lo[i];
        w->hi[i] = of->hi[i];
    }
    ex_t20 = 0;
}

/* after the oracle: its checks (less the ends flagged only at 2^-20) under
 * exact, and each end's distance to the exact end (the oracle's, in units
 * of 2^-52 (1 + |end|)) against the twins' 2^-19 (1 + |end|) */
static void after_oracle(long passed0, long failed0, long passed, long failed, xu_dists *d)
{
    long k;
    n_chk[cur_fn][K_EXACT] += passed - passed0 + failed - failed0 - ex_t20;
    n_fail[cur_fn][K_EXACT] += failed - failed0 - ex_t20;
    t20[cur_fn] += ex_t20;
    for (k = 0; k < d->n; k++) {
        double u = fabs(d->v[k]);
        check(K_TIGHT, u <= 0x1p33, "an end farther than 2^-19 (1 + |end|) from the exact end");
        xu_dists_add(&dist[cur_fn], u * 0x1p-29);
    }
    d->n = 0;          /* the oracle's summary prints binary64's units: kept here instead */
    d->worst = 0;
}

/* ---- the three twins ---------------------------------------------------------- */
cbx_status pwt_run_sph(const char *name)
{
    cbx_projf pf, pf0;
    cbx_proj pd;
    float cf[3], cf0[3], rf, rf0;
    cbx_boxf of, of2;
    cbx_box od, w;
    cbx_status sf, sf2, sd;
    int j, table = -1;
    long p0 = Ss.passed, f0 = Ss.failed;
    cur_fn = FN_SPH;
    case_name = name;
    map_f(&pf, &pd);
    for (j = 0; j < 3; j++)
        CD[j] = cf[j] = f32(pwt_C[j]);
    RD = rf = f32(pwt_R);
    pf0 = pf;
    memcpy(cf0, cf, sizeof cf);
    rf0 = rf;
    memset(&of, 0x5a, sizeof of);
    sf = cbx_project_spheref(&pf, cf, rf, &of);
    check(K_INPUT, memcmp(&pf, &pf0, sizeof pf) == 0 && memcmp(cf, cf0, sizeof cf) == 0
          && memcmp(&rf, &rf0, sizeof rf) == 0, "the inputs changed");
    memset(&of2, 0xa5, sizeof of2);
    sf2 = cbx_project_spheref(&pf, cf, -rf, &of2);
    check(K_SAME, sf2 == sf && memcmp(&of2, &of, sizeof of) == 0, "radius -r gives other bits than r (the same ball)");
    sd = cbx_project_sphere(&pd, CD, RD, &od);
    if (map_nan(&pf) || f_nan(cf[0]) || f_nan(cf[1]) || f_nan(cf[2]) || f_nan(rf))
        table = CBX_EINVAL;
    else if (map_inf(&pf) || f_inf(cf[0]) || f_inf(cf[1]) || f_inf(cf[2]) || f_inf(rf))
        table = CBX_ERANGE;
    common(sf, sd, table, &of, &od, &w);
    pso_judge((const double (*)[4])PD, CD, RD, sf, &w, &Ss, on_oracle_fail);
    after_oracle(p0, f0, Ss.passed, Ss.failed, &Ss.dist);
    return sf;
}

cbx_status pwt_run_near(const char *name)
{
    cbx_projf pf, pf0;
    cbx_proj pd;
    cbx_boxf bf, bf0, of, a;
    cbx_box od, w;
    float wf, wf0;
    cbx_status sf, sa, sd;
    int j, table = -1, nan = 0, inf = 0, empty = 0;
    long p0 = Sn.passed, f0 = Sn.failed;
    cur_fn = FN_NEAR;
    case_name = name;
    map_f(&pf, &pd);
    for (j = 0; j < 3; j++) {
        BD.lo[j] = bf.lo[j] = f32(pwt_B.lo[j]);
        BD.hi[j] = bf.hi[j] = f32(pwt_B.hi[j]);
        nan |= f_nan(bf.lo[j]) | f_nan(bf.hi[j]);
        inf |= f_inf(bf.lo[j]) | f_inf(bf.hi[j]);
        empty |= bf.hi[j] < bf.lo[j] || bf.lo[j] == (float)INFINITY || bf.hi[j] == -(float)INFINITY;
    }
    WND = wf = f32(pwt_WN);
    pf0 = pf;
    bf0 = bf;
    wf0 = wf;
    memset(&of, 0x5a, sizeof of);
    sf = cbx_project_box_nearf(&pf, &bf, wf, &of);
    check(K_INPUT, memcmp(&pf, &pf0, sizeof pf) == 0 && memcmp(&bf, &bf0, sizeof bf) == 0
          && memcmp(&wf, &wf0, sizeof wf) == 0, "the inputs changed");
    a = bf;
    sa = cbx_project_box_nearf(&pf, &a, wf, &a);
    check(K_SAME, sa == sf && memcmp(&a, &of, sizeof of) == 0, "out == in gives other bits");
    sd = cbx_project_box_near(&pd, &BD, WND, &od);
    if (map_nan(&pf) || nan || f_nan(wf))
        table = CBX_EINVAL;
    else if (empty)
        table = CBX_EMPTY;
    else if (map_inf(&pf) || inf || f_inf(wf))
        table = CBX_ERANGE;
    common(sf, sd, table, &of, &od, &w);
    pno_judge((const double (*)[4])PD, &BD, WND, sf, &w, &Sn, on_oracle_fail);
    after_oracle(p0, f0, Sn.passed, Sn.failed, &Sn.dist);
    return sf;
}

cbx_status pwt_run_ball(const char *name)
{
    cbx_projf pf, pf0;
    cbx_proj pd;
    float cf[3], cf0[3], rf, rf0, wf, wf0;
    cbx_boxf of, of2;
    cbx_box od, w;
    cbx_status sf, sf2, sd;
    int j, table = -1;
    long p0 = Sb.passed, f0 = Sb.failed;
    cur_fn = FN_BALL;
    case_name = name;
    map_f(&pf, &pd);
    for (j = 0; j < 3; j++)
        CD[j] = cf[j] = f32(pwt_C[j]);
    RD = rf = f32(pwt_R);
    WND = wf = f32(pwt_WN);
    pf0 = pf;
    memcpy(cf0, cf, sizeof cf);
    rf0 = rf;
    wf0 = wf;
    memset(&of, 0x5a, sizeof of);
    sf = cbx_project_sphere_nearf(&pf, cf, rf, wf, &of);
    check(K_INPUT, memcmp(&pf, &pf0, sizeof pf) == 0 && memcmp(cf, cf0, sizeof cf) == 0
          && memcmp(&rf, &rf0, sizeof rf) == 0 && memcmp(&wf, &wf0, sizeof wf) == 0, "the inputs changed");
    memset(&of2, 0xa5, sizeof of2);
    sf2 = cbx_project_sphere_nearf(&pf, cf, -rf, wf, &of2);
    check(K_SAME, sf2 == sf && memcmp(&of2, &of, sizeof of) == 0, "radius -r gives other bits than r (the same ball)");
    sd = cbx_project_sphere_near(&pd, CD, RD, WND, &od);
    if (map_nan(&pf) || f_nan(cf[0]) || f_nan(cf[1]) || f_nan(cf[2]) || f_nan(rf) || f_nan(wf))
        table = CBX_EINVAL;
    else if (map_inf(&pf) || f_inf(cf[0]) || f_inf(cf[1]) || f_inf(cf[2]) || f_inf(rf) || f_inf(wf))
        table = CBX_ERANGE;
    common(sf, sd, table, &of, &od, &w);
    pbo_judge((const double (*)[4])PD, CD, RD, WND, sf, &w, &Sb, on_oracle_fail);
    after_oracle(p0, f0, Sb.passed, Sb.failed, &Sb.dist);
    return sf;
}

/* an expected status of a hard case (counted under status) */
cbx_status pwt_run_ell(const char *name)
{
    cbx_projf pf, pf0;
    cbx_proj pd;
    float cf[3], ef[3], qf[3][3], nf[3], nq[3][3], cf0[3], ef0[3], qf0[3][3];
    cbx_boxf of, of2;
    cbx_box od, w;
    cbx_status sf, sf2, sd;
    int i, j, nan, inf, table = -1;
    long p0 = Se.passed, f0 = Se.failed;
    cur_fn = FN_ELL;
    case_name = name;
    map_f(&pf, &pd);
    nan = map_nan(&pf);
    inf = map_inf(&pf);
    for (i = 0; i < 3; i++) {
        CD[i] = cf[i] = f32(pwt_C[i]);
        ED[i] = ef[i] = f32(pwt_E[i]);
        nf[i] = -ef[i];
        nan |= f_nan(cf[i]) | f_nan(ef[i]);
        inf |= f_inf(cf[i]) | f_inf(ef[i]);
        for (j = 0; j < 3; j++) {
            QD[i][j] = qf[i][j] = f32(pwt_Q[i][j]);
            nq[i][j] = -qf[i][j];
            nan |= f_nan(qf[i][j]);
            inf |= f_inf(qf[i][j]);
        }
    }
    pf0 = pf;
    memcpy(cf0, cf, sizeof cf);
    memcpy(ef0, ef, sizeof ef);
    memcpy(qf0, qf, sizeof qf);
    memset(&of, 0x5a, sizeof of);
    sf = cbx_project_ellipsoidf(&pf, cf, ef, (const float (*)[3])qf, &of);
    check(K_INPUT, memcmp(&pf, &pf0, sizeof pf) == 0 && memcmp(cf, cf0, sizeof cf) == 0
          && memcmp(ef, ef0, sizeof ef) == 0 && memcmp(qf, qf0, sizeof qf) == 0, "the inputs changed");
    /* rot's columns and the radii negated: M = rot diag(radii) unchanged */
    memset(&of2, 0xa5, sizeof of2);
    sf2 = cbx_project_ellipsoidf(&pf, cf, nf, (const float (*)[3])nq, &of2);
    check(K_SAME, sf2 == sf && memcmp(&of2, &of, sizeof of) == 0,
          "rot's columns and the radii negated (the same ellipsoid) give other bits");
    sd = cbx_project_ellipsoid(&pd, CD, ED, (const double (*)[3])QD, &od);
    if (nan)
        table = CBX_EINVAL;
    else if (inf)
        table = CBX_ERANGE;
    common(sf, sd, table, &of, &od, &w);
    pso_judge_ell((const double (*)[4])PD, CD, ED, (const double (*)[3])QD, sf, &w, &Se, on_oracle_fail);
    after_oracle(p0, f0, Se.passed, Se.failed, &Se.dist);
    return sf;
}
void pwt_expect(cbx_status got, cbx_status want, const char *what)
{
    check(K_STATUS, got == want, what);
}

/* ---- summary ---------------------------------------------------------------------- */
static void print_dists(xu_dists *d)
{
    if (d->n == 0)
        return;
    qsort(d->v, (size_t)d->n, sizeof *d->v, xu_cmp_double);
    printf("  distance of a float end to the exact end, in units of 2^-23 (1 + |end|) (proven: at most 16):\n"
           "    median %.3f, 99th percentile %.3f, 99.9th %.3f, largest %.3f (%ld ends)\n",
           d->v[d->n / 2], d->v[d->n * 99 / 100], d->v[d->n * 999 / 1000], d->worst, d->n);
}

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 20000, k, passed = 0, failed = 0;
    uint64_t seed = argc > 2 ? strtoull(argv[2], NULL, 10) : 1;
    xu_rng g, ge;
    int f, q;
    g.s = seed;
    ge.s = seed + 1000003;
    pso_init(&Ss, seed + 99);
    pso_init(&Se, seed + 98);
    pno_init(&Sn, seed + 99);
    pbo_init(&Sb, seed + 99);
    tc_sphere_hard(pwt_P, pwt_C, &pwt_R, pwt_sph_run);
    tc_box_hard(pwt_P, &pwt_B, &pwt_WN, NULL, pwt_near_run);
    tc_ball_hard(pwt_P, pwt_C, &pwt_R, &pwt_WN, 0x1p-20, pwt_ball_run);
    pwt_float_hard();
    for (pwt_ell_kind = 0; pwt_ell_kind < 2; pwt_ell_kind++)
        tc_sphere_hard(pwt_P, pwt_C, &pwt_R, pwt_ell_run);
    for (k = 0; k < n; k++) {   /* the ellipsoid: a generator of its own (the others' cases unchanged) */
        tc_sphere_camera(&ge, pwt_P, pwt_C, &pwt_R);
        tc_ell_shape(&ge, pwt_R, pwt_E, pwt_Q);
        pwt_run_ell("random camera");
        tc_sphere_general(&ge, pwt_P, pwt_C, &pwt_R);
        tc_ell_shape(&ge, pwt_R, pwt_E, pwt_Q);
        pwt_run_ell("random map");
    }
    for (k = 0; k < n; k++) {
        tc_sphere_camera(&g, pwt_P, pwt_C, &pwt_R);
        pwt_run_sph("random camera");
        tc_sphere_general(&g, pwt_P, pwt_C, &pwt_R);
        pwt_run_sph("random map");
        tc_box_camera(&g, pwt_P, &pwt_B, &pwt_WN);
        pwt_run_near("random camera");
        tc_box_general(&g, pwt_P, &pwt_B, &pwt_WN);
        pwt_run_near("random general map");
        if (k % 8 == 0)
            pwt_near_in_front(&g);
        tc_ball_camera(&g, pwt_P, pwt_C, &pwt_R, &pwt_WN);
        pwt_run_ball("random camera");
        tc_ball_general(&g, pwt_P, pwt_C, &pwt_R, &pwt_WN);
        pwt_run_ball("random general map");
    }
    printf("test_pwide: the binary32 twins against binary64 and the exact oracles: %ld random cameras and %ld random\n"
           "general maps per twin (seed %llu), and the hard cases\n", n, n, (unsigned long long)seed);
    for (f = 0; f < NFN; f++) {
        printf("%s: %ld calls\n", fn_name[f], n_calls[f]);
        if (f == FN_SPH)
            pso_print(stdout, &Ss);
        else if (f == FN_ELL)
            pso_print(stdout, &Se);
        else if (f == FN_NEAR)
            pno_print(stdout, &Sn);
        else
            pbo_print(stdout, &Sb);
        print_dists(&dist[f]);
        printf("  the oracle's binary64 tightness test (2^-20 (1 + |end|)) failed %ld times (those ends judged at 2^-19 by tight);\n"
               "  containment failures (an exact end or an exact point outside): %ld\n", t20[f], contain_fail[f]);
        for (q = 0; q < NK; q++) {
            char nm[40];
            sprintf(nm, "%s.%s", fn_short[f], k_name[q]);
            printf("  check %-21s %9ld %-6s checked, %ld failed\n", nm, n_chk[f][q], k_unit[q], n_fail[f][q]);
            passed += n_chk[f][q] - n_fail[f][q];
            failed += n_fail[f][q];
        }
        xu_dists_free(&dist[f]);
    }
    pso_free(&Ss);
    pso_free(&Se);
    pno_free(&Sn);
    pbo_free(&Sb);
    printf("%ld passed, %ld failed\n", passed, failed);
    return failed != 0;
}
