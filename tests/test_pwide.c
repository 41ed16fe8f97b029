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

enum { FN_SPH, FN_NEAR, FN_BALL, FN_ELL, NFN };
enum { K_STATUS, K_SPECIAL, K_RELATION, K_EXACT, K_TIGHT, K_INPUT, K_SAME, NK };
static const char *const fn_name[NFN] = {"cbx_project_spheref", "cbx_project_box_nearf", "cbx_project_sphere_nearf",
                                          "cbx_project_ellipsoidf"};
static const char *const fn_short[NFN] = {"spheref", "box_nearf", "sphere_nearf", "ellipsoidf"};
static const char *const k_name[NK] = {"status", "special", "relation", "exact", "tight", "input", "same"};
static const char *const k_unit[NK] = {"calls", "calls", "ends", "checks", "ends", "calls", "calls"};

/* the case in binary64, as the generators draw it */
static double P[4][4], C[3], R, WN;
static cbx_box B;
/* the float case widened (what the oracles and on_fail see) */
static double PD[4][4], CD[3], RD, WND;
/* the ellipsoid: radii E and rot Q (its center C), and their float values widened */
static double E[3], Q[3][3], ED[3], QD[3][3];
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
            pf->m[i][j] = f32(P[i][j]);
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
static cbx_status run_sph(const char *name)
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
        CD[j] = cf[j] = f32(C[j]);
    RD = rf = f32(R);
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

static cbx_status run_near(const char *name)
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
        BD.lo[j] = bf.lo[j] = f32(B.lo[j]);
        BD.hi[j] = bf.hi[j] = f32(B.hi[j]);
        nan |= f_nan(bf.lo[j]) | f_nan(bf.hi[j]);
        inf |= f_inf(bf.lo[j]) | f_inf(bf.hi[j]);
        empty |= bf.hi[j] < bf.lo[j] || bf.lo[j] == (float)INFINITY || bf.hi[j] == -(float)INFINITY;
    }
    WND = wf = f32(WN);
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

static cbx_status run_ball(const char *name)
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
        CD[j] = cf[j] = f32(C[j]);
    RD = rf = f32(R);
    WND = wf = f32(WN);
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
static cbx_status run_ell(const char *name)
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
        CD[i] = cf[i] = f32(C[i]);
        ED[i] = ef[i] = f32(E[i]);
        nf[i] = -ef[i];
        nan |= f_nan(cf[i]) | f_nan(ef[i]);
        inf |= f_inf(cf[i]) | f_inf(ef[i]);
        for (j = 0; j < 3; j++) {
            QD[i][j] = qf[i][j] = f32(Q[i][j]);
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

/* the ball's hard cases as ellipsoids: a ball, and a tilted disk */
static int ell_kind;
static void ell_run(const char *name, cbx_status want, const char *what)
{
    (void)want;
    (void)what;
    E[0] = E[1] = E[2] = R;
    tc_identity3(Q);
    if (ell_kind == 1) {
        tc_rotation(Q, 0.9, 0.3, -0.2, 0.1);
        E[2] = 0;
    }
    run_ell(name);
}

static void expect(cbx_status got, cbx_status want, const char *what)
{
    check(K_STATUS, got == want, what);
}

/* ---- cases: test_psphere's and test_pball's (tests/proj_cases.c) ------------------ */
static const double q0[4] = {1, 0, 0, 0}, t0[3] = {0, 0, 0};

static void sph_run(const char *name, cbx_status want, const char *what)
{
    cbx_status st = run_sph(name);
    if (what)
        expect(st, want, what);
}

static void ball_run(const char *name, cbx_status want, const char *what)
{
    cbx_status st = run_ball(name);
    if (what)
        expect(st, want, what);
}

/* ---- cases: test_pnear's ---------------------------------------------------------- */
static void set_box(double l0, double h0, double l1, double h1, double l2, double h2)
{
    B.lo[0] = l0; B.hi[0] = h0;
    B.lo[1] = l1; B.hi[1] = h1;
    B.lo[2] = l2; B.hi[2] = h2;
}

/* a box wholly in front of the camera plane (cbx_project_box gives CBX_OK
 * on the binary64 case), the near plane far below it */
static void near_in_front(xu_rng *g)
{
    cbx_proj p;
    cbx_box o;
    int i, j;
    tc_box_camera(g, P, &B, &WN);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            p.m[i][j] = P[i][j];
    if (cbx_project_box(&p, &B, &o) != CBX_OK)
        return;
    WN = 0x1p-90;
    run_near("box in front, near plane at 2^-90");
}

static void near_hard(void)
{
    static const double bad_wn[] = {0.0, -0.0, -1.0, 0x1p-101, 0x1p121, INFINITY, -INFINITY};
    int k;
    tc_identity_camera(P);
    set_box(-1, 1, -1, 1, -12, -8); WN = 0.125;
    run_near("box ahead");
    set_box(-1, 1, -1, 1, -4, 4);
    run_near("box across the near plane (the camera inside)");
    set_box(-1, 1, -1, 1, 1, 4);
    expect(run_near("box behind the camera"), CBX_EMPTY, "a box behind the camera without CBX_EMPTY");
    set_box(-1, 1, -1, 1, -0.125, 4);
    run_near("box with a face on the near plane");
    set_box(-1, 1, -1, 1, -0.0625, 4);
    run_near("box just behind the near plane");
    set_box(1, 1, 1, 1, -0.125, -0.125);
    run_near("a point on the near plane");
    set_box(-1e6, 1e6, -1e6, 1e6, -1e6, 1e6);
    run_near("huge box around the camera");
    set_box(1e3, 1e3 + 1e-9, 1e3, 1e3 + 1e-9, -1e4, -1e4 + 1e-9);
    run_near("tiny box far away (a point in float)");
    set_box(1e3, 1e3 + 1e-3, 1e3, 1e3 + 1e-3, -1e4, -1e4 + 1e-3);
    run_near("small box far away");
    for (k = 0; k < 23; k++) {
        tc_identity_camera(P);
        set_box(-1, 1, -1, 1, -4, 4); WN = 0.125;
        if (k < 16)
            P[k / 4][k % 4] = NAN;
        else if (k < 22)
            ((k - 16) % 2 ? B.hi : B.lo)[(k - 16) / 2] = NAN;
        else
            WN = NAN;
        expect(run_near("NaN"), CBX_EINVAL, "NaN without CBX_EINVAL");
    }
    tc_identity_camera(P);
    set_box(-1, 1, 1, -1, -4, 4); WN = 0.125;
    expect(run_near("empty box"), CBX_EMPTY, "an empty box without CBX_EMPTY");
    set_box(-1, 1, -1, 1, -4, INFINITY);
    run_near("an infinite end");
    for (k = 0; k < (int)(sizeof bad_wn / sizeof bad_wn[0]); k++) {
        set_box(-1, 1, -1, 1, -12, -8); WN = bad_wn[k];
        expect(run_near("near plane outside the domain"), CBX_ERANGE, "wn outside the domain without CBX_ERANGE");
    }
    WN = 0.125;
    for (k = 0; k < 10; k++) {
        tc_identity_camera(P);
        set_box(-1, 1, -1, 1, -12, -8);
        if (k < 4)
            P[k][k == 3 ? 2 : k] = k == 3 ? -0x1p61 : 0x1p61;
        else
            (k % 2 ? B.hi : B.lo)[(k - 4) / 2] = k % 2 ? 0x1p61 : -0x1p61;
        expect(run_near("an entry or a box end above 2^60"), CBX_ERANGE, "outside the domain without CBX_ERANGE");
    }
    tc_identity_camera(P);
    P[3][0] = 0x1p-60;
    P[0][0] = 0x1p50;
    set_box(-1, 1, -1, 1, -4, 4);
    run_near("a ratio beyond the range of an end");
    memset(P, 0, sizeof P);
    P[0][0] = 0x1p60; P[1][1] = 1; P[2][2] = 1; P[3][2] = 1;
    set_box(1, 2, 0, 1, 0x1p-100, 1); WN = 0x1p-100;
    expect(run_near("an end beyond 2^99 (a corner)"), CBX_ERANGE, "an end beyond 2^99 without CBX_ERANGE");
    set_box(1, 2, 0, 1, 0, 1);
    expect(run_near("an end beyond 2^99 (a crossing)"), CBX_ERANGE, "an end beyond 2^99 without CBX_ERANGE");
    for (k = 0; k < 3; k++) {
        memset(P, 0, sizeof P);
        P[0][0] = 1; P[1][1] = 1; P[2][2] = 1;
        P[3][3] = k == 0 ? 2 : k == 1 ? 0.125 : 0.0625;
        set_box(-1, 1, -1, 1, -4, 4);
        WN = 0.125;
        run_near("W constant");
    }
    tc_identity_camera(P);
    P[0][0] = P[0][1] = P[0][2] = P[0][3] = 0;
    set_box(-1, 1, -1, 1, -4, 4);
    run_near("X_0 zero");
    memset(P, 0, sizeof P);
    P[0][0] = 1; P[1][1] = 1; P[2][2] = 1; P[3][0] = 1; P[3][1] = 1; P[3][2] = 1;
    set_box(0, 1, 0, 1, 0, 1); WN = 1;
    run_near("corner on the near plane");
    WN = 3;
    run_near("only the far corner on the near plane");
    WN = 2;
    run_near("a diagonal plane through four corners");
    for (k = 0; k < 8; k++) {
        tc_scaled_camera(P, k);
        set_box(-3, 5, -2, 7, -9, 0.5); WN = ldexp(0.01, 12 * k - 40);
        run_near("scaled wide or narrow camera");
    }
}

/* ---- cases: float's own ------------------------------------------------------------ */
/* the three twins on the current map, ball (C, R), its box [C - |R|, C + |R|] and WN */
static void run_all(const char *name)
{
    int j;
    for (j = 0; j < 3; j++) {
        B.lo[j] = C[j] - fabs(R);
        B.hi[j] = C[j] + fabs(R);
    }
    run_sph(name);
    run_near(name);
    run_ball(name);
}

static void base_case(void)
{
    tc_identity_camera(P);
    tc_set_ball(C, &R, 0.5, -0.25, -4, 1);
    WN = 0.125;
}

static void float_hard(void)
{
    /* each input in turn: infinities (CBX_ERANGE), the largest float (out
     * of the domain) and the least subnormal (in it, except wn) */
    static const double v[] = {INFINITY, -INFINITY, FLT_MAX, -FLT_MAX, 0x1p-149, -0x1p-149, 0x1.ffffffp127, -1e39};
    int k, s, j, i;
    for (k = 0; k < (int)(sizeof v / sizeof v[0]); k++) {
        for (s = 0; s < 31; s++) {   /* 16 map entries, the center, the radii, rot */
            base_case();
            E[0] = 1; E[1] = 0.5; E[2] = 0.25;
            tc_identity3(Q);
            if (s < 16)
                P[s / 4][s % 4] = v[k];
            else if (s < 19)
                C[s - 16] = v[k];
            else if (s < 22)
                E[s - 19] = v[k];
            else
                Q[(s - 22) / 3][(s - 22) % 3] = v[k];
            run_ell("an extreme float in one input of the ellipsoid");
        }
        for (s = 0; s < 21; s++) {   /* 16 map entries, the center, the radius, wn */
            base_case();
            if (s < 16)
                P[s / 4][s % 4] = v[k];
            else if (s < 19)
                C[s - 16] = v[k];
            else if (s < 20)
                R = v[k];
            else
                WN = v[k];
            if (s < 20)
                run_sph("an extreme float in one input");
            run_ball("an extreme float in one input");
        }
        for (s = 0; s < 23; s++) {   /* 16 map entries, the 6 box ends, wn */
            base_case();
            set_box(0, 1, -1, 0, -8, -2);
            if (s < 16)
                P[s / 4][s % 4] = v[k];
            else if (s < 22)
                ((s - 16) % 2 ? B.hi : B.lo)[(s - 16) / 2] = v[k];
            else
                WN = v[k];
            run_near("an extreme float in one input");
        }
    }
    /* empty float boxes: hi < lo, lo = +inf, hi = -inf (each alone: [+inf,
     * +inf], [-inf, -inf]); alone, with NaN
     * (CBX_EINVAL first), with an infinite or out-of-domain input or a bad
     * wn (CBX_EMPTY first) */
    for (k = 0; k < 5; k++)
        for (s = 0; s < 5; s++) {
            base_case();
            set_box(0, 1, -1, 0, -8, -2);
            if (k == 0) { B.lo[1] = 0.5f; B.hi[1] = 0.25f; }
            if (k == 1) B.lo[2] = INFINITY;
            if (k == 2) B.hi[0] = -INFINITY;
            if (k == 3) { B.lo[1] = INFINITY; B.hi[1] = INFINITY; }   /* lo = +inf, not hi < lo */
            if (k == 4) { B.lo[2] = -INFINITY; B.hi[2] = -INFINITY; } /* hi = -inf, not hi < lo */
            if (s == 1) P[2][1] = NAN;
            if (s == 2) P[0][3] = INFINITY;
            if (s == 3) B.lo[0] = -INFINITY;
            if (s == 4) WN = -1;
            expect(run_near("an empty float box"), s == 1 ? CBX_EINVAL : CBX_EMPTY,
                   s == 1 ? "an empty box with NaN without CBX_EINVAL" : "an empty box without CBX_EMPTY");
        }
    /* a box one float wide; negative zeros */
    base_case();
    set_box(0.5, 0x1.000002p-1, -0.25, -0.25, -4, -4);
    run_near("a box one float wide");
    base_case();
    tc_set_ball(C, &R, -0.0, -0.0, -4, -0.0);
    run_all("negative zeros");
    /* ends in float's subnormal range and around 0: rows X scaled down
     * (2^-120 .. 2^-150: the entries themselves float subnormals) */
    for (k = 0; k < 4; k++) {
        base_case();
        for (j = 0; j < 3; j++)
            for (i = 0; i < 4; i++)
                P[j][i] = ldexp(P[j][i], -120 - 10 * k);
        run_all("ends in float's subnormal range");
        tc_set_ball(C, &R, 0, 0, -4, 1);
        run_all("ends around 0, tiny");
    }
    /* X / W constant 0 (a zero row) and exactly representable ends */
    memset(P, 0, sizeof P);
    P[1][1] = 1; P[2][2] = 1; P[3][3] = 1;
    tc_set_ball(C, &R, 0.5, 0.25, 0.75, 0.125);
    WN = 0.5;
    run_all("a zero row, the rest the identity");
    /* ends near 2^98 (X up to 2^60 times 2^38) */
    memset(P, 0, sizeof P);
    P[0][0] = 0x1p60; P[1][1] = 1; P[2][2] = 1; P[3][3] = 1;
    tc_set_ball(C, &R, 0x1p38, 0, 0, 1);
    WN = 0.5;
    run_all("ends near 2^98");
    /* a double case that float rounding moves across the camera plane */
    tc_camera(P, 1.83, 1.0, 0.1, 100, q0, t0);
    tc_set_ball(C, &R, 0.3, -0.2, -1, 1 - 0x1p-30);
    run_all("a ball tangent to the camera plane in float");
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
    tc_sphere_hard(P, C, &R, sph_run);
    near_hard();
    tc_ball_hard(P, C, &R, &WN, 0x1p-20, ball_run);
    float_hard();
    for (ell_kind = 0; ell_kind < 2; ell_kind++)
        tc_sphere_hard(P, C, &R, ell_run);
    for (k = 0; k < n; k++) {   /* the ellipsoid: a generator of its own (the others' cases unchanged) */
        tc_sphere_camera(&ge, P, C, &R);
        tc_ell_shape(&ge, R, E, Q);
        run_ell("random camera");
        tc_sphere_general(&ge, P, C, &R);
        tc_ell_shape(&ge, R, E, Q);
        run_ell("random map");
    }
    for (k = 0; k < n; k++) {
        tc_sphere_camera(&g, P, C, &R);
        run_sph("random camera");
        tc_sphere_general(&g, P, C, &R);
        run_sph("random map");
        tc_box_camera(&g, P, &B, &WN);
        run_near("random camera");
        tc_box_general(&g, P, &B, &WN);
        run_near("random general map");
        if (k % 8 == 0)
            near_in_front(&g);
        tc_ball_camera(&g, P, C, &R, &WN);
        run_ball("random camera");
        tc_ball_general(&g, P, C, &R, &WN);
        run_ball("random general map");
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
