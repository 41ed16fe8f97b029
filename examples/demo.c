/*
 * demo: transform a few sample boxes with cbx_transform_box and show, for
 * each, the input, the map, the status, the output box and how tight it is
 * compared with the exact image (computed exactly with GMP, see
 * tests/exact_util.h).
 *
 * Tightness is printed as the excess of each bound over the exact bound in
 * units of u*S + 2^-1074 (u = 2^-53, S = |t| + sum |m_j| max|x_j|): how
 * many "unit roundoffs of the row's scale" the library gave away.  The
 * library proves a gap of at most 12 u S + 2^-1065; "contains" is checked
 * exactly, on the exact bounds and on the 8 corners of the input box.
 *
 * Two more sections: a sphere (cbx_sphere_box, exact bounds t -+ sqrt(s)
 * per axis) next to Arvo's box of the sphere's own box [-1, 1]^3 under the
 * same map, with their volume ratio; and the centre/half-diagonal form
 * (cbx_box_to_cbox, cbx_transform_cbox, cbx_cbox_to_box).
 */
#include <stdio.h>
#include <math.h>

#include "certbox.h"
#include "exact_util.h"
#include "psph_oracle.h"
#include "pnear_oracle.h"
#include "pball_oracle.h"

#define N_SAMPLES 9

typedef struct sample {
    const char *title;
    cbx_affine a;
    cbx_box in;
} sample;

static void set_row(cbx_affine *a, int i, double m0, double m1, double m2,
                    double t)
{
    a->m[i][0] = m0;
    a->m[i][1] = m1;
    a->m[i][2] = m2;
    a->m[i][3] = t;
}

static void set_axis(cbx_box *b, int j, double lo, double hi)
{
    b->lo[j] = lo;
    b->hi[j] = hi;
}

/* Built at run time because the rotations need cos/sin. */
static void make_samples(sample s[N_SAMPLES])
{
    const double deg30 = atan(1.0) / 1.5; /* pi/6; M_PI is not ISO C */
    const double c30 = cos(deg30), s30 = sin(deg30);
    const double ct = cos(1e-8), st = sin(1e-8);

    s[0].title = "rotation by 30 deg about z, then translation (1, 2, 3)";
    set_row(&s[0].a, 0, c30, -s30, 0, 1);
    set_row(&s[0].a, 1, s30, c30, 0, 2);
    set_row(&s[0].a, 2, 0, 0, 1, 3);
    set_axis(&s[0].in, 0, 0, 1);
    set_axis(&s[0].in, 1, 0, 2);
    set_axis(&s[0].in, 2, -1, 1);

    s[1].title = "scale (2, 0.1, -3) and translation (10, -1, 0.25)";
    set_row(&s[1].a, 0, 2, 0, 0, 10);
    set_row(&s[1].a, 1, 0, 0.1, 0, -1);
    set_row(&s[1].a, 2, 0, 0, -3, 0.25);
    set_axis(&s[1].in, 0, -1.5, 2.5);
    set_axis(&s[1].in, 1, 0.3, 0.7);
    set_axis(&s[1].in, 2, 1e-3, 1e3);

    s[2].title = "permutation (x0, x1, x2) -> (x2, x0, x1)";
    set_row(&s[2].a, 0, 0, 0, 1, 0);
    set_row(&s[2].a, 1, 1, 0, 0, 0);
    set_row(&s[2].a, 2, 0, 1, 0, 0);
    set_axis(&s[2].in, 0, -1, 1);
    set_axis(&s[2].in, 1, 2, 3);
    set_axis(&s[2].in, 2, -5, -4);

    s[3].title = "rotation by 1e-8 rad about z (cos rounds to 1.0)";
    set_row(&s[3].a, 0, ct, -st, 0, 0);
    set_row(&s[3].a, 1, st, ct, 0, 0);
    set_row(&s[3].a, 2, 0, 0, 1, 0);
    set_axis(&s[3].in, 0, -1e6, 1e6);
    set_axis(&s[3].in, 1, -1, 1);
    set_axis(&s[3].in, 2, 0, 0);

    s[4].title = "point box through a general affine map";
    set_row(&s[4].a, 0, 0.36, -0.48, 0.8, 10);
    set_row(&s[4].a, 1, 0.8, 0.6, 0, -3);
    set_row(&s[4].a, 2, -0.48, 0.64, 0.6, 0.5);
    set_axis(&s[4].in, 0, 0.3, 0.3);
    set_axis(&s[4].in, 1, -1.7, -1.7);
    set_axis(&s[4].in, 2, 2.5, 2.5);

    s[5].title = "empty box (lo > hi on axis 1)";
    s[5].a = s[1].a;
    set_axis(&s[5].in, 0, 0, 1);
    set_axis(&s[5].in, 1, 2, 1);
    set_axis(&s[5].in, 2, 0, 1);

    s[6].title = "NaN in the matrix";
    s[6].a = s[0].a;
    s[6].a.m[1][2] = NAN;
    s[6].in = s[0].in;

    s[7].title = "row 0: 1e300 * 1e300 is outside the proven domain (the upper end is lost, the lower end proven)";
    set_row(&s[7].a, 0, 1e300, 0, 0, 0);
    set_row(&s[7].a, 1, 0, 1, 0, 0);
    set_row(&s[7].a, 2, 0, 0, 2, 1);
    set_axis(&s[7].in, 0, 1, 1e300);
    set_axis(&s[7].in, 1, -1, 1);
    set_axis(&s[7].in, 2, 3, 4);

    s[8].title = "half-space x0 >= 1 (x0 in [1, +inf)) under a shear; zero column";
    set_row(&s[8].a, 0, 1, 0.5, 0, 0);
    set_row(&s[8].a, 1, -2, 1, 0, 3);
    set_row(&s[8].a, 2, 0, 0, 1, -1);
    set_axis(&s[8].in, 0, 1, HUGE_VAL);
    set_axis(&s[8].in, 1, -1, 1);
    set_axis(&s[8].in, 2, 3, 4);
}

static void print_matrix(const cbx_affine *a)
{
    int i;
    for (i = 0; i < 3; i++)
        printf("  %s [ %10.6g %10.6g %10.6g | %10.6g ]\n",
               i == 0 ? "matrix" : "      ", a->m[i][0], a->m[i][1],
               a->m[i][2], a->m[i][3]);
}

static void print_input(const cbx_box *b)
{
    int j;
    for (j = 0; j < 3; j++)
        printf("  %s x%d in [%24.17g, %24.17g]\n", j == 0 ? "input " : "      ",
               j, b->lo[j], b->hi[j]);
}

/* One output axis, with its exact tightness when it is in the domain. */
static void print_axis(xu_exact *x, const sample *s, const cbx_box *out,
                       int i, cbx_status st, int oob)
{
    printf("  %s y%d in [%24.17g, %24.17g]", i == 0 ? "output" : "      ", i,
           out->lo[i], out->hi[i]);
    if (st == CBX_EINVAL || st == CBX_EMPTY) {
        printf("\n");
    } else if (oob & (1 << i)) {
        /* not a full row: each end on its own (vertex rule) */
        int e;
        printf("  ");
        for (e = 0; e < 2; e++) {
            int k = xu_end_kind(&s->a, &s->in, i, e);
            double v[3], end = e ? out->hi[i] : out->lo[i];
            printf(" %s: ", e ? "hi" : "lo");
            if (k == XU_END_UNB) printf("unbounded (exact)");
            else if (k == XU_END_LOST) printf("outside the domain");
            else if (k == XU_END_WHOLE) printf("infinite map entry");
            else if (xu_vertex(&s->a, &s->in, i, e, v)) {
                cbx_box pt;
                double ex;
                int j;
                for (j = 0; j < 3; j++) pt.lo[j] = pt.hi[j] = v[j];
                xu_row_bounds(x, &s->a, &pt, i);
                ex = e ? xu_excess_hi(x, end) : xu_excess_lo(x, end);
                printf("excess %5.2f at the vertex, contains: %s", ex, ex >= 0 ? "yes" : "NO");
            }
        }
        printf("\n");
    } else if (!isfinite(out->lo[i]) || !isfinite(out->hi[i])) {
        printf("   (not finite!)\n");
    } else {
        double elo, ehi;
        int corners;
        xu_row_bounds(x, &s->a, &s->in, i);
        elo = xu_excess_lo(x, out->lo[i]);
        ehi = xu_excess_hi(x, out->hi[i]);
        corners = xu_corner_failures(x, &s->a, &s->in, i, out->lo[i], out->hi[i]);
        printf("   excess lo %5.2f hi %5.2f  contains: %s\n", elo, ehi,
               elo >= 0 && ehi >= 0 && corners == 0 ? "yes" : "NO");
    }
}

static void show(xu_exact *x, int n, const sample *s)
{
    cbx_box out;
    cbx_status st = cbx_transform_box(&s->a, &s->in, &out);
    int oob = xu_oob_mask(&s->a, &s->in), i;

    printf("[%d] %s\n", n, s->title);
    print_matrix(&s->a);
    print_input(&s->in);
    printf("  status %s\n", cbx_status_name(st));
    for (i = 0; i < 3; i++) print_axis(x, s, &out, i, st, oob);
    printf("\n");
}

/* ---- sphere: exact bounds vs Arvo's box of [-1, 1]^3 ------------------ */

/* gap of an end beyond t -+ sqrt(s / 2^2148), in units of
 * u (|t| + sqrt(s')) + 2^-1074, evaluated with 320-bit mpf (display only;
 * containment itself is decided exactly by xu_sqrt_lo_ok / xu_sqrt_hi_ok) */
static double sphere_units(const mpz_t s, double t, double end, int upper)
{
    mpf_t r, e, d, g;
    double u;
    mpf_inits(r, e, d, g, (mpf_ptr)0);
    mpf_set_prec(r, 320); mpf_set_prec(e, 320);
    mpf_set_prec(d, 320); mpf_set_prec(g, 320);
    mpf_set_z(r, s);
    mpf_div_2exp(r, r, 2148);
    mpf_sqrt(r, r);                      /* sqrt(s') */
    mpf_set_d(e, t);
    if (upper) mpf_add(e, e, r); else mpf_sub(e, e, r); /* exact end */
    mpf_set_d(g, end);
    if (upper) mpf_sub(g, g, e); else mpf_sub(g, e, g);  /* gap */
    mpf_set_d(d, fabs(t));
    mpf_add(d, d, r);
    mpf_div_2exp(d, d, 53);
    mpf_set_d(r, 0x1p-1074);
    mpf_add(d, d, r);
    mpf_div(g, g, d);
    u = mpf_get_d(g);
    mpf_clears(r, e, d, g, (mpf_ptr)0);
    return u;
}

static void show_sphere(xu_exact *x, int n)
{
    const double d30 = atan(1.0) / 1.5, d45 = atan(1.0);
    const double c = cos(d30), s = sin(d30), a = cos(d45), b = sin(d45);
    const double rad = 2.0;
    cbx_affine m;
    cbx_box cube = { { -1, -1, -1 }, { 1, 1, 1 } }, sb, ab;
    cbx_status ss, as;
    mpz_t sq, z;
    double vs = 1, va = 1;
    int i, j;

    /* y = rad * Rx(45) * Rz(30) * p + (1, 2, 3); Rx(45) Rz(30) =
     *   [ c     -s      0 ]
     *   [ a s    a c   -b ]
     *   [ b s    b c    a ]                                             */
    set_row(&m, 0, rad * c, rad * -s, 0, 1);
    set_row(&m, 1, rad * (a * s), rad * (a * c), rad * -b, 2);
    set_row(&m, 2, rad * (b * s), rad * (b * c), rad * a, 3);

    ss = cbx_sphere_box(&m, &sb);
    as = cbx_transform_box(&m, &cube, &ab);

    printf("[%d] sphere: unit ball scaled by 2, rotated 30 deg about z then 45 deg\n"
           "    about x, translated (1, 2, 3)\n", n);
    print_matrix(&m);
    printf("  cbx_sphere_box (exact bounds t -+ sqrt(s), outward): status %s\n",
           cbx_status_name(ss));
    printf("  cbx_transform_box of the sphere's box [-1,1]^3 (Arvo):   status %s\n",
           cbx_status_name(as));
    printf("        %-45s %s\n", "sphere box", "Arvo box of [-1,1]^3");
    mpz_inits(sq, z, (mpz_ptr)0);
    for (i = 0; i < 3; i++) {
        int ok;
        mpz_set_ui(sq, 0);
        for (j = 0; j < 3; j++) {  /* s = sum m_ij^2, scaled by 2^2148 */
            xu_scaled_sh(z, m.m[i][j], 1074);
            mpz_addmul(sq, z, z);
        }
        ok = ss == CBX_OK && xu_sqrt_lo_ok(x, sq, 1074, m.m[i][3], sb.lo[i])
             && xu_sqrt_hi_ok(x, sq, 1074, m.m[i][3], sb.hi[i]);
        printf("  y%d in [%20.17g, %20.17g]   [%20.17g, %20.17g]\n", i, sb.lo[i],
               sb.hi[i], ab.lo[i], ab.hi[i]);
        printf("       contains t -+ sqrt(s): %s, excess lo %.2f hi %.2f units of "
               "u*(|t|+sqrt s)\n", ok ? "yes" : "NO",
               sphere_units(sq, m.m[i][3], sb.lo[i], 0),
               sphere_units(sq, m.m[i][3], sb.hi[i], 1));
        vs *= sb.hi[i] - sb.lo[i];
        va *= ab.hi[i] - ab.lo[i];
    }
    mpz_clears(sq, z, (mpz_ptr)0);
    printf("  volume: sphere box %.6g (exact: 4^3 = 64), Arvo box %.6g\n"
           "          ratio Arvo box / exact box = %.4f (the ball fills %.1f%% of "
           "the exact box)\n\n", vs, va, va / vs,
           100.0 * (32.0 / 3.0) * (4.0 * atan(1.0)) / vs);
}

/* ---- centre/half-diagonal form ---------------------------------------- */

static void print_cbox_axes(const char *label, const cbx_cbox *b)
{
    int j;
    for (j = 0; j < 3; j++)
        printf("  %s%d: c = %24.17g, h = %24.17g\n", label, j, b->c[j], b->h[j]);
}

static void show_cbox(xu_exact *x, int n, const sample *smp)
{
    cbx_cbox cin, cout;
    cbx_box viac, arvo;
    cbx_status s1, s2, s3, s4;
    int i;

    s1 = cbx_box_to_cbox(&smp->in, &cin);
    s2 = cbx_transform_cbox(&smp->a, &cin, &cout);
    s3 = cbx_cbox_to_box(&cout, &viac);
    s4 = cbx_transform_box(&smp->a, &smp->in, &arvo);
    printf("[%d] centre/half-diagonal form (Arvo's Fig. 2) on sample [1]:\n"
           "    box -> cbox -> transform -> box, next to cbx_transform_box\n", n);
    print_matrix(&smp->a);
    print_input(&smp->in);
    printf("  cbx_box_to_cbox: %s, cbx_transform_cbox: %s, cbx_cbox_to_box: %s\n",
           cbx_status_name(s1), cbx_status_name(s2), cbx_status_name(s3));
    print_cbox_axes("in   x", &cin);
    print_cbox_axes("out  y", &cout);
    printf("        %-45s %s (%s)\n", "via cbox", "cbx_transform_box", cbx_status_name(s4));
    for (i = 0; i < 3; i++) {
        int ok = s3 == CBX_OK && isfinite(viac.lo[i]) && isfinite(viac.hi[i]);
        double elo = 0, ehi = 0;
        if (ok) {
            xu_row_bounds(x, &smp->a, &smp->in, i);
            elo = xu_excess_lo(x, viac.lo[i]);
            ehi = xu_excess_hi(x, viac.hi[i]);
            ok = elo >= 0 && ehi >= 0
                 && xu_corner_failures(x, &smp->a, &smp->in, i, viac.lo[i], viac.hi[i]) == 0;
        }
        printf("  y%d in [%20.17g, %20.17g]   [%20.17g, %20.17g]\n", i, viac.lo[i],
               viac.hi[i], arvo.lo[i], arvo.hi[i]);
        printf("       via cbox contains the exact image: %s, excess lo %.2f hi %.2f "
               "(units of u*S)\n", ok ? "yes" : "NO", elo, ehi);
    }
    printf("\n");
}

/* The float family on a sample: the map and box rounded to float, the
 * binary32 result, checked exactly (exact_util in its binary32 format:
 * excess in units of u S + eta with u = 2^-24, eta = 2^-149). */
static void show_float(xu_exact *x, int n, const sample *s0)
{
    sample s = *s0;
    cbx_affinef af;
    cbx_boxf bf, of;
    cbx_box out;
    cbx_status st;
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) {
            volatile float f = (float)s.a.m[i][j];
            af.m[i][j] = f;
            s.a.m[i][j] = f;
        }
    for (j = 0; j < 3; j++) {
        volatile float l = (float)s.in.lo[j], h = (float)s.in.hi[j];
        bf.lo[j] = l;
        bf.hi[j] = h;
        s.in.lo[j] = l;
        s.in.hi[j] = h;
    }
    st = cbx_transform_boxf(&af, &bf, &of);
    for (j = 0; j < 3; j++) {
        out.lo[j] = of.lo[j];
        out.hi[j] = of.hi[j];
    }
    xu_set_format(&xu_binary32);
    printf("[%d] the float family: sample [1] in binary32 (cbx_transform_boxf);\n"
           "    excess in units of u*S + 2^-149, u = 2^-24 (proven: within 12 u S + 2^-140)\n", n);
    print_matrix(&s.a);
    print_input(&s.in);
    printf("  status %s\n", cbx_status_name(st));
    for (i = 0; i < 3; i++) print_axis(x, &s, &out, i, st, xu_oob_mask(&s.a, &s.in));
    xu_set_format(&xu_binary64);
    printf("  build check cbx_ieee_check(): %s\n\n",
           cbx_ieee_check() == 0 ? "0 (this build computes as the proofs assume)" : "FAILED");
}

/* A ball under the same projection (cbx_project_sphere): each end checked
 * against the exact ends (tests/psph_oracle.c: MPFR with directed
 * rounding from the exact rational coefficients), the round-to-nearest
 * closed form beside it. */
static void show_project_sphere(const cbx_proj *p)
{
    static const double c[3] = {-0.1, 0.4, -4.3};
    const double rad = 0.45;
    static const char *verdict[3] = {"no (rounded inward)", "yes", "undecided"};
    cbx_box out;
    cbx_status st = cbx_project_sphere(p, c, rad, &out);
    int i;
    printf("  the ball |x - (%g, %g, %g)| <= %g under it: cbx_project_sphere: status %s\n",
           c[0], c[1], c[2], rad, cbx_status_name(st));
    for (i = 0; i < 3; i++) {
        double nl, nh;
        int v = pso_contains((const double (*)[4])p->m, c, rad, i, out.lo[i], out.hi[i]);
        int w;
        pso_closed_form((const double (*)[4])p->m, c, rad, i, &nl, &nh);
        w = pso_contains((const double (*)[4])p->m, c, rad, i, nl, nh);
        printf("  ndc%d in [%22.17g, %22.17g]  contains the exact bound: %s\n", i, out.lo[i], out.hi[i],
               v == 1 ? "yes" : v == 0 ? "NO" : "undecided");
        printf("       closed form, RN:  [%22.17g, %22.17g]  contains it: %s\n", nl, nh,
               verdict[w < 0 ? 2 : w]);
    }
    printf("\n");
}

/* An ellipsoid under the same projection (cbx_project_ellipsoid): a disk
 * of radius 0.6 tilted 30 degrees about x with a thickness of 0.05, judged
 * by the exact oracle (tests/psph_oracle.c: every end against the exact
 * ends, MPFR, and exact points of the ellipsoid), beside the box of its
 * bounding ball. */
static int ell_failures;
static void ell_fail(const char *what)
{
    ell_failures++;
    printf("  oracle: %s\n", what);
}

static void show_project_ellipsoid(const cbx_proj *p)
{
    static const double c[3] = {0.3, -0.2, -3.5};
    static const double radii[3] = {0.6, 0.6, 0.05};
    static const double rot[3][3] = {{1, 0, 0}, {0, 0.8660254037844386, -0.5}, {0, 0.5, 0.8660254037844386}};
    cbx_box out, ball;
    pso_stats s;
    cbx_status st = cbx_project_ellipsoid(p, c, radii, rot, &out);
    cbx_status sb = cbx_project_sphere(p, c, 0.6, &ball);
    int i;
    printf("  a disk of radius 0.6 and thickness 0.1 at (%g, %g, %g), tilted 30 degrees:\n"
           "  cbx_project_ellipsoid: status %s (its bounding ball: %s)\n",
           c[0], c[1], c[2], cbx_status_name(st), cbx_status_name(sb));
    for (i = 0; i < 3; i++)
        printf("  ndc%d in [%22.17g, %22.17g]  (the ball's: [%.6g, %.6g])\n", i, out.lo[i], out.hi[i],
               ball.lo[i], ball.hi[i]);
    pso_init(&s, 1);
    pso_judge_ell((const double (*)[4])p->m, c, radii, rot, st, &out, &s, ell_fail);
    printf("  contains the exact bound, each end within 2^-20 of it: %s (%ld exact checks)\n\n",
           ell_failures == 0 && st == CBX_OK ? "yes" : "NO", s.passed);
    pso_free(&s);
}

/* The cube around the camera clipped at the near plane W = 0.1
 * (cbx_project_box_near): the bound of its visible part, judged by the
 * exact oracle (tests/pnear_oracle.c: every end against the exact end over
 * the clipped cube's vertices, in rationals). */
static int near_failures;
static void near_fail(const char *what)
{
    near_failures++;
    printf("  oracle: %s\n", what);
}

static void show_project_near(const cbx_proj *p, const cbx_box *cube)
{
    cbx_box out;
    pno_stats s;
    cbx_status st = cbx_project_box_near(p, cube, 0.1, &out);
    int i;
    printf("  the same cube clipped at the near plane w = 0.1: cbx_project_box_near: status %s\n",
           cbx_status_name(st));
    for (i = 0; i < 3; i++)
        printf("  ndc%d in [%22.17g, %22.17g]\n", i, out.lo[i], out.hi[i]);
    pno_init(&s, 1);
    pno_judge((const double (*)[4])p->m, cube, 0.1, st, &out, &s, near_fail);
    printf("  contains the exact bound of the visible part, each end within 2^-20 of it: %s (%ld exact checks)\n",
           near_failures == 0 && st == CBX_OK ? "yes" : "NO", s.passed);
    pno_free(&s);
}

/* A ball around the camera's near plane (cbx_project_sphere_near): the
 * bound of its visible part, judged by the exact oracle
 * (tests/pball_oracle.c: every end against its closed form in MPFR, exact
 * points of the ball in front of the plane). */
static void show_project_ball_near(const cbx_proj *p)
{
    const double c[3] = {0.3, -0.2, -0.5};
    double rad = 1.0;
    cbx_box out, whole;
    pbo_stats s;
    cbx_status st = cbx_project_sphere_near(p, c, rad, 0.1, &out);
    cbx_status st2 = cbx_project_sphere(p, c, rad, &whole);
    int i, before = near_failures;
    printf("  the ball |x - (%g, %g, %g)| <= %g (it crosses the camera plane): cbx_project_sphere: %s;\n"
           "  clipped at the near plane w = 0.1: cbx_project_sphere_near: status %s\n",
           c[0], c[1], c[2], rad, cbx_status_name(st2), cbx_status_name(st));
    for (i = 0; i < 3; i++)
        printf("  ndc%d in [%22.17g, %22.17g]\n", i, out.lo[i], out.hi[i]);
    pbo_init(&s, 1);
    pbo_judge((const double (*)[4])p->m, c, rad, 0.1, st, &out, &s, near_fail);
    printf("  contains the exact bound of the visible part, each end within 2^-20 of it: %s (%ld exact checks)\n",
           near_failures == before && st == CBX_OK ? "yes" : "NO", s.passed);
    pbo_free(&s);
}

/* A box under a camera's projection (cbx_project_box), in NDC, with the
 * round-to-nearest 8-corner divide beside it; the exact bounds in mpq. */
static void show_project(int n)
{
    /* OpenGL's perspective: 90-degree field of view, near 0.1, far 100 */
    cbx_proj p = {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, -100.1 / 99.9, -20.0 / 99.9}, {0, 0, -1, 0}}};
    cbx_box in = {{-0.3, 0.2, -4.7}, {0.1, 0.6, -3.9}}, out, behind = {{-1, -1, -1}, {1, 1, 1}}, o2;
    cbx_status st = cbx_project_box(&p, &in, &out), st2 = cbx_project_box(&p, &behind, &o2);
    mpq_t X, W, r, lo, hi, t;
    int i, c, j;
    mpq_inits(X, W, r, lo, hi, t, NULL);
    printf("[%d] a box under a camera's projection (90-degree field of view), in NDC:\n"
           "  cbx_project_box: status %s\n", n, cbx_status_name(st));
    for (i = 0; i < 3; i++) {
        double nlo = HUGE_VAL, nhi = -HUGE_VAL;
        for (c = 0; c < 8; c++) {
            double v[3], x = 0, w = 0;
            v[0] = (c & 1) ? in.hi[0] : in.lo[0];
            v[1] = (c & 2) ? in.hi[1] : in.lo[1];
            v[2] = (c & 4) ? in.hi[2] : in.lo[2];
            mpq_set_d(X, p.m[i][3]);
            mpq_set_d(W, p.m[3][3]);
            for (j = 0; j < 3; j++) {
                mpq_set_d(t, p.m[i][j]);
                mpq_set_d(r, v[j]);
                mpq_mul(t, t, r);
                mpq_add(X, X, t);
                mpq_set_d(t, p.m[3][j]);
                mpq_mul(t, t, r);
                mpq_add(W, W, t);
                x += p.m[i][j] * v[j];
                w += p.m[3][j] * v[j];
            }
            x += p.m[i][3];
            w += p.m[3][3];
            mpq_div(r, X, W);
            if (c == 0 || mpq_cmp(r, lo) < 0) mpq_set(lo, r);
            if (c == 0 || mpq_cmp(r, hi) > 0) mpq_set(hi, r);
            if (x / w < nlo) nlo = x / w;
            if (x / w > nhi) nhi = x / w;
        }
        mpq_set_d(t, out.lo[i]);
        mpq_set_d(r, out.hi[i]);
        printf("  ndc%d in [%22.17g, %22.17g]  contains the exact hull: %s\n", i, out.lo[i], out.hi[i],
               mpq_cmp(t, lo) <= 0 && mpq_cmp(r, hi) >= 0 ? "yes" : "NO");
        mpq_set_d(t, nlo);
        mpq_set_d(r, nhi);
        printf("       8 corners / w, RN: [%22.17g, %22.17g]  contains it: %s\n", nlo, nhi,
               mpq_cmp(t, lo) <= 0 && mpq_cmp(r, hi) >= 0 ? "yes" : "no (rounded inward)");
    }
    printf("  the cube [-1, 1]^3 around the camera: status %s, out = the whole space: %s\n",
           cbx_status_name(st2), o2.lo[0] == -HUGE_VAL && o2.hi[0] == HUGE_VAL ? "yes" : "no");
    mpq_clears(X, W, r, lo, hi, t, NULL);
    show_project_near(&p, &behind);
    show_project_sphere(&p);
    show_project_ellipsoid(&p);
    show_project_ball_near(&p);
}

/* A box swept by a keyframed rotation: [4, 6] x [-1, 1] x [-1, 1] turned
 * 90 degrees about z while moving 2 up.  The exact swept box is
 * x, y in [-1, sqrt(37)], z in [-1, 3] (sqrt(37) = 6.0828: the corner
 * (6, 1) at 9.46 degrees for x, the corner (6, 1) at 80.5 degrees for y). */
static void show_rotation(int n)
{
    cbx_trs k0 = {{0, 0, 0}, {0, 0, 0, 1}, {1, 1, 1}};
    cbx_trs k1 = {{0, 0, 2}, {0, 0, 0.70710678118654752, 0.70710678118654752}, {1, 1, 1}};
    cbx_box in = {{4, -1, -1}, {6, 1, 1}};
    double ex_lo[3] = {-1, -1, -1}, ex_hi[3];
    static const unsigned depth[3] = {2, 4, 6};
    int d, i;
    ex_hi[0] = ex_hi[1] = sqrt(37.0);
    ex_hi[2] = 3;
    printf("[%d] motion with rotation: the box [4,6]x[-1,1]x[-1,1] turned 90 degrees about z (slerp)\n"
           "  while moving 2 up; the exact swept box: x, y in [-1, sqrt(37) = 6.0828], z in [-1, 3]\n", n);
    for (d = 0; d < 3; d++) {
        cbx_box out;
        cbx_status st = cbx_motion_trs_box(&k0, &k1, CBX_SLERP, 0.0, 1.0, depth[d], &in, &out);
        double worst = 0;
        int ok = 1;
        for (i = 0; i < 3; i++) {
            ok &= out.lo[i] <= ex_lo[i] && out.hi[i] >= ex_hi[i];
            worst = fmax(worst, fmax(ex_lo[i] - out.lo[i], out.hi[i] - ex_hi[i]));
        }
        printf("  cbx_motion_trs_box, %2d cells: x [%8.5f, %7.5f] y [%8.5f, %7.5f] z [%8.5f, %7.5f] %s\n"
               "       contains the exact box: %s; largest excess %.4f (%.2f%% of its side 7.08)\n",
               1 << depth[d], out.lo[0], out.hi[0], out.lo[1], out.hi[1], out.lo[2], out.hi[2],
               cbx_status_name(st), ok ? "yes" : "NO", worst, 100 * worst / (ex_hi[0] - ex_lo[0]));
    }
    printf("  union of the boxes at s = 0 and 1 (pbrt's endpoints): x [-1, 6] y [-1, 6] z [-1, 3]:\n"
           "       misses the exact box by sqrt(37) - 6 = %.4f on x and y\n\n", sqrt(37.0) - 6);
}

int main(void)
{
    sample s[N_SAMPLES];
    xu_exact x;
    int n;

    make_samples(s);
    xu_init(&x);
    printf("certbox %s demo\n"
           "excess = distance beyond the exact bound, in units of u*S + 2^-1074\n"
           "(proven: within 12 u S + 2^-1065, i.e. excess <= 12 except where\n"
           " u*S is near 2^-1074; target excess <= 8)\n\n", CBX_VERSION_STRING);
    for (n = 0; n < N_SAMPLES; n++) show(&x, n + 1, &s[n]);
    show_sphere(&x, N_SAMPLES + 1);
    show_cbox(&x, N_SAMPLES + 2, &s[0]);
    show_float(&x, N_SAMPLES + 3, &s[0]);
    show_project(N_SAMPLES + 4);
    show_rotation(N_SAMPLES + 5);
    xu_clear(&x);
    return 0;
}
