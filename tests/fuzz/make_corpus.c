/*
 * make_corpus OUTDIR: write the seed corpus of the certbox fuzz harnesses
 * to OUTDIR/<harness>/<seed name> (the committed copy is tests/fuzz/corpus).
 *
 *   cc -std=c99 -Itests/fuzz tests/fuzz/make_corpus.c -lm -o make_corpus
 *   ./make_corpus tests/fuzz/corpus
 *
 * Each seed is the control byte followed by the doubles in the order the
 * harness reads them, encoded with fz_encode() (fuzz_common.h): one byte
 * for a special value, 9 bytes otherwise.  Every seed is decoded back and
 * compared bit for bit before it is written.  fuzz_pwide reads floats, 4
 * raw bytes each: its seeds are written by seed_f32 instead.
 */
#include <errno.h>
#include <sys/stat.h>
#include <sys/types.h>

#define FZ_DECODE_ONLY
#include "fuzz_common.h"

#define INF HUGE_VAL
#define NaN (0.0 * HUGE_VAL) /* any NaN; the quiet one is a special */
#define P254U 0x1.0000000000001p254
#define P509U 0x1.0000000000001p509
#define P1018U 0x1.0000000000001p1018
#define P1019U 0x1.0000000000001p1019
#define TINY 0x1p-1074

static const char *outdir;
static int nwritten;

static void mkdir_p(const char *d)
{
    if (mkdir(d, 0755) != 0 && errno != EEXIST) {
        perror(d);
        exit(1);
    }
}

/* one seed: control byte, then the n doubles v[] (n must be what the
 * harness reads: `want`) */
static void seed_arr(const char *harness, const char *name, unsigned ctl,
                     const double *v, size_t n, size_t want)
{
    uint8_t buf[1024];
    size_t len = 0, k;
    char path[1024];
    FILE *f;
    fz_in in;

    if (n != want) {
        fprintf(stderr, "%s/%s: %lu values, the harness reads %lu\n", harness, name,
                (unsigned long)n, (unsigned long)want);
        exit(1);
    }
    buf[len++] = (uint8_t)ctl;
    for (k = 0; k < n; k++) len += fz_encode(v[k], buf + len);
    /* round trip */
    in.p = buf;
    in.n = len;
    if (fz_byte(&in) != ctl) abort();
    for (k = 0; k < n; k++) {
        double d = fz_double(&in);
        if (fz_to_bits(d) != fz_to_bits(v[k]) && !(d != d && v[k] != v[k])) {
            fprintf(stderr, "%s/%s: value %lu does not round-trip\n", harness, name,
                    (unsigned long)k);
            exit(1);
        }
    }
    snprintf(path, sizeof path, "%s/%s", outdir, harness);
    mkdir_p(path);
    snprintf(path, sizeof path, "%s/%s/%s", outdir, harness, name);
    f = fopen(path, "wb");
    if (!f || fwrite(buf, 1, len, f) != len || fclose(f) != 0) {
        perror(path);
        exit(1);
    }
    nwritten++;
}

/* seed(harness, name, control byte, n, values...): the values become a
 * double array (a compound literal), so integer constants are converted */
#define seed(h, name, ctl, n, ...)                                              \
    seed_arr(h, name, ctl, (const double[]){ __VA_ARGS__ },                     \
             sizeof((const double[]){ __VA_ARGS__ }) / sizeof(double), n)

/* a 3x4 matrix row by row, then a box as (lo0, hi0, lo1, hi1, lo2, hi2) */
#define MAT(a, b, c, d, e, f, g, h, i, j, k, l) a, b, c, d, e, f, g, h, i, j, k, l
#define ID3(t0, t1, t2) MAT(1, 0, 0, t0, 0, 1, 0, t1, 0, 0, 1, t2)

static void transform_box(void)
{
    const char *H = "transform_box";
    seed(H, "identity-unit-cube", 0x07, 18, ID3(0, 0, 0), 0., 1., 0., 1., 0., 1.);
    seed(H, "cyclic-perm-int-t", 0x07, 18, MAT(0, 1, 0, 5, 0, 0, 1, -7, 1, 0, 0, 0),
         -1., 2., 3., 4., -6., -5.);
    seed(H, "decimal-rotation-point-box", 0x17, 18,
         MAT(0.36, -0.48, 0.8, 10, 0.8, 0.6, 0, -3, -0.48, 0.64, 0.6, 0.5),
         0.3, 0.3, -1.7, -1.7, 2.5, 2.5);
    seed(H, "subnormals", 0x07, 18,
         MAT(TINY, -TINY, TINY, TINY, -TINY, -TINY, TINY, -TINY, TINY, TINY, -TINY, 0),
         -TINY, TINY, TINY, TINY, -TINY, 0.);
    seed(H, "class509-edge", 0x07, 18,
         MAT(0x1p509, 0, 0, 0, -0x1p509, 0x1p509, 0, 0, 0x1p509, 0x1p509, 0x1p509, 0x1p1018),
         -0x1p509, 0x1p509, -0x1p509, 0x1p509, -0x1p509, 0x1p509);
    seed(H, "class509-ulp-out", 0x07, 18, MAT(1, 0, 0, 0, -1, 1, 0, 0, 0x1p509, 0, 0, 0),
         -0x1p509, P509U, 0., 1., 0., 1.);
    seed(H, "class1018-edge", 0x07, 18,
         MAT(0x1p1018, 0, 0, 0, 0, -0x1p1018, 0, 0, 0x1p1018, 0, 0, -0x1p1018),
         -1., 1., 0.5, 1., -0x1p1018, 0x1p1018);
    seed(H, "t-1018-ulp-out", 0x07, 18, ID3(P1018U, 0x1p1018, -0x1p1018),
         0., 1., 0., 1., 0., 1.);
    seed(H, "class64-class960", 0x07, 18,
         MAT(0x1p64, 0, 0, 0, 0, 0x1p960, 0, 0, -0x1p64, -0x1p960, 1, 0),
         0x1p954, 0x1p954, -0x1p58, 0x1p58, 0., 1.);
    seed(H, "cancel-decimal", 0x0f, 18,
         MAT(0.1, 0.2, 0.3, 0, 1e-3, 1.1, -0.7, 0, 0.1, 0, 0, 0), 1., 1., 1., 1., 1., 1.);
    seed(H, "cancel-interval-1e100", 0x0f, 18,
         MAT(1e100, 3e99, -7e98, 0, 1e100, 0, 0, 0, -1e100, -3e99, 7e98, 0),
         1e100, 1e100, 7e99, 7e99, 3e101, 3.0000000000000001e101);
    seed(H, "tiny-rotation-1e-8", 0x07, 18,
         MAT(1.0, -1e-8, 0, 0, 1e-8, 1.0, 0, 0, 0, 0, 1, 0), -1e6, 1e6, -1., 1., 0., 0.);
    seed(H, "signed-zeros", 0x00, 18,
         MAT(-0., 1, -0., -0., -0., -0., -1, 0, 1, -0., 0, -0.), -0., 0., -2., -1., 0., -0.);
    seed(H, "all-rows-out-1e300", 0x07, 18,
         MAT(1e300, 0, 0, 0, -1e300, 1, 0, 0, 1e300, 0, 1, 0), 1., 1e300, 0., 1., 0., 1.);
    seed(H, "t-dbl-max", 0x07, 18, ID3(0, 0, DBL_MAX), 0., 1., 0., 1., 0., 1.);
    seed(H, "empty-box", 0x00, 18, ID3(0, 0, 0), 0., 1., 2., 1., 0., 1.);
    seed(H, "nan-matrix", 0x07, 18, ID3(0, NaN, 0), 0., 1., 0., 1., 0., 1.);
    seed(H, "nan-box-inf-matrix", 0x00, 18, MAT(INF, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0),
         0., 1., 0., NaN, 0., 1.);
    seed(H, "half-space-below", 0x07, 18, MAT(2, 0, 0, 1, 0, -3, 0, 0, 1, 1, 1, 0),
         -INF, 0., 1., 2., 0., 1.);
    seed(H, "half-space-zero-column", 0x07, 18, MAT(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 7),
         0., 1., 0., 1., -INF, INF);
    seed(H, "whole-space-input", 0x07, 18, ID3(1, 2, 3), -INF, INF, -INF, INF, -INF, INF);
    seed(H, "inf-matrix-entry", 0x07, 18, MAT(INF, 0, 0, 0, 0, -INF, 0, 0, 1, 1, 1, INF),
         -1., 1., 0., 2., 0., 1.);
    seed(H, "box-at-plus-inf", 0x07, 18, ID3(0, 0, 0), INF, INF, 0., 1., 0., 1.);
    seed(H, "dbl-max-coords", 0x07, 18, ID3(0, 0, 0), -DBL_MAX, DBL_MAX, 0., 1., 0., 1.);
    seed(H, "in-place-rotation", 0x47, 18,
         MAT(0.36, -0.48, 0.8, 10, 0.8, 0.6, 0, -3, -0.48, 0.64, 0.6, 0.5),
         0.3, 1.3, -1.7, 2., 2.5, 2.75);
    seed(H, "in-place-half-space", 0x47, 18, MAT(0, 1, 0, 0, 2, 0, 0, 1, 1, 1, 1, 0),
         -INF, 0., 1., 2., 0., 1.);
    /* half-spaces: each end on its own (rule B) */
    seed(H, "half-space-neg-zero-vs-inf", 0x07, 18, MAT(-0., 1, 0, 2, 1, -0., 0, 0, 0, 0, -1, 0),
         -INF, INF, 0., 1., 3., INF);
    seed(H, "half-space-vertex-out", 0x07, 18, MAT(1e300, 0, 0, 0, 0, 1, 0, DBL_MAX, 1, 1, 1, 0),
         -INF, 2., 0., INF, 0., 1.);
    seed(H, "huge-unneeded-end", 0x07, 18, MAT(1, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0),
         0., DBL_MAX, 0., 1., 0., 1.);
    seed(H, "half-space-2p1018-vertex", 0x07, 18,
         MAT(1, 0, 0, 0x1p1018, 0, -0x1p1018, 0, 0, 0, 0, 0x1p509, 0),
         -0x1p1018, INF, 0., 0., -INF, 0x1p509);
    seed(H, "box-at-minus-inf", 0x00, 18, ID3(0, 0, 0), 0., 1., -INF, -INF, 0., 1.);
}

static void transform_cbox(void)
{
    const char *H = "transform_cbox";
    /* matrix, then (c0, h0, c1, h1, c2, h2) */
    seed(H, "identity-unit", 0x07, 18, ID3(0, 0, 0), 0.5, 0.5, 0.5, 0.5, 0.5, 0.5);
    seed(H, "cyclic-perm-int-t", 0x07, 18, MAT(0, 1, 0, 5, 0, 0, 1, -7, 1, 0, 0, 0),
         0.5, 1.5, 3.5, 0.5, -5.5, 0.5);
    seed(H, "decimal-rotation", 0x07, 18,
         MAT(0.36, -0.48, 0.8, 10, 0.8, 0.6, 0, -3, -0.48, 0.64, 0.6, 0.5),
         0.3, 0.1, -1.7, 0.2, 2.5, 0.3);
    seed(H, "points-decimal", 0x17, 18,
         MAT(0.36, -0.48, 0.8, 10, 0.8, 0.6, 0, -3, -0.48, 0.64, 0.6, 0.5),
         0.3, 0., -1.7, 0., 2.5, 0.);
    seed(H, "subnormals", 0x07, 18,
         MAT(TINY, -TINY, TINY, TINY, -TINY, -TINY, TINY, -TINY, TINY, TINY, -TINY, 0),
         TINY, TINY, -TINY, TINY, 0., TINY);
    seed(H, "class509-edge", 0x07, 18,
         MAT(0x1p509, 0, 0, 0, -0x1p509, 0x1p509, 0, 0, 0x1p509, 0x1p509, 0x1p509, 0x1p1018),
         0x1p509, 0x1p509, -0x1p509, 0x1p509, 0., 0x1p509);
    seed(H, "class509-ulp-out", 0x07, 18, MAT(1, 0, 0, 0, -1, 1, 0, 0, 0x1p509, 0, 0, 0),
         P509U, 1., 0., 1., 0., 1.);
    seed(H, "class1018-edge", 0x07, 18,
         MAT(0x1p1018, 0, 0, 0, 0, -0x1p1018, 0, 0, 0x1p1018, 0, 0, -0x1p1018),
         0., 1., 0.75, 0.25, 0., 0x1p1018);
    seed(H, "t-1018-ulp-out", 0x07, 18, ID3(P1018U, 0x1p1018, -0x1p1018),
         0.5, 0.5, 0.5, 0.5, 0.5, 0.5);
    seed(H, "cancel-decimal", 0x0f, 18,
         MAT(0.1, 0.2, 0.3, 0, 1e-3, 1.1, -0.7, 0, 0.1, 0, 0, 0), 1., 0., 1., 1e-20, 1., 0.);
    seed(H, "cancel-1e200", 0x0f, 18,
         MAT(1e100, 3e99, -7e98, 0, 1e100, 0, 0, 0, -1e100, -3e99, 7e98, 0),
         1e100, 1e80, 7e99, 0., 3e101, 1.);
    seed(H, "signed-zeros", 0x00, 18,
         MAT(-0., 1, -0., -0., -0., -0., -1, 0, 1, -0., 0, -0.), -0., 0., -2., -0., 0., 0.);
    seed(H, "all-rows-out-1e300", 0x07, 18,
         MAT(1e300, 0, 0, 0, -1e300, 1, 0, 0, 1e300, 0, 1, 0), 1e300, 1., 0.5, 0.5, 0.5, 0.5);
    seed(H, "t-dbl-max", 0x07, 18, ID3(0, 0, DBL_MAX), 0., 1., 0., 1., 0., 1.);
    seed(H, "negative-h-empty", 0x00, 18, ID3(0, 0, 0), 0., 1., 0., -1., 0., 1.);
    seed(H, "minus-zero-h-point", 0x00, 18, ID3(1, 2, 3), 0., -0., 5., -0., -5., -0.);
    seed(H, "nan-matrix", 0x07, 18, ID3(0, NaN, 0), 0., 1., 0., 1., 0., 1.);
    seed(H, "nan-h-inf-c", 0x00, 18, ID3(0, 0, 0), INF, 1., 0., NaN, 0., 1.);
    seed(H, "h-inf-zero-column", 0x07, 18, MAT(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 7),
         0., 1., 0., 1., 0., INF);
    seed(H, "h-inf-all", 0x07, 18, ID3(1, 2, 3), 0., INF, 1., INF, -1., INF);
    seed(H, "c-inf", 0x07, 18, ID3(0, 0, 0), INF, 1., 0., 1., 0., 1.);
    seed(H, "inf-matrix-entry", 0x07, 18, MAT(INF, 0, 0, 0, 0, -INF, 0, 0, 1, 1, 1, -INF),
         0., 1., 1., 1., 0., 1.);
    seed(H, "in-place-rotation", 0x47, 18,
         MAT(0.36, -0.48, 0.8, 10, 0.8, 0.6, 0, -3, -0.48, 0.64, 0.6, 0.5),
         0.3, 0.1, -1.7, 0.2, 2.5, 0.3);
    seed(H, "in-place-permutation", 0x47, 18, MAT(0, 1, 0, 5, 0, 0, 1, -7, 1, 0, 0, 0),
         0.5, 1.5, 3.5, 0.5, -5.5, 0.5);
    seed(H, "conv-edge-c-h", 0x07, 18, ID3(0, 0, 0), 0x1p1018, 0x1p1018, -0x1p1018, 0x1p1018,
         0., 0x1p1018);
    /* zero-coefficient columns dropped (0 * inf = 0): kind D */
    seed(H, "zero-col-c-h-inf", 0x07, 18, MAT(0, 1, 2, 3, -0., -1, 0.5, 0, 0, 0.25, -4, -1),
         -INF, INF, 1., 0.5, -2., 1.);
    seed(H, "neg-zero-col-dbl-max", 0x07, 18, MAT(1, -0., 0, 0, -0., 0, 1, 0, 1, -0., 1, 1),
         2., 1., DBL_MAX, 0x1p1023, -3., 0.5);
    seed(H, "zero-col-2p1018-ulp", 0x07, 18, MAT(1, 0, 0, 0, 0, 0, 1, 0, 1, -0., 1, 0),
         1., 1., -P1018U, P1018U, 1., 1.);
    seed(H, "zero-col-mix-lost", 0x07, 18, MAT(0, 1, 1, 0, 0, 1, 0, 0, -0., 0, 2, 0),
         INF, 1., 0., 1., 0., INF);
    seed(H, "all-zero-map-inf-box", 0x00, 18, MAT(0, -0., 0, 5, -0., 0, -0., -0x1p1018, 0, 0, 0, -0.),
         INF, INF, -INF, INF, DBL_MAX, INF);
    seed(H, "zero-col-tiny-not-zero", 0x07, 18, MAT(TINY, 1, 0, 0, -TINY, 0, 1, 0, 0, 1, 1, 0),
         INF, 0., 1., 1., 1., 1.);
    seed(H, "zero-col-neg-h-empty", 0x00, 18, MAT(-0., 1, 0, 0, 0, 0, 1, 0, 0, 1, 1, 0),
         INF, -INF, 1., 1., 1., 1.);
    seed(H, "in-place-zero-col", 0x47, 18, MAT(0, 1, 0, 5, 0, 0, 1, -7, -0., 1, 1, 0),
         -INF, INF, 3.5, 0.5, -5.5, 0.5);
}

static void box_to_cbox(void)
{
    const char *H = "box_to_cbox";
    seed(H, "unit-cube", 0x07, 6, 0., 1., 0., 1., 0., 1.);
    seed(H, "ordinary", 0x07, 6, -1., 3., 0.1, 0.3, -7.5, -2.25);
    seed(H, "points", 0x0f, 6, 0.1, 0., -1e300, 0., 3., 0.);
    seed(H, "one-ulp", 0x17, 6, 0.1, 0., 1e300, 0., -TINY, 0.);
    seed(H, "subnormals", 0x07, 6, -TINY, TINY, 0x0.fffffffffffffp-1022, 0x1p-1022, 0., TINY);
    seed(H, "edge-2p1019", 0x07, 6, -0x1p1019, 0x1p1019, 0x1p1019, 0x1p1019, -0x1p1019, -0x1p1019);
    seed(H, "edge-2p1019-ulp-out", 0x07, 6, 0., P1019U, 0., 1., -P1019U, 0.);
    seed(H, "dbl-max", 0x07, 6, -DBL_MAX, DBL_MAX, 0., 1., 0., 1.);
    seed(H, "mixed-magnitudes", 0x07, 6, -0x1p1019, TINY, 1e-300, 1e300, -1., 0x1p-1022);
    seed(H, "signed-zeros", 0x00, 6, -0., 0., 0., -0., -0., -0.);
    seed(H, "empty", 0x00, 6, 0., 1., 2., 1., 0., 1.);
    seed(H, "nan", 0x07, 6, 0., 1., NaN, 1., 0., 1.);
    seed(H, "nan-and-inf", 0x00, 6, -INF, 1., 0., NaN, 0., INF);
    seed(H, "whole-lines", 0x07, 6, -INF, INF, -INF, INF, -INF, INF);
    seed(H, "half-lines", 0x07, 6, -INF, 0., 1., INF, 0., 1.);
    seed(H, "at-plus-inf", 0x07, 6, INF, INF, 0., 1., 0., 1.);
    seed(H, "at-minus-inf", 0x00, 6, 0., 1., -INF, -INF, 0., 1.);
    seed(H, "cancel-near-zero", 0x07, 6, -0x1p1019, 0x1.fffffffffffffp1018, -1e-300, 1e-300,
         -3., 3.);
}

static void cbox_to_box(void)
{
    const char *H = "cbox_to_box";
    /* (c0, h0, c1, h1, c2, h2) */
    seed(H, "unit", 0x07, 6, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5);
    seed(H, "ordinary", 0x07, 6, 1., 2., 0.2, 0.1, -4.875, 2.625);
    seed(H, "points", 0x0f, 6, 0.1, 0., -1e300, 0., 3., 0.);
    seed(H, "cancel-h-eq-c", 0x17, 6, 0.1, 0., -1e300, 0., 0x1p1019, 0.);
    seed(H, "subnormals", 0x07, 6, TINY, TINY, 0x0.fffffffffffffp-1022, TINY, 0., TINY);
    seed(H, "edge-2p1019", 0x07, 6, 0x1p1019, 0x1p1019, -0x1p1019, 0x1p1019, 0., 0x1p1019);
    seed(H, "edge-2p1019-ulp-out", 0x07, 6, P1019U, 0., 0., 1., 0., P1019U);
    seed(H, "dbl-max", 0x07, 6, DBL_MAX, DBL_MAX, 0., 1., 0., 1.);
    seed(H, "signed-zeros", 0x00, 6, -0., 0., 0., -0., -0., -0.);
    seed(H, "negative-h-empty", 0x00, 6, 0., 1., 0., -TINY, 0., 1.);
    seed(H, "minus-inf-h-empty", 0x00, 6, 0., 1., 0., -INF, 0., 1.);
    seed(H, "nan", 0x07, 6, 0., 1., NaN, 1., 0., 1.);
    seed(H, "nan-and-inf", 0x00, 6, INF, 1., 0., NaN, 0., INF);
    seed(H, "h-inf", 0x07, 6, 0., INF, 1e300, INF, -5., 1.);
    seed(H, "c-inf", 0x07, 6, INF, 1., 0., 1., -INF, INF);
    seed(H, "mixed-magnitudes", 0x07, 6, 1e300, TINY, TINY, 1e300, -1., 0x1p-1022);
}

static void sphere_box(void)
{
    const char *H = "sphere_box";
    seed(H, "unit-sphere", 0x00, 12, ID3(0, 0, 0));
    seed(H, "translated-scaled", 0x00, 12, MAT(2, 0, 0, 5, 0, 3, 0, -7, 0, 0, 0.5, 0.25));
    seed(H, "decimal-rotation", 0x00, 12,
         MAT(0.36, -0.48, 0.8, 10, 0.8, 0.6, 0, -3, -0.48, 0.64, 0.6, 0.5));
    seed(H, "pythagorean-exact", 0x00, 12, MAT(3, 4, 0, 5, 0, 5, 12, -13, 1, 2, 2, 3));
    seed(H, "cancel-plus", 0x01, 12,
         MAT(0.36, -0.48, 0.8, 0, 0.1, 0.2, 0.3, 0, 1e-3, 1.1, -0.7, 0));
    seed(H, "cancel-minus", 0x03, 12,
         MAT(1e100, 3e99, -7e98, 0, 1, 1, 1, 0, TINY, TINY, 0, 0));
    seed(H, "edge-2p509", 0x00, 12,
         MAT(0x1p509, 0x1p509, 0x1p509, 0x1p1018, -0x1p509, 0, 0, -0x1p1018, 0, 0, 0x1p509, 0));
    seed(H, "edge-2p509-ulp-out", 0x00, 12, MAT(P509U, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0));
    seed(H, "t-1018-ulp-out", 0x00, 12, ID3(0x1p1018, -P1018U, 0));
    seed(H, "t-dbl-max", 0x00, 12, ID3(0, DBL_MAX, 0));
    seed(H, "subnormal-rows", 0x00, 12,
         MAT(TINY, TINY, TINY, 0, TINY, 0, 0, TINY, 0x1p-1022, -0x1p-1022, TINY, 0x1p-1060));
    seed(H, "tiny-rows-rescaled", 0x00, 12,
         MAT(0x1p-300, 0x1p-301, 0x1.fffffffffffffp-301, 0, 0x1p-537, 0x1p-537, 0x1p-537, 1,
             0x1p-400, 0, 0, 0x1p-400));
    seed(H, "huge-t-tiny-radius", 0x00, 12,
         MAT(0x1p-1000, 0, 0, 0x1p1018, 0, TINY, 0, -1e300, 0, 0, 1e-300, 1));
    seed(H, "zero-rows-signed", 0x00, 12, MAT(-0., 0., -0., 5, 0., 0., 0., -0., -0., -0., -0., 0));
    seed(H, "nan", 0x00, 12, ID3(0, NaN, 0));
    seed(H, "nan-and-inf", 0x00, 12, MAT(INF, 0, 0, 0, 0, 1, 0, NaN, 0, 0, 1, 0));
    seed(H, "inf-coefficient", 0x00, 12, MAT(INF, 0, 0, 0, 0, -INF, 0, 5, 0, 0, 1, 0));
    seed(H, "inf-t", 0x00, 12, ID3(INF, -INF, 0));
}

static void ellipsoid_box(void)
{
    const char *H = "ellipsoid_box";
    /* center[3], radii[3], rot[3][3] */
#define ROT_ID 1., 0., 0., 0., 1., 0., 0., 0., 1.
    seed(H, "unit-sphere", 0x00, 15, 0., 0., 0., 1., 1., 1., ROT_ID);
    seed(H, "axis-aligned", 0x00, 15, 1., -2., 3., 0.5, 2., 7., ROT_ID);
    seed(H, "quaternion-rot", 0x04, 15, 1., 2., 3., 1., 2., 3.,
         0.5, 0.1, -0.3, 0.7, 0., 0., 0., 0., 0.);
    seed(H, "quaternion-rot-cancel", 0x05, 15, 0., 0., 0., 1e-3, 1e3, 1.,
         0.9, 0.1, 0.1, 0.1, 0., 0., 0., 0., 0.);
    seed(H, "decimal-rot-cancel-minus", 0x03, 15, 0., 0., 0., 0.1, 0.2, 0.3,
         0.36, -0.48, 0.8, 0.8, 0.6, 0., -0.48, 0.64, 0.6);
    seed(H, "negative-zero-radii", 0x00, 15, 0., 0., 0., -2., 0., -0., ROT_ID);
    seed(H, "edge-2p254", 0x00, 15, 0x1p1018, -0x1p1018, 0., 0x1p254, -0x1p254, 0x1p254,
         0x1p254, 0x1p254, 0x1p254, -0x1p254, 0x1p254, 0., 1., 1., 1.);
    seed(H, "rot-2p254-ulp-out", 0x00, 15, 0., 0., 0., 1., 1., 1.,
         0., P254U, 0., 0., 1., 0., 0., 0., 1.);
    seed(H, "radius-2p254-ulp-out", 0x00, 15, 0., 0., 0., 1., -P254U, 1., ROT_ID);
    seed(H, "center-1018-ulp-out", 0x00, 15, 0., 0., P1018U, 1., 1., 1., ROT_ID);
    seed(H, "subnormal-rot-radii", 0x00, 15, 0., TINY, -0., TINY, TINY, TINY,
         TINY, TINY, TINY, TINY, 0., 0., 0x1p-1060, 1., 0.);
    seed(H, "extreme-radius-ratio", 0x00, 15, 1e300, 0., -1., 1e-300, 1e70, 1.,
         0.36, -0.48, 0.8, 0.8, 0.6, 0., -0.48, 0.64, 0.6);
    seed(H, "center-eq-radius", 0x00, 15, 5., -5., 0., 3., 4., 1.,
         1., 1., 0., 1., 1., 0., 0., 0., 1.);
    seed(H, "nan-radius", 0x00, 15, 0., 0., 0., 1., NaN, 1., ROT_ID);
    seed(H, "nan-center-inf-radius", 0x00, 15, 0., NaN, 0., INF, 1., 1., ROT_ID);
    seed(H, "inf-radius", 0x00, 15, 0., 0., 0., 1., 1., INF, ROT_ID);
    seed(H, "inf-rot-zero-radius", 0x00, 15, 0., 0., 0., 1., 0., 1.,
         1., INF, 0., 0., 1., 0., 0., 0., 1.);
    seed(H, "inf-center", 0x00, 15, -INF, 0., INF, 1., 1., 1., ROT_ID);
    seed(H, "dbl-max-center", 0x00, 15, DBL_MAX, 0., 0., 1., 1., 1., ROT_ID);
}

/* fuzz_plane: control bits 0..1 choose the function (box2, cbox2, disk,
 * ellipse), then 10 doubles (tests/fuzz/fuzz_plane.c). */
static void plane(void)
{
    const char *H = "plane";
    seed(H, "box2-identity", 0x00, 10, 1, 0, 0, 0, 1, 0, -1, 2, -3, 4);
    seed(H, "box2-rotation", 0x00, 10, 0.6, -0.8, 5, 0.8, 0.6, -5, -1, 1, 0.5, 2);
    seed(H, "box2-cancel", 0x0c, 10, 0.1, 0.7, 0, -3, 1e-3, 0, 3, 2, 1e10, -1e10);
    seed(H, "box2-edges", 0x00, 10, 0x1p509, -0x1p509, 0x1p1018, 1, 1, -0x1p1018,
         -0x1p509, 0x1p509, -1, 1);
    seed(H, "box2-halfplane", 0x00, 10, 1, 1, 0, -1, 2, 0, 2, INF, 0, 1);
    seed(H, "box2-empty", 0x00, 10, 1, 0, 0, 0, 1, 0, 1, 0, 0, 1);
    seed(H, "box2-nan", 0x00, 10, 1, NaN, 0, 0, 1, 0, 0, 1, 0, 1);
    seed(H, "cbox2-plain", 0x01, 10, 2, 1, 3, -1, 0.5, 0, 1, 0.25, -2, 3);
    seed(H, "cbox2-zero-column-inf", 0x01, 10, 0, 1, 0, 1, 0, 0, INF, INF, 1, 1);
    seed(H, "cbox2-negative-h", 0x01, 10, 1, 0, 0, 0, 1, 0, 0, -1, 0, 1);
    seed(H, "cbox2-edges", 0x05, 10, P509U, 1, 0, 1, 1, P1018U, 0x1p509, 0x1p509, 1, 1);
    seed(H, "disk-unit", 0x02, 10, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0);
    seed(H, "disk-pythagorean", 0x02, 10, 3, 4, 0.1, -5, 12, -7, 0, 0, 0, 0);
    seed(H, "disk-edges", 0x02, 10, 0x1p509, -0x1p509, 0x1p1018, P509U, 0, 0, 0, 0, 0, 0);
    seed(H, "disk-tiny", 0x02, 10, TINY, TINY, 0, 0x1p-600, 0x1p-601, 1e-300, 0, 0, 0, 0);
    seed(H, "disk-inf-nan", 0x02, 10, INF, 0, 0, 1, NaN, 1, 0, 0, 0, 0);
    seed(H, "ellipse-unit", 0x03, 10, 0, 0, 1, 1, 1, 0, 0, 1, 0, 0);
    seed(H, "ellipse-rotated", 0x03, 10, 5, -5, 3, 0.5, 0.6, -0.8, 0.8, 0.6, 0, 0);
    seed(H, "ellipse-edges", 0x03, 10, 0x1p1018, 0, 0x1p254, P254U, 0x1p254, -1, 1, 1, 0, 0);
    seed(H, "ellipse-negative-radius", 0x03, 10, 0, 0, -2, 0, 1, 0, 0, 1, 0, 0);
    seed(H, "ellipse-nan", 0x03, 10, 0, 0, 1, 1, NaN, 0, 0, 1, 0, 0);
}

/* fuzz_project: control bit 0 the format, 1 sort the box, 2 W clear; then
 * the 16 map entries and lo0, hi0, lo1, hi1, lo2, hi2
 * (tests/fuzz/fuzz_project.c). */
#define CAM90 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1.002, -0.2002, 0, 0, -1, 0
static void project(void)
{
    const char *H = "project";
    seed(H, "camera-cube-front", 0x00, 22, CAM90, -0.5, 0.5, -0.5, 0.5, -5.5, -4.5);
    seed(H, "camera-cube-front-f32", 0x01, 22, CAM90, -0.5, 0.5, -0.5, 0.5, -5.5, -4.5);
    seed(H, "camera-crossing", 0x00, 22, CAM90, -0.5, 0.5, -0.5, 0.5, -1, 1);
    seed(H, "camera-touching", 0x00, 22, CAM90, -0.5, 0.5, -0.5, 0.5, -1, 0);
    seed(H, "camera-behind", 0x00, 22, CAM90, -0.5, 0.5, -0.5, 0.5, 1, 2);
    seed(H, "camera-w-tiny", 0x00, 22, CAM90, -0.5, 0.5, -0.5, 0.5, -1, -0x1p-1000);
    seed(H, "camera-far-tiny", 0x00, 22, 1e6, 0, 0, 0, 0, 1e6, 0, 0, 0, 0, -1, -0.2, 0, 0, -1, 0,
         -1e-3, 1e-3, -1e-3, 1e-3, -1e5, -99999.999);
    seed(H, "affine-w-const", 0x04, 22, 0.6, -0.8, 0, 5, 0.8, 0.6, 0, -5, 0, 0, 1, 0, 0, 0, 0, 3,
         -1, 1, -2, 2, -3, 3);
    seed(H, "edges", 0x02, 22, 0x1p509, -0x1p509, 0x1p509, 0x1p1018, 1, 1, 1, -0x1p1018, 0, 0, 1, 0,
         0, 0, 0, 0x1p1018, -0x1p509, 0x1p509, -1, 1, 0, 0);
    seed(H, "empty", 0x00, 22, CAM90, 1, -1, -0.5, 0.5, -5.5, -4.5);
    seed(H, "nan-map", 0x00, 22, 1, NaN, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, -1, 0,
         -0.5, 0.5, -0.5, 0.5, -5.5, -4.5);
    seed(H, "inf-box", 0x00, 22, CAM90, -INF, 0.5, -0.5, 0.5, -5.5, -4.5);
    seed(H, "zero-w", 0x00, 22, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0,
         -1, 1, -1, 1, -1, 1);
}

/* fuzz_psphere: control bit 0 W clear, 1 a ball in front of a camera
 * looking down -z; then the 16 map entries, c0, c1, c2, r
 * (tests/fuzz/fuzz_psphere.c). */
static void psphere(void)
{
    const char *H = "psphere";
    seed(H, "camera-front", 0x00, 20, CAM90, 0.2, -0.1, -5, 1);
    seed(H, "camera-front-forced", 0x02, 20, CAM90, 0.2, -0.1, 5, 1);
    seed(H, "camera-crossing", 0x00, 20, CAM90, 0, 0, -1, 2);
    seed(H, "camera-tangent", 0x00, 20, CAM90, 0, 0, -1, 1);
    seed(H, "camera-behind", 0x00, 20, CAM90, 0, 0, 3, 1);
    seed(H, "camera-far-tiny", 0x00, 20, 1e6, 0, 0, 0, 0, 1e6, 0, 0, 0, 0, -1, -0.2, 0, 0, -1, 0,
         1e-3, -1e-3, -1e5, 1e-4);
    seed(H, "affine-w-const", 0x01, 20, 0.6, -0.8, 0, 5, 0.8, 0.6, 0, -5, 0, 0, 1, 0, 0, 0, 0, 3,
         1, 2, 3, 0.5);
    seed(H, "point", 0x00, 20, CAM90, 0.3, 0.3, -2, 0);
    seed(H, "negative-radius", 0x00, 20, CAM90, 0.3, 0.3, -4, -0.5);
    seed(H, "edges", 0x01, 20, 0x1p60, -0x1p60, 0x1p60, 0x1p120, 1, 1, 1, -0x1p120, 0, 0, 1, 0,
         0, 0, 0, 0x1p120, 0x1p60, -0x1p60, 1, 0x1p60);
    seed(H, "nan-radius", 0x00, 20, CAM90, 0, 0, -5, NaN);
    seed(H, "inf-center", 0x00, 20, CAM90, 0, INF, -5, 1);
    seed(H, "zero-w", 0x00, 20, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1);
}

/* fuzz_pell: control bit 0 W clear, 1 an ellipsoid in front of a camera
 * looking down -z, 2 rot the identity; then the 16 map entries, c0, c1,
 * c2, the radii and rot's 9 entries (tests/fuzz/fuzz_pell.c). */
#define ROT_TILT 0.6, -0.8, 0, 0.8, 0.6, 0, 0, 0, 1
static void pell(void)
{
    const char *H = "pell";
    seed(H, "camera-front", 0x00, 31, CAM90, 0.2, -0.1, -5, 1, 0.5, 0.25, ROT_TILT);
    seed(H, "camera-front-forced", 0x02, 31, CAM90, 0.2, -0.1, 5, 1, 2, 0.5, ROT_TILT);
    seed(H, "camera-crossing", 0x04, 31, CAM90, 0, 0, -1, 0.5, 0.5, 2, ROT_ID);
    seed(H, "camera-tangent", 0x04, 31, CAM90, 0, 0, -2, 0.5, 0.5, 2, ROT_ID);
    seed(H, "camera-behind", 0x00, 31, CAM90, 0, 0, 3, 1, 1, 1, ROT_TILT);
    seed(H, "camera-far-tiny", 0x00, 31, 1e6, 0, 0, 0, 0, 1e6, 0, 0, 0, 0, -1, -0.2, 0, 0, -1, 0,
         1e-3, -1e-3, -1e5, 1e-4, 1e-6, 1e-5, ROT_TILT);
    seed(H, "affine-w-const", 0x01, 31, 0.6, -0.8, 0, 5, 0.8, 0.6, 0, -5, 0, 0, 1, 0, 0, 0, 0, 3,
         1, 2, 3, 0.5, 0.25, 4, ROT_TILT);
    seed(H, "disk", 0x00, 31, CAM90, 0.3, 0.3, -4, 1, 1, 0, ROT_TILT);
    seed(H, "point", 0x00, 31, CAM90, 0.3, 0.3, -2, 0, 0, 0, ROT_ID);
    seed(H, "needle", 0x00, 31, CAM90, 0.1, 0.1, -5, 0.01, 0.01, 4.9, ROT_ID);
    seed(H, "singular-rot", 0x00, 31, CAM90, 0.3, 0.3, -4, 1, 2, 3, 1, 1, 1, 1, 1, 1, 1, 1, 1);
    seed(H, "negative-radii", 0x00, 31, CAM90, 0.3, 0.3, -4, -0.5, 1, -2, ROT_TILT);
    seed(H, "edges", 0x01, 31, 0x1p60, -0x1p60, 0x1p60, 0x1p120, 1, 1, 1, -0x1p120, 0, 0, 1, 0,
         0, 0, 0, 0x1p120, 0x1p60, -0x1p60, 1, 0x1p30, -0x1p30, 1, 0x1p30, 0, 0, 0, 1, 0, 0, 0, -0x1p30);
    seed(H, "nan-rot", 0x00, 31, CAM90, 0, 0, -5, 1, 1, 1, 1, 0, 0, 0, NaN, 0, 0, 0, 1);
    seed(H, "inf-radius", 0x00, 31, CAM90, 0, INF, -5, 1, INF, 1, ROT_ID);
    seed(H, "zero-w", 0x00, 31, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, ROT_ID);
}

static void pnear(void)
{
    const char *H = "pnear";
    seed(H, "camera-box-front", 0x00, 23, CAM90, -0.5, 0.5, -0.5, 0.5, -5.5, -4.5, 0.1);
    seed(H, "camera-box-crossing", 0x00, 23, CAM90, -0.5, 0.5, -0.5, 0.5, -1, 1, 0.1);
    seed(H, "camera-box-behind", 0x00, 23, CAM90, -0.5, 0.5, -0.5, 0.5, 1, 2, 0.1);
    seed(H, "camera-face-on-plane", 0x01, 23, CAM90, -0.5, 0.5, -0.5, 0.5, -0.1, 2, 0.1);
    seed(H, "camera-huge-box", 0x01, 23, CAM90, -1e6, 1e6, -1e6, 1e6, -1e6, 1e6, 0.01);
    seed(H, "swapped-ends", 0x06, 23, CAM90, 0.5, -0.5, 0.5, -0.5, 1, -1, -0.1);
    seed(H, "w-const", 0x00, 23, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 2, -1, 1, -1, 1, -1, 1, 2);
    seed(H, "edges", 0x00, 23, 0x1p60, -0x1p60, 0x1p60, 0x1p120, 1, 1, 1, -0x1p120, 0, 0, 1, 0,
         0, 0, -1, 0x1p120, -0x1p60, 0x1p60, -1, 1, -0x1p60, 0x1p60, 0x1p-100);
    seed(H, "zero-wn", 0x00, 23, CAM90, -0.5, 0.5, -0.5, 0.5, -1, 1, 0);
    seed(H, "nan-wn", 0x00, 23, CAM90, -0.5, 0.5, -0.5, 0.5, -1, 1, NaN);
    seed(H, "inf-box", 0x00, 23, CAM90, -0.5, 0.5, -0.5, INF, -1, 1, 0.1);
}

static void pball(void)
{
    const char *H = "pball";
    seed(H, "camera-ball-front", 0x00, 21, CAM90, 0, 0, -5, 1, 0.1);
    seed(H, "camera-ball-crossing", 0x00, 21, CAM90, 0.5, 0, -0.5, 1, 0.1);
    seed(H, "camera-ball-around", 0x00, 21, CAM90, 0, 0, 0, 4, 0.1);
    seed(H, "camera-ball-behind", 0x00, 21, CAM90, 0, 0, 5, 1, 0.1);
    seed(H, "camera-ball-touching", 0x01, 21, CAM90, 0, 0, 0.9, 1, 0.1);
    seed(H, "depth-row-parallel", 0x03, 21, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -2, -1, 0, 0, -1, 0, 1, 2, -3, 4, 0.5);
    seed(H, "w-const", 0x00, 21, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 2, 1, 2, 3, 4, 2);
    seed(H, "zero-radius", 0x00, 21, CAM90, 0, 0, -0.1, 0, 0.1);
    seed(H, "negative-radius", 0x00, 21, CAM90, 0.5, 0, -0.5, -1, 0.1);
    seed(H, "zero-wn", 0x00, 21, CAM90, 0, 0, -1, 2, 0);
    seed(H, "nan-wn", 0x00, 21, CAM90, 0, 0, -1, 2, NaN);
    seed(H, "inf-radius", 0x00, 21, CAM90, 0, 0, -1, INF, 0.1);
}

/* fuzz_pwide: its floats are 4 raw bytes each (little-endian binary32),
 * not fz_encode()'s doubles: seed_f32 writes the control byte, then each
 * value rounded to float (every value here is in float's range).  Control
 * bits 0-1 the twin (0 spheref, 1 box_nearf, 2 sphere_nearf), 2 camera row,
 * 3 center in front / box ordered, 4 |wn|, 5 exponents folded, 6 W clear;
 * then the 16 map entries and c0, c1, c2, r (spheref), lo0, hi0, lo1, hi1,
 * lo2, hi2, wn (box_nearf) or c0, c1, c2, r, wn (sphere_nearf)
 * (tests/fuzz/fuzz_pwide.c). */
static void seed_f32(const char *harness, const char *name, unsigned ctl,
                     const double *v, size_t n, size_t want)
{
    uint8_t buf[1024];
    size_t len = 0, k;
    char path[1024];
    FILE *f;

    if (n != want) {
        fprintf(stderr, "%s/%s: %lu values, the harness reads %lu\n", harness, name,
                (unsigned long)n, (unsigned long)want);
        exit(1);
    }
    buf[len++] = (uint8_t)ctl;
    for (k = 0; k < n; k++) {
        float x = (float)v[k];
        uint32_t u;
        int j;
        memcpy(&u, &x, sizeof u);
        for (j = 0; j < 4; j++) buf[len++] = (uint8_t)(u >> (8 * j));
    }
    snprintf(path, sizeof path, "%s/%s", outdir, harness);
    mkdir_p(path);
    snprintf(path, sizeof path, "%s/%s/%s", outdir, harness, name);
    f = fopen(path, "wb");
    if (!f || fwrite(buf, 1, len, f) != len || fclose(f) != 0) {
        perror(path);
        exit(1);
    }
    nwritten++;
}

#define seedf(h, name, ctl, n, ...)                                             \
    seed_f32(h, name, ctl, (const double[]){ __VA_ARGS__ },                     \
             sizeof((const double[]){ __VA_ARGS__ }) / sizeof(double), n)

static void pwide(void)
{
    const char *H = "pwide";
    /* spheref: 20 floats */
    seedf(H, "sph-camera-front", 0x00, 20, CAM90, 0.2, -0.1, -5, 1);
    seedf(H, "sph-camera-front-forced", 0x0c, 20, CAM90, 0.2, -0.1, 5, 1);
    seedf(H, "sph-affine-w-const", 0x00, 20, 0.6, -0.8, 0, 5, 0.8, 0.6, 0, -5, 0, 0, 1, 0, 0, 0, 0, 3,
          1, 2, 3, 0.5);
    seedf(H, "sph-far-tiny", 0x00, 20, 1e6, 0, 0, 0, 0, 1e6, 0, 0, 0, 0, -1, -0.2, 0, 0, -1, 0,
          1e-3, -1e-3, -1e5, 1e-4);
    seedf(H, "sph-camera-behind", 0x00, 20, CAM90, 0, 0, 3, 1);
    seedf(H, "sph-nan-radius", 0x00, 20, CAM90, 0, 0, -5, NaN);
    /* box_nearf: 23 floats */
    seedf(H, "near-camera-box-front", 0x01, 23, CAM90, -0.5, 0.5, -0.5, 0.5, -5.5, -4.5, 0.1);
    seedf(H, "near-camera-box-crossing", 0x01, 23, CAM90, -0.5, 0.5, -0.5, 0.5, -1, 1, 0.1);
    seedf(H, "near-camera-huge-box", 0x09, 23, CAM90, -1e6, 1e6, -1e6, 1e6, -1e6, 1e6, 0.01);
    seedf(H, "near-w-const", 0x01, 23, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 2,
          -1, 1, -1, 1, -1, 1, 1);
    seedf(H, "near-folded", 0x3d, 23, CAM90, 0.5, -0.5, 0.5, -0.5, 1, -1, -0.1);
    seedf(H, "near-camera-box-behind", 0x01, 23, CAM90, -0.5, 0.5, -0.5, 0.5, 1, 2, 0.1);
    seedf(H, "near-empty", 0x01, 23, CAM90, 1, -1, -0.5, 0.5, -5.5, -4.5, 0.1);
    seedf(H, "near-inf-box", 0x01, 23, CAM90, -0.5, 0.5, -0.5, INF, -1, 1, 0.1);
    /* sphere_nearf: 21 floats */
    seedf(H, "ball-camera-front", 0x02, 21, CAM90, 0, 0, -5, 1, 0.1);
    seedf(H, "ball-camera-crossing", 0x02, 21, CAM90, 0.5, 0, -0.5, 1, 0.1);
    seedf(H, "ball-camera-around", 0x02, 21, CAM90, 0, 0, 0, 4, 0.1);
    seedf(H, "ball-w-const", 0x02, 21, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 2, 1, 2, 3, 4, 1);
    seedf(H, "ball-folded", 0x3e, 21, CAM90, 0.5, 0.25, 3, 2, -0.125);
    seedf(H, "ball-camera-behind", 0x02, 21, CAM90, 0, 0, 5, 1, 0.1);
    seedf(H, "ball-zero-wn", 0x02, 21, CAM90, 0, 0, -1, 2, 0);
    /* ellipsoidf (control bit 7): 31 floats, the center, the radii, rot */
    seedf(H, "ell-camera-front", 0x80, 31, CAM90, 0.2, -0.1, -5, 1, 0.5, 0.25, 1, 0, 0, 0, 1, 0, 0, 0, 1);
    seedf(H, "ell-camera-front-forced", 0x8c, 31, CAM90, 0.2, -0.1, 5, 1, 0.5, 0.25, 1, 0, 0, 0, 1, 0, 0, 0, 1);
    seedf(H, "ell-disk-tilted", 0x80, 31, CAM90, 0.1, 0.2, -4, 1, 0.5, 0, 0.8, -0.36, 0.48, 0.6, 0.48, -0.64,
          0, 0.8, 0.6);
    seedf(H, "ell-needle-at-camera", 0x80, 31, CAM90, 0, 0, -2, 1e-9, 1e-9, 1.5, 1, 0, 0, 0, 1, 0, 0, 0, 1);
    seedf(H, "ell-camera-behind", 0x80, 31, CAM90, 0, 0, 5, 1, 1, 1, 1, 0, 0, 0, 1, 0, 0, 0, 1);
    seedf(H, "ell-nan-rot", 0x80, 31, CAM90, 0, 0, -5, 1, 1, 1, 1, 0, 0, 0, NaN, 0, 0, 0, 1);
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: %s OUTDIR\n", argv[0]);
        return 2;
    }
    outdir = argv[1];
    mkdir_p(outdir);
    transform_box();
    transform_cbox();
    box_to_cbox();
    cbox_to_box();
    sphere_box();
    ellipsoid_box();
    plane();
    project();
    psphere();
    pell();
    pnear();
    pball();
    pwide();
    printf("make_corpus: %d seeds written under %s\n", nwritten, outdir);
    return 0;
}
