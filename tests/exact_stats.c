/* exact_stats: the statistics of the checked cases (xu_stats: failed
 * checks, end kinds, excess maxima, means and histogram) and their report,
 * the printing of a case, and the drivers' small helpers: the class values
 * and their names, a numeric command-line argument.
 * Part of the oracle declared in exact_util.h (see there for the map). */
#include "exact_util.h"

#include <stdlib.h>
#include <string.h>
#include <limits.h>

/* ---------------------------------------------------------------------- */
/* Statistics                                                             */
/* ---------------------------------------------------------------------- */

static const double xu_bin_top[XU_NBINS - 1] = { 0, 0.5, 1, 2, 4, 6, 8, 12 };

void xu_stats_init(xu_stats *s) { memset(s, 0, sizeof *s); }

static void xu_stats_excess(xu_stats *s, double e)
{
    int b = 0;
    while (b < XU_NBINS - 1 && !(e < xu_bin_top[b])) b++;
    s->hist[b]++;
    if (e > 8) s->over_target++;
}

/* max/mean split by scale (call before s->axes++). */
static void xu_stats_scale(xu_stats *s, const xu_axis *ax, int i,
                           const cbx_affine *a, const cbx_box *in)
{
    double m = ax->ex_lo > ax->ex_hi ? ax->ex_lo : ax->ex_hi;
    long n_norm = s->axes - s->axes_tiny;
    if (ax->tiny) {
        if (s->axes_tiny == 0 || m > s->max_tiny) s->max_tiny = m;
        s->sum_tiny += ax->ex_lo + ax->ex_hi;
        s->axes_tiny++;
    } else {
        if (n_norm == 0 || m > s->max_norm) {
            s->max_norm = m;
            s->worst_a = *a;
            s->worst_in = *in;
            s->worst_axis = i;
        }
        s->sum_norm += ax->ex_lo + ax->ex_hi;
        s->over_target_norm += (ax->ex_lo > 8) + (ax->ex_hi > 8);
    }
}

void xu_stats_add(xu_stats *s, const xu_verdict *v, const cbx_affine *a,
                  const cbx_box *in)
{
    int f, i, si = xu_status_index(v->expected);
    s->cases++;
    if (v->failed) s->failed++;
    if (si >= 0) s->status_seen[si]++;
    for (f = 0; f < XU_NFLAGS; f++) {
        s->flag_fail[f] += v->flag[f];
        s->flag_checked[f] += v->applied[f];
    }
    for (i = 0; i < 3; i++) {
        const xu_axis *ax = &v->ax[i];
        int e;
        for (e = 0; e < 2; e++) {
            if (ax->end_kind[e] >= 0 && ax->end_kind[e] < XU_NEND)
                s->ends_kind[ax->end_kind[e]]++;
            if (!ax->end_checked[e]) continue;
            if (ax->end_tiny[e]) {
                if (s->vends_tiny == 0 || ax->ex_end[e] > s->max_vend_tiny)
                    s->max_vend_tiny = ax->ex_end[e];
                s->vends_tiny++;
            } else {
                if (s->vends == 0 || ax->ex_end[e] > s->max_vend) s->max_vend = ax->ex_end[e];
                s->sum_vend += ax->ex_end[e];
                s->vends++;
            }
        }
        if (!ax->checked) continue;
        if (s->axes == 0 || ax->ex_lo > s->max_lo) s->max_lo = ax->ex_lo;
        if (s->axes == 0 || ax->ex_hi > s->max_hi) s->max_hi = ax->ex_hi;
        s->sum_lo += ax->ex_lo;
        s->sum_hi += ax->ex_hi;
        xu_stats_scale(s, ax, i, a, in);
        s->axes++;
        s->axes_exact += ax->exact;
        xu_stats_excess(s, ax->ex_lo);
        xu_stats_excess(s, ax->ex_hi);
    }
}

static const char *const xu_flag_unit[XU_NFLAGS] = {
    "cases", "cases", "cases", "axes", "axes",
    "axes", "axes", "axes", "axes",
    "ends", "ends", "ends", "ends", "ends", "ends", "cases"
};

void xu_stats_print(FILE *f, const char *title, const xu_stats *s)
{
    int k;
    double n = s->axes ? (double)s->axes : 1.0;
    double mx = s->max_lo > s->max_hi ? s->max_lo : s->max_hi;
    fprintf(f, "== %s: %ld cases (expected OK %ld, EMPTY %ld, EINVAL %ld, "
               "ERANGE %ld)\n", title, s->cases, s->status_seen[0],
            s->status_seen[1], s->status_seen[2], s->status_seen[3]);
    for (k = 0; k < XU_NFLAGS; k++)
        fprintf(f, "  check %-12s %10ld %-5s checked, %6ld failed\n",
                xu_flag_name[k], s->flag_checked[k], xu_flag_unit[k],
                s->flag_fail[k]);
    fprintf(f, "  ends by rule: full-row A %ld, vertex F %ld, unbounded U %ld, "
               "lost L %ld, whole-line W %ld\n", s->ends_kind[XU_END_FULL],
            s->ends_kind[XU_END_VERTEX], s->ends_kind[XU_END_UNB], s->ends_kind[XU_END_LOST],
            s->ends_kind[XU_END_WHOLE]);
    if (s->vends + s->vends_tiny)
        fprintf(f, "  vertex ends (rule B, finite) checked: %ld; excess (units of u*S_v + "
                   "2^-%d): max %.4f mean %.4f over %ld ends with u*S_v >= 2^%d*eta, "
                   "max %.4f over %ld below\n", s->vends + s->vends_tiny, xu_fmt->emin, s->max_vend,
                s->vends ? s->sum_vend / (double)s->vends : 0.0, s->vends, XU_TINY,
                s->max_vend_tiny, s->vends_tiny);
    fprintf(f, "  in-domain (full-row) axes checked: %ld (exactly equal to the exact "
               "image: %ld)\n", s->axes, s->axes_exact);
    if (s->axes == 0) return;
    fprintf(f, "  excess lo: max %.4f  mean %.4f   (units of u*S + 2^-%d, u = 2^-%d)\n",
            s->max_lo, s->sum_lo / n, xu_fmt->emin, xu_fmt->p);
    fprintf(f, "  excess hi: max %.4f  mean %.4f\n", s->max_hi, s->sum_hi / n);
    fprintf(f, "  excess   : max %.4f  mean %.4f   target <= 8: %s (%ld sides "
               "above 8)\n", mx, (s->sum_lo + s->sum_hi) / (2 * n),
            mx <= 8 ? "met" : "NOT met", s->over_target);
    if (s->axes > s->axes_tiny)
        fprintf(f, "  excess, axes with u*S >= 2^%d*eta: max %.4f  mean %.4f  "
                   "(%ld axes, %ld sides above 8)\n", XU_TINY, s->max_norm,
                s->sum_norm / (2.0 * (double)(s->axes - s->axes_tiny)),
                s->axes - s->axes_tiny, s->over_target_norm);
    if (s->axes_tiny)
        fprintf(f, "  excess, axes with u*S <  2^%d*eta: max %.4f  mean %.4f  "
                   "(%ld axes)\n", XU_TINY, s->max_tiny,
                s->sum_tiny / (2.0 * (double)s->axes_tiny), s->axes_tiny);
    fprintf(f, "  (the proven bound 12 u S + 2^-%d is checked exactly as "
               "proven-tight; 2^-%d = 512 eta, so where u*S is tiny an "
               "excess above 12 is allowed)\n", xu_fmt->tight_e, xu_fmt->tight_e);
    fprintf(f, "  histogram (both sides):");
    for (k = 0; k < XU_NBINS; k++) {
        if (k == 0) fprintf(f, " <0:%ld", s->hist[k]);
        else if (k == XU_NBINS - 1) fprintf(f, " >=12:%ld", s->hist[k]);
        else fprintf(f, " [%g,%g):%ld", xu_bin_top[k - 1], xu_bin_top[k],
                     s->hist[k]);
    }
    fprintf(f, "\n");
}

/* ---------------------------------------------------------------------- */
/* Printing                                                               */
/* ---------------------------------------------------------------------- */

int xu_status_index(cbx_status s)
{
    switch (s) {
    case CBX_OK: return 0;
    case CBX_EMPTY: return 1;
    case CBX_EINVAL: return 2;
    case CBX_ERANGE: return 3;
    case CBX_EBEHIND: return -1; /* cbx_project_box only: not a status of the affine forms */
    }
    return -1;
}

void xu_print_box(FILE *f, const char *label, const cbx_box *b)
{
    int j;
    for (j = 0; j < 3; j++)
        fprintf(f, "  %s[%d] = [%.17g, %.17g]  (%a, %a)\n", label, j,
                b->lo[j], b->hi[j], b->lo[j], b->hi[j]);
}

void xu_print_case(FILE *f, const cbx_affine *a, const cbx_box *in)
{
    int i;
    for (i = 0; i < 3; i++)
        fprintf(f, "  m[%d] = {%a, %a, %a | %a}\n", i, a->m[i][0],
                a->m[i][1], a->m[i][2], a->m[i][3]);
    xu_print_box(f, "in", in);
}

/* ---------------------------------------------------------------------- */
/* Class values and the command line                                      */
/* ---------------------------------------------------------------------- */

const int xu_cls_values[XU_NCLS_VALUES] = {
    CBX_CLASS_GENERAL, CBX_CLASS_PERMUTE, CBX_CLASS_SCALE, CBX_CLASS_TRANSLATE,
    CBX_CLASS_IDENTITY, 5, 7, -1, -3, INT_MAX, INT_MIN
};

const char *xu_cls_str(int cls, char buf[16])
{
    static const char *const names[5] = { "GENERAL", "PERMUTE", "SCALE", "TRANSLATE",
                                          "IDENTITY" };
    if (cls >= 0 && cls < 5) return names[cls];
    if (cls == INT_MAX) return "INT_MAX";
    if (cls == INT_MIN) return "INT_MIN";
    snprintf(buf, 16, "%d", cls);
    return buf;
}

unsigned long long xu_arg_num(int argc, char **argv, int n, unsigned long long dflt,
                              const char *usage)
{
    char *end;
    unsigned long long v;
    if (argc <= n) return dflt;
    v = strtoull(argv[n], &end, 0);
    if (*argv[n] == '\0' || *argv[n] == '-' || *end != '\0') {
        fprintf(stderr, "usage: %s %s\n", argv[0], usage);
        exit(2);
    }
    return v;
}
