/*
 * libFuzzer harness: the glTF reader (tools/certbox/gltf.c) against the exact
 * oracle of tests/test_gltf.c (tests/gltf_oracle.c, shared: one copy).
 *
 * Input: the bytes of a .gltf or .glb file.  gltf_load reads files, so
 * each input is written to `input` in a private folder made once per
 * process (mkdtemp under $TMPDIR or /tmp, removed at exit) that holds
 * nothing else: a relative buffer `uri` can only name the input itself
 * (read as its own .bin, deterministic) or fail; absolute paths, `..`,
 * schemes and symbolic links out of the folder are refused by the reader.
 * Every input is loaded three times: boxes from min/max, then
 * --from-vertices, then min/max with --animated (2 cells per key
 * interval: its boxes hold the static pose too, so the same oracle
 * applies; the animated poses are test_gltf's).
 *
 * Oracle (abort() on failure, the input in the crash reproducer):
 *   - the reader returns 0 or -1; on -1 the error is a non-empty line
 *     starting with the file's path and ':';
 *   - on 0: every status documented, no NaN in any box; every leaf box
 *     (CBX_EINVAL: the whole space) contains every vertex of its accessor
 *     mapped by the exact (GMP) product of its node chain (gx_check_leaf:
 *     float32 and normalized integers exactly; an infinite coordinate
 *     must give an infinite end) and, with min/max boxes, the 8 min/max
 *     corners (vertices outside a flagged accessor's min/max excepted:
 *     those boxes are documented as wrong, with a note); every scene box
 *     holds its leaves' boxes; a scene with no leaf is CBX_EMPTY;
 *   - ASan/UBSan: no memory error, leak or undefined behaviour; libFuzzer:
 *     no hang (-timeout) and no huge allocation (-rss_limit_mb).
 */
#define _XOPEN_SOURCE 700          /* mkdtemp */
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "gltf.h"
#include "gltf_oracle.h"

static char dir[512], path[600];
static const uint8_t *IN;
static size_t NIN;
static int FROMV;

static void cleanup(void)
{
    if (path[0]) unlink(path);
    if (dir[0]) rmdir(dir);
}

static void fail(const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "\n==== certbox fuzz oracle FAILURE in fuzz_gltf: ");
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, "\n---- input (%zu bytes, %s boxes):\n", NIN, FROMV == 1 ? "--from-vertices" : FROMV ? "--animated" : "min/max");
    fwrite(IN, 1, NIN < 2000 ? NIN : 2000, stderr);
    fprintf(stderr, "\n====\n");
    fflush(stderr);
    abort();
}

/* the oracle's reports: the first is fatal */
static void report(const char *fmt, ...)
{
    char msg[600];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    fail("%s", msg);
}

static int known(cbx_status s)
{
    return s == CBX_OK || s == CBX_ERANGE || s == CBX_EINVAL || s == CBX_EMPTY;
}

static void check(const gl_doc *d)
{
    gx_map *W = malloc((size_t)(d->nn + 1) * sizeof *W);
    mpq_t hlo[3], hhi[3];
    gx_counts cnt;
    if (!W) fail("out of memory in the harness");
    for (int k = 0; k < d->nn; k++) gx_init(&W[k]);
    for (int j = 0; j < 3; j++) { mpq_init(hlo[j]); mpq_init(hhi[j]); }
    memset(&cnt, 0, sizeof cnt);
    for (int l = 0; l < d->nl; l++) {
        const gl_leaf *L = &d->leaves[l];
        int nh;
        if (!known(L->st)) fail("leaf %s: undocumented status %d", L->path, (int)L->st);
        if (L->scene < 0 || L->scene >= d->ns || L->acc < 0 || L->acc >= d->na || L->node < 0 || L->node >= d->nn)
            fail("leaf %d: scene %d, accessor %d or node %d out of range", l, L->scene, L->acc, L->node);
        for (int i = 0; i < 3; i++)
            if (isnan(L->world.lo[i]) || isnan(L->world.hi[i]) || L->world.lo[i] > L->world.hi[i])
                fail("leaf %s: axis %d is [%a, %a]", L->path, i, L->world.lo[i], L->world.hi[i]);
        gx_check_leaf(d, L, &L->world, gx_world(d, W, L->node), FROMV != 1, FROMV != 1, &cnt, "input", report,
                      hlo, hhi, &nh);
        const gl_scene *G = &d->scenes[L->scene];
        for (int i = 0; i < 3; i++)
            if (!(G->world.lo[i] <= L->world.lo[i]) || !(G->world.hi[i] >= L->world.hi[i]))
                fail("scene %d does not hold leaf %s on axis %d", L->scene, L->path, i);
    }
    for (int s = 0; s < d->ns; s++) {
        const gl_scene *G = &d->scenes[s];
        if (!known(G->st)) fail("scene %d: undocumented status %d", s, (int)G->st);
        if ((G->n == 0) != (G->st == CBX_EMPTY)) fail("scene %d: %d leaves, status %s", s, G->n, cbx_status_name(G->st));
        for (int i = 0; i < 3; i++)
            if (isnan(G->world.lo[i]) || isnan(G->world.hi[i]))
                fail("scene %d: NaN on axis %d", s, i);
    }
    for (int j = 0; j < 3; j++) { mpq_clear(hlo[j]); mpq_clear(hhi[j]); }
    for (int k = 0; k < d->nn; k++) gx_clear(&W[k]);
    free(W);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (!dir[0]) {
        const char *t = getenv("TMPDIR");
        snprintf(dir, sizeof dir, "%s/certbox-fuzz-gltf.XXXXXX", t && *t ? t : "/tmp");
        if (!mkdtemp(dir)) { perror(dir); abort(); }
        snprintf(path, sizeof path, "%s/input", dir);
        atexit(cleanup);
    }
    IN = data;
    NIN = size;
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(data, 1, size, f) != size || fclose(f) != 0) { perror(path); abort(); }
    for (FROMV = 0; FROMV < 3; FROMV++) {
        gl_doc d;
        char err[700];
        err[0] = '\0';
        unsigned opts = FROMV == 1 ? GLTF_FROM_VERTICES : FROMV ? GLTF_ANIMATED | GLTF_CELLS(2) : 0u;
        int rc = gltf_load(&d, path, opts, NULL, err, sizeof err);
        if (rc != 0) {
            if (rc != -1) fail("gltf_load returned %d", rc);
            if (strncmp(err, path, strlen(path)) != 0 || err[strlen(path)] != ':' || strchr(err, '\n'))
                fail("the error '%s' is not one line starting with 'FILE:'", err);
            continue;
        }
        check(&d);
        gltf_free(&d);
    }
    return 0;
}
