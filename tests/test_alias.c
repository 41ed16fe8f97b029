/*
 * test_alias [N] [seed]: in-place use (out == in) of cbx_transform_box and
 * cbx_transform_cbox, which their contracts allow (include/certbox.h; proven:
 * the postconditions read the inputs at Pre).
 *
 * For N random cases each (default 100000; special values, empty boxes and
 * out-of-domain magnitudes included), per function:
 *   - the in-place call returns the same status as the call with a separate
 *     output, and the same output, bit for bit (every field);
 *   - for cbx_transform_box, the in-place result is also checked on its own
 *     against the exact oracle of exact_util (status, containment of the 8
 *     corners of the ORIGINAL box in exact rational arithmetic, the proven
 *     tightness bound; with infinite box ends, each end per the half-space
 *     rules of exact_util.h), through xu_run_case on a copy of the inputs
 *     whose output is then compared with the in-place one;
 *   - for cbx_transform_cbox, the in-place result is also checked on its
 *     own against exact_util's cbox rules (exact_util.h): the status equals
 *     xu_cbox_expected_status, EINVAL / EMPTY outputs c = 0, h = +inf / -inf,
 *     lost axes (W) exactly c = 0, h = +inf, and every other axis (A full
 *     row, D zero-coefficient columns dropped) finite and containing the
 *     exact images (mpq_t) of the 8 corners of the ORIGINAL box, for D of
 *     the dropped box (c_j = h_j = 0 where m_ij == 0).
 * The last line is "N passed, M failed" (cases); exit status 1 on failure.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>

#include "certbox.h"
#include "exact_util.h"

static double gen_value(xu_rng *r)
{
    static const double specials[] = { 0.0, -0.0, 1.0, -1.0, 0x1p-1074, 0x1p509, 0x1p1018,
                                       0x1p1019, HUGE_VAL, -HUGE_VAL };
    int k = xu_rng_int(r, 0, 99);
    if (k < 3) return specials[xu_rng_int(r, 0, 9)];
    if (k < 4) return nan("");
    if (k < 70) return xu_gen_signed(r, -40, 40);
    return xu_gen_signed(r, -1074, 1023);
}

static void gen_affine(xu_rng *r, cbx_affine *a)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 4; j++) a->m[i][j] = gen_value(r);
}

static int same_bits(const void *p, const void *q, size_t n)
{
    return memcmp(p, q, n) == 0;
}

/* The in-place cbox result o (status st) of the ORIGINAL input (a, in)
 * against exact_util's rules; returns a description of the first failure,
 * or NULL.  Uses the mpq scratch of *x. */
static const char *cbox_oracle(xu_exact *x, const cbx_affine *a, const cbx_cbox *in,
                               const cbx_cbox *o, cbx_status st)
{
    cbx_status want = xu_cbox_expected_status(a, in);
    int i, j;
    unsigned c;
    if (st != want) return "status differs from xu_cbox_expected_status";
    if (want == CBX_EINVAL || want == CBX_EMPTY) {
        for (i = 0; i < 3; i++)
            if (!(o->c[i] == 0 && isinf(o->h[i])
                  && (want == CBX_EINVAL ? o->h[i] > 0 : o->h[i] < 0)))
                return "EINVAL / EMPTY output not c = 0, h = +inf / -inf";
        return NULL;
    }
    for (i = 0; i < 3; i++) {
        cbx_cbox d;
        int kind = xu_cbox_axis_kind(a, in, i);
        if (kind == XU_CAX_LOST) {
            if (!(o->c[i] == 0 && isinf(o->h[i]) && o->h[i] > 0))
                return "lost axis (W) not c = 0, h = +inf";
            continue;
        }
        if (!isfinite(o->c[i]) || !isfinite(o->h[i]) || o->h[i] < 0)
            return "axis of kind A or D not finite with h >= 0";
        xu_cbox_dropped(a, in, i, &d); /* kind A: the same box */
        mpq_set_d(x->qa, o->c[i]);
        mpq_set_d(x->qb, o->h[i]);
        mpq_sub(x->qmin, x->qa, x->qb);
        mpq_add(x->qmax, x->qa, x->qb);
        for (c = 0; c < 8; c++) {
            mpq_set_d(x->q, a->m[i][3]);
            for (j = 0; j < 3; j++) {
                mpq_set_d(x->qa, d.c[j]);
                mpq_set_d(x->qb, d.h[j]);
                if ((c >> j) & 1u) mpq_add(x->qa, x->qa, x->qb);
                else mpq_sub(x->qa, x->qa, x->qb);
                mpq_set_d(x->qb, a->m[i][j]);
                mpq_mul(x->qa, x->qa, x->qb);
                mpq_add(x->q, x->q, x->qa);
            }
            if (mpq_cmp(x->qmin, x->q) > 0 || mpq_cmp(x->q, x->qmax) > 0)
                return "a corner's exact image outside [c - h, c + h]";
        }
    }
    return NULL;
}

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 100000;
    unsigned long seed = argc > 2 ? strtoul(argv[2], 0, 10) : 1;
    xu_rng rng = { 0x9e3779b97f4a7c15ULL ^ seed };
    xu_exact x;
    long k, box_fail = 0, cbox_fail = 0, oracle_fail = 0, st[4] = { 0, 0, 0, 0 };
    long cst[4] = { 0, 0, 0, 0 }, coracle_fail = 0, ckind[XU_NCAX] = { 0, 0, 0 };
    int j;

    xu_init(&x);
    for (k = 0; k < n; k++) {
        cbx_affine a;
        cbx_box in, sep_out, inplace, oracle_out;
        cbx_cbox cin, csep, cinplace;
        cbx_status s1, s2;
        int s3;
        xu_verdict v;

        gen_affine(&rng, &a);
        for (j = 0; j < 3; j++) {
            double p = gen_value(&rng), q = gen_value(&rng);
            if (xu_rng_int(&rng, 0, 19) != 0 && !(p <= q)) { double t = p; p = q; q = t; }
            in.lo[j] = p;
            in.hi[j] = q;
            cin.c[j] = gen_value(&rng);
            cin.h[j] = xu_rng_int(&rng, 0, 19) == 0 ? gen_value(&rng) : fabs(gen_value(&rng));
        }

        /* interval form: separate output, in place, and the exact oracle */
        memset(&sep_out, 0xff, sizeof sep_out);
        s1 = cbx_transform_box(&a, &in, &sep_out);
        inplace = in;
        s2 = cbx_transform_box(&a, &inplace, &inplace);
        s3 = xu_run_case(&x, &a, &in, &oracle_out, 1, &v);
        if (xu_status_index(s1) >= 0) st[xu_status_index(s1)]++;
        if (s1 != s2 || !same_bits(&sep_out, &inplace, sizeof inplace)) {
            if (box_fail++ < 10) {
                printf("FAIL transform_box in place differs (status %s vs %s)\n",
                       cbx_status_name(s1), cbx_status_name(s2));
                xu_print_case(stdout, &a, &in);
            }
        }
        if (s3 != 0 || v.got != s2 || !same_bits(&oracle_out, &inplace, sizeof inplace)) {
            if (oracle_fail++ < 10) {
                printf("FAIL transform_box oracle: %s\n", v.why);
                xu_print_case(stdout, &a, &in);
            }
        }

        /* center/half form */
        memset(&csep, 0xff, sizeof csep);
        s1 = cbx_transform_cbox(&a, &cin, &csep);
        cinplace = cin;
        s2 = cbx_transform_cbox(&a, &cinplace, &cinplace);
        if (xu_status_index(s1) >= 0) cst[xu_status_index(s1)]++;
        if (s1 != s2 || !same_bits(&csep, &cinplace, sizeof cinplace)) {
            if (cbox_fail++ < 10)
                printf("FAIL transform_cbox in place differs (status %s vs %s)\n",
                       cbx_status_name(s1), cbx_status_name(s2));
        }
        {
            const char *bad = cbox_oracle(&x, &a, &cin, &cinplace, s2);
            if (s2 == CBX_OK || s2 == CBX_ERANGE)
                for (j = 0; j < 3; j++) ckind[xu_cbox_axis_kind(&a, &cin, j)]++;
            if (bad && coracle_fail++ < 10) {
                printf("FAIL transform_cbox in-place oracle: %s (status %s)\n", bad,
                       cbx_status_name(s2));
                for (j = 0; j < 3; j++)
                    printf("  m[%d] = {%a, %a, %a | %a}  c[%d] = %a, h[%d] = %a\n", j,
                           a.m[j][0], a.m[j][1], a.m[j][2], a.m[j][3], j, cin.c[j], j,
                           cin.h[j]);
            }
        }
    }
    xu_clear(&x);

    printf("== in-place use (out == in), %ld random cases per function\n", n);
    printf("  transform_box  (OK %ld, EMPTY %ld, EINVAL %ld, ERANGE %ld): "
           "same status and bits as a separate output: %ld failed;\n"
           "    in-place result against the exact oracle (8 corners, mpq; proven "
           "tightness): %ld failed\n", st[0], st[1], st[2], st[3], box_fail, oracle_fail);
    printf("  transform_cbox (OK %ld, EMPTY %ld, EINVAL %ld, ERANGE %ld): "
           "same status and bits as a separate output: %ld failed;\n"
           "    in-place result against exact_util's cbox rules (status, lost axes, "
           "8 corners, mpq; axes A %ld, D %ld, W %ld): %ld failed\n",
           cst[0], cst[1], cst[2], cst[3], cbox_fail, ckind[XU_CAX_FULL],
           ckind[XU_CAX_DROP], ckind[XU_CAX_LOST], coracle_fail);
    {
        long failed = box_fail + oracle_fail + cbox_fail + coracle_fail;
        printf("%ld passed, %ld failed\n", 2 * n - failed, failed);
        return failed ? 1 : 0;
    }
}
