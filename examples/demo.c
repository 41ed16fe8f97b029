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
 */
#include <stdio.h>
#include <math.h>

#include "certbox.h"
#include "exact_util.h"

#define N_SAMPLES 8

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

    s[7].title = "outside the proven domain on row 0 (1e300 * 1e300)";
    set_row(&s[7].a, 0, 1e300, 0, 0, 0);
    set_row(&s[7].a, 1, 0, 1, 0, 0);
    set_row(&s[7].a, 2, 0, 0, 2, 1);
    set_axis(&s[7].in, 0, 1, 1e300);
    set_axis(&s[7].in, 1, -1, 1);
    set_axis(&s[7].in, 2, 3, 4);
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
        printf("   outside the domain: whole line\n");
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
    xu_clear(&x);
    return 0;
}
