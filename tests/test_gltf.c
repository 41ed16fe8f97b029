/*
 * The glTF reader against exact rational arithmetic (GMP), on files
 * nobody here wrote (Debian's assimp-testmodels) and on hand-made ones.
 *   test_gltf [ASSIMP_GLTF2_DIR [DATA_DIR [CERTBOX [N]]]]
 * defaults: /usr/share/assimp/models/glTF2 tests/data/gltf build/certbox 20000
 * (N: random cases of the library's cbx_transform_box_imat, as the tool
 * calls it, checked exactly; tests/test_imat.c is its full test)
 * For every file (every .gltf / .glb under ASSIMP_GLTF2_DIR, recursively,
 * and those of DATA_DIR/expect.txt): refused with the expected error,
 * flagged with the expected note, or loaded (expect.txt). For every
 * loaded file, twice (boxes from min/max, and --from-vertices):
 *   - every node's exact map (mpq): `matrix` as written, TRS as
 *     T * R(q)/|q|^2 * S with the exact normalised quaternion rotation;
 *   - every vertex of every mesh instance (float32 exactly, normalized
 *     integers as exact fractions) mapped by the exact product of its
 *     node chain lies inside its printed box (an infinite coordinate:
 *     the box end it pushes is infinite); with min/max boxes, also the 8
 *     corners of min/max (the promise itself);
 *   - the excess of each box end over the exact bound (relative to the
 *     axis' magnitude): the min/max image with min/max boxes, the vertex
 *     hull with --from-vertices;
 *   - (min/max load) every node's local interval matrix, and its world
 *     one (cbx_imat_compose down the chain), holds the exact map entry by
 *     entry.
 * Then cbx_transform_box_imat (the box transform the tool calls) alone on
 * random interval matrices and boxes (zeros, subnormals, near-overflow,
 * infinite ends): every axis in its fast range holds the exact extremes,
 * every other axis is exactly [-inf, +inf] with CBX_ERANGE.
 * Teeth: for each loaded file, one box end moved one ulp inside the exact
 * vertex hull must be caught.  Then the tool itself on a few files (its
 * printed numbers equal the boxes here, bit for bit; exit statuses).
 * Exit 1 on any failure.
 * This file is the driver (the checks of the static boxes, the files and the
 * tool, main, the order of the suites, the summary); its parts are
 * gltf_exact.c and gltf_files.c (gltf_parts.h, in build/libtestutil.a) and
 * gltf_anim.c (gltf_anim.h: the --animated checks, built like
 * gltf_oracle.c since they need the tool's headers and jansson).
 */
#define _XOPEN_SOURCE 700
/* 64-bit file offsets and inode numbers on 32-bit hosts too: without
 * it, readdir / stat fail with EOVERFLOW on file systems with large inode
 * numbers (armhf under qemu-user, scripts/cross.sh) */
#define _FILE_OFFSET_BITS 64
#include <dirent.h>
#include <float.h>
#include <stdarg.h>
#include <stdint.h>
#include <gmp.h>
#include <jansson.h>
#include <mpfr.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include "gltf.h"
#include "gltf_oracle.h"
#include "exact_util.h"
#include "gltf_parts.h"
#include "gltf_anim.h"


/* counts every failure (FAIL, gltf_anim.h), prints the first 50 */
long glt_n_fail;

/* the oracle's failures (gltf_oracle.c), counted and printed as FAIL's */
static void report(const char *fmt, ...)
{
    va_list ap;
    if (++glt_n_fail > 50)
        return;
    fputs("FAIL ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
}


/* Every node's interval matrices hold its exact maps entry by entry: the
 * local one (the tool's TRS interval arithmetic, or a `matrix` as points)
 * and, where the walk computed it, the world one (cbx_imat_compose down
 * the chain).  Checked directly: the box transform's own widening would
 * hide a local entry rounded inward by an ulp. */
static void check_node_maps(const gl_doc *d, stats *st, const char *file)
{
    gx_map *W = malloc((size_t)(d->nn + 1) * sizeof *W), L;
    if (!W) { fprintf(stderr, "out of memory\n"); exit(2); }
    mpq_t t;
    mpq_init(t);
    gx_init(&L);
    for (int k = 0; k < d->nn; k++) gx_init(&W[k]);
    for (int k = 0; k < d->nn; k++) {
        const gl_node *g = &d->nodes[k];
        gx_local(&L, g);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 4; j++)
                if (glt_q_out(L.m[i][j], g->local.lo[i][j], g->local.hi[i][j], t))
                    FAIL("%s: node %d: local entry (%d, %d) [%a, %a] misses the exact %.17g\n", file, k, i, j,
                         g->local.lo[i][j], g->local.hi[i][j], mpq_get_d(L.m[i][j]));
        st->locals++;
        if (!g->world_done) continue;
        const gx_map *M = gx_world(d, W, k);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 4; j++)
                if (glt_q_out(M->m[i][j], g->world.lo[i][j], g->world.hi[i][j], t))
                    FAIL("%s: node %d: world entry (%d, %d) [%a, %a] misses the exact %.17g\n", file, k, i, j,
                         g->world.lo[i][j], g->world.hi[i][j], mpq_get_d(M->m[i][j]));
        st->worlds++;
    }
    for (int k = 0; k < d->nn; k++) gx_clear(&W[k]);
    gx_clear(&L);
    mpq_clear(t);
    free(W);
}

/* All checks of one loaded document (fromv: --from-vertices boxes). */
static void check_doc(const gl_doc *d, int fromv, stats *st, const char *file)
{
    gx_map *W = malloc((size_t)(d->nn + 1) * sizeof *W);
    if (!W) { fprintf(stderr, "out of memory\n"); exit(2); }
    for (int k = 0; k < d->nn; k++) gx_init(&W[k]);
    mpq_t hlo[3], hhi[3], ilo, ihi;
    for (int j = 0; j < 3; j++) { mpq_init(hlo[j]); mpq_init(hhi[j]); }
    mpq_inits(ilo, ihi, NULL);
    int teeth_done = 0;
    for (int l = 0; l < d->nl; l++) {
        const gl_leaf *L = &d->leaves[l];
        const gl_acc *A = &d->accs[L->acc];
        const gx_map *M = gx_world(d, W, L->node);
        int nh;
        st->instances++;
        gx_check_leaf(d, L, &L->world, M, !fromv, !fromv, &st->c, file, report, hlo, hhi, &nh);
        /* the scene box holds the leaf box */
        const gl_scene *G = &d->scenes[L->scene];
        for (int i = 0; i < 3; i++)
            if (G->world.lo[i] > L->world.lo[i] || G->world.hi[i] < L->world.hi[i])
                FAIL("%s: scene %d does not hold leaf %s on axis %d\n", file, L->scene, L->path, i);
        int fin = !A->vinf && L->st != CBX_EINVAL;
        for (int i = 0; i < 3; i++) {
            /* rounding: over the exact image of the box that was mapped */
            if (fin) {
                glt_box_image(&L->local, M, i, ilo, ihi);
                double sc = glt_qabs_max(ilo, ihi);
                double e = glt_excess(L->world.lo[i], ilo, sc, 0), f = glt_excess(L->world.hi[i], ihi, sc, 1);
                double *mx = fromv ? &st->round_v : &st->round_mm;
                if (e > *mx) *mx = e;
                if (f > *mx) *mx = f;
            }
            /* all told: over the exact hull of the mapped vertices */
            if (nh > 0 && fin) {
                double sc = glt_qabs_max(hlo[i], hhi[i]), e = glt_excess(L->world.lo[i], hlo[i], sc, 0), f = glt_excess(L->world.hi[i], hhi[i], sc, 1);
                double *mx = fromv ? &st->excess_v : &st->excess_mm;
                if (e > *mx) *mx = e;
                if (f > *mx) *mx = f;
            }
        }
        /* teeth: lo[0] one ulp above the exact hull's lo must be caught */
        double h0 = nh > 0 ? mpq_get_d(hlo[0]) : 0.0;     /* beyond DBL_MAX: no double inside */
        if (!teeth_done && nh > 0 && isfinite(L->world.lo[0]) && !A->outside && isfinite(h0) && fabs(h0) < DBL_MAX) {
            cbx_box b = L->world;
            b.lo[0] = nextafter(mpq_get_d(hlo[0]), HUGE_VAL);   /* > exact min */
            gx_counts scratch;
            memset(&scratch, 0, sizeof scratch);
            int nh2;
            if (gx_check_leaf(d, L, &b, M, 0, !fromv, &scratch, file, NULL, hlo, hhi, &nh2) == 0)
                FAIL("%s: teeth: a box one ulp inside the exact hull was not caught (leaf %s)\n", file, L->path);
            st->teeth++;
            teeth_done = 1;
        }
    }
    for (int j = 0; j < 3; j++) { mpq_clear(hlo[j]); mpq_clear(hhi[j]); }
    mpq_clears(ilo, ihi, NULL);
    for (int k = 0; k < d->nn; k++) gx_clear(&W[k]);
    free(W);
}

/* Load one file both ways and check it against its expectation. */
static void run_file(const char *path, const char *label, const char *kind, const char *sub, stats *st)
{
    char err[700], notes[4096];
    gl_doc d;
    st->files++;
    FILE *nf = tmpfile();
    if (!nf) { fprintf(stderr, "tmpfile failed\n"); exit(2); }
    /* anim: loads with --animated (checked by check_anim); aerror:
     * refused with --animated; both load without it, with a note */
    int anim = strcmp(kind, "anim") == 0 || strcmp(kind, "aerror") == 0;
    const char *akind = kind, *asub = sub;
    if (anim) { kind = "flag"; sub = "not bounded: the boxes are for the static pose"; }
    int rc = gltf_load(&d, path, 0, nf, err, sizeof err);
    rewind(nf);
    size_t nn = fread(notes, 1, sizeof notes - 1, nf);
    notes[nn] = '\0';
    fclose(nf);
    /* one line each: the file's strings are quoted with their control
     * characters escaped (no newline inside an error or a note, no ESC) */
    for (const char *s = err; rc != 0 && *s; s++)
        if ((unsigned char)*s < 0x20 || *s == 0x7f) { FAIL("%s: control character 0x%02x in the error\n", label, (unsigned char)*s); break; }
    for (const char *s = notes; *s; s++)
        if (((unsigned char)*s < 0x20 && *s != '\n') || *s == 0x7f) { FAIL("%s: control character 0x%02x in a note\n", label, (unsigned char)*s); break; }
    if (strcmp(kind, "error") == 0) {
        if (rc == 0) { FAIL("%s: loaded, expected the error '%s'\n", label, sub); gltf_free(&d); return; }
        if (!strstr(err, sub)) FAIL("%s: error '%s' does not contain '%s'\n", label, err, sub);
        if (strncmp(err, path, strlen(path)) != 0 || err[strlen(path)] != ':')
            FAIL("%s: error '%s' does not start with 'FILE:'\n", label, err);
        st->refused++;
    } else if (rc != 0) {
        FAIL("%s: refused: %s\n", label, err);
        return;
    } else {
        st->loaded++;
        if (strcmp(kind, "flag") == 0) {
            if (!strstr(notes, sub)) FAIL("%s: notes '%s' do not contain '%s'\n", label, notes, sub);
            st->flagged++;
        } else if (d.notes != 0) {
            FAIL("%s: expected no note, got: %s\n", label, notes);
        }
        if (strstr(label, "2CylinderEngine.glb")) {
            int nm = 0, na = 0;
            long nv = 0, vi = 0;
            for (int k = 0; k < d.nn; k++) nm += d.nodes[k].has_matrix;
            for (int k = 0; k < d.na; k++) if (d.accs[k].used) { na++; nv += d.accs[k].count; }
            for (int k = 0; k < d.nl; k++) vi += d.accs[d.leaves[k].acc].count;
            printf("test_gltf: %s: %d nodes (%d with a matrix), %d POSITION accessors holding %ld vertices, "
                   "%d mesh instances, %ld vertex instances\n", label, d.nn, nm, na, nv, d.nl, vi);
        }
        check_doc(&d, 0, st, label);
        check_node_maps(&d, st, label);
        gltf_free(&d);
    }
    if (anim) {
        nf = tmpfile();
        if (!nf) { fprintf(stderr, "tmpfile failed\n"); exit(2); }
        rc = gltf_load(&d, path, GLTF_ANIMATED, nf, err, sizeof err);
        rewind(nf);
        nn = fread(notes, 1, sizeof notes - 1, nf);
        notes[nn] = '\0';
        fclose(nf);
        if (strcmp(akind, "aerror") == 0) {
            if (rc == 0) { FAIL("%s: loaded with --animated, expected the error '%s'\n", label, asub); gltf_free(&d); }
            else if (!strstr(err, asub)) FAIL("%s: error '%s' does not contain '%s'\n", label, err, asub);
            else st->refused++;
        } else if (rc != 0) {
            FAIL("%s: refused with --animated: %s\n", label, err);
        } else {
            if (d.notes != 0) FAIL("%s: --animated: expected no note, got: %s\n", label, notes);
            int loose = strstr(asub, "loose") != NULL;   /* containment only */
            glt_anim_no_stats = loose;
            double e = glt_check_anim(&d, label, st);
            gltf_free(&d);
            /* the excess is first order in the cells' length: 4 times as
             * many cells, at most half the excess (about a quarter) */
            if (gltf_load(&d, path, GLTF_ANIMATED | GLTF_CELLS(4 * GLTF_ANIM_CELLS), NULL, err, sizeof err) != 0) {
                FAIL("%s: refused with --animated --cells %d: %s\n", label, 4 * GLTF_ANIM_CELLS, err);
            } else {
                double e4 = glt_check_anim(&d, label, st);
                gltf_free(&d);
                if (!loose && (e > ANIM_MAX_EXCESS || e4 > e / 2))
                    FAIL("%s: --animated: excess %.3g at %d cells (at most %g), %.3g at %d (expected at most half)\n",
                         label, e, GLTF_ANIM_CELLS, ANIM_MAX_EXCESS, e4, 4 * GLTF_ANIM_CELLS);
                if (!loose && e4 > st->anim_excess4) st->anim_excess4 = e4;
            }
            /* --animation k: each animation alone, its poses inside, its
             * boxes inside those of all animations (same cells) */
            for (int k = 0; ; k++) {
                gl_doc all, one;
                if (gltf_load(&one, path, GLTF_ANIMATED | GLTF_ANIM_ONLY(k), NULL, err, sizeof err) != 0) {
                    if (!strstr(err, "--animation")) FAIL("%s: --animation %d: %s\n", label, k, err);
                    st->anim_only_refused += k > 0;
                    break;
                }
                (void)glt_check_anim(&one, label, st);
                if (gltf_load(&all, path, GLTF_ANIMATED, NULL, err, sizeof err) == 0) {
                    for (int l = 0; l < one.nl && l < all.nl; l++)
                        for (int i = 0; i < 3; i++)
                            if (one.leaves[l].world.lo[i] < all.leaves[l].world.lo[i]
                                || one.leaves[l].world.hi[i] > all.leaves[l].world.hi[i])
                                FAIL("%s: --animation %d: leaf %d axis %d outside the all-animations box\n", label, k, l, i);
                    gltf_free(&all);
                }
                gltf_free(&one);
                st->anim_only++;
            }
            /* coarse cells: wide enclosures, the same containment */
            for (int n = 1; n <= 3; n += 2) {
                if (gltf_load(&d, path, GLTF_ANIMATED | GLTF_CELLS(n), NULL, err, sizeof err) != 0) {
                    FAIL("%s: refused with --animated --cells %d: %s\n", label, n, err);
                    continue;
                }
                (void)glt_check_anim(&d, label, st);
                gltf_free(&d);
            }
            glt_anim_no_stats = 0;
        }
    }
    /* --from-vertices: every file with readable vertices loads (or is
     * refused for a reason that is not min/max) */
    if (gltf_load(&d, path, GLTF_FROM_VERTICES, NULL, err, sizeof err) == 0) {
        check_doc(&d, 1, st, label);
        gltf_free(&d);
    }
}

/* The tool: its printed boxes equal gltf_load's, bit for bit. */
static void run_tool(const char *certbox, const char *path, unsigned opts, int want_rc, stats *st)
{
    char cmd[1200], line[1200];
    snprintf(cmd, sizeof cmd, "%s --hex %s'%s' 2>/dev/null; echo \"rc $?\"", certbox,
             opts & GLTF_ANIMATED ? "--animated " : "", path);
    FILE *p = popen(cmd, "r");
    if (!p) { FAIL("popen %s\n", cmd); return; }
    gl_doc d;
    char err[700];
    int loaded = gltf_load(&d, path, opts, NULL, err, sizeof err) == 0, li = 0, si = 0, rc = -1;
    while (fgets(line, sizeof line, p)) {
        double v[6];
        char a[64], b[64], s[32];
        if (sscanf(line, "rc %d", &rc) == 1) continue;
        if (!loaded) { FAIL("tool printed for a refused file: %s", line); continue; }
        const cbx_box *bx = NULL;
        if (sscanf(line, "leaf %63s %63s lo %la %la %la hi %la %la %la %31s", a, b, &v[0], &v[1], &v[2], &v[3], &v[4], &v[5], s) == 9)
            bx = li < d.nl ? &d.leaves[li++].world : NULL;
        else if (sscanf(line, "scene lo %la %la %la hi %la %la %la %31s", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5], s) == 7)
            bx = si < d.ns ? &d.scenes[si++].world : NULL;
        if (!bx) { FAIL("tool line not understood: %s", line); continue; }
        for (int j = 0; j < 3; j++)
            if (memcmp(&v[j], &bx->lo[j], sizeof v[j]) != 0 || memcmp(&v[3 + j], &bx->hi[j], sizeof v[j]) != 0)
                FAIL("tool box differs from gltf_load's: %s", line);
    }
    pclose(p);
    if (rc != want_rc) FAIL("tool on %s: exit %d, expected %d\n", path, rc, want_rc);
    if (loaded && (li != d.nl || si != d.ns)) FAIL("tool on %s: %d leaves %d scenes printed, expected %d %d\n", path, li, si, d.nl, d.ns);
    if (loaded) gltf_free(&d);
    st->files++;
}

int main(int argc, char **argv)
{
    const char *adir = argc > 1 ? argv[1] : "/usr/share/assimp/models/glTF2";
    const char *ddir = argc > 2 ? argv[2] : "tests/data/gltf";
    const char *tool = argc > 3 ? argv[3] : "build/certbox";
    char path[1200];
    clock_t t0 = clock();
    stats st;
    memset(&st, 0, sizeof st);
    expect *ex;
    snprintf(path, sizeof path, "%s/expect.txt", ddir);
    int ne = glt_read_expect(path, &ex);
    char **files = NULL;
    int nf = 0, cap = 0;
    glt_find_files(adir, &files, &nf, &cap);
    if (nf == 0) { fprintf(stderr, "FAIL no glTF file under %s (install assimp-testmodels: sh scripts/deps.sh test)\n", adir); return 1; }
    qsort(files, (size_t)nf, sizeof *files, glt_cmpstr);
    long assimp_files = nf;
    for (int k = 0; k < nf; k++) {
        const char *rel = files[k] + strlen(adir) + 1, *kind = "ok", *sub = "";
        for (int e = 0; e < ne; e++)
            if (strncmp(ex[e].file, "assimp:", 7) == 0 && strcmp(ex[e].file + 7, rel) == 0) {
                kind = ex[e].kind; sub = ex[e].sub; ex[e].seen = 1;
            }
        run_file(files[k], rel, kind, sub, &st);
    }
    for (int e = 0; e < ne; e++) {
        if (strncmp(ex[e].file, "data:", 5) == 0) {
            snprintf(path, sizeof path, "%s/%s", ddir, ex[e].file + 5);
            run_file(path, ex[e].file, ex[e].kind, ex[e].sub, &st);
            ex[e].seen = 1;
        }
        if (!ex[e].seen) FAIL("%s: listed in expect.txt but not found\n", ex[e].file);
    }
    int nhand = 0;
    for (int e = 0; e < ne; e++) nhand += strncmp(ex[e].file, "data:", 5) == 0;
    printf("test_gltf: %ld files (%ld from assimp-testmodels, %d hand-made): %ld loaded (%ld of them flagged), %ld refused with the expected error\n",
           st.files, assimp_files, nhand, st.loaded, st.flagged, st.refused);
    printf("test_gltf: %ld mesh instances (min/max boxes and --from-vertices boxes), %ld vertex instances inside their box (exact, GMP), "
           "%ld min/max corners inside, %ld infinite-coordinate ends, %ld teeth caught\n",
           st.instances, st.c.vertices, st.c.corners, st.c.inf_checks, st.teeth);
    printf("test_gltf: node maps: %ld local interval matrices (TRS in outward interval arithmetic, or `matrix`) and %ld world ones "
           "(cbx_imat_compose down the chain) hold the exact maps entry by entry (GMP)\n", st.locals, st.worlds);
    printf("test_gltf: max relative excess (per axis, relative to the axis' largest magnitude) of a box over the exact image of\n"
           "  the box it maps (rounding only): %.3g with min/max boxes, %.3g with --from-vertices\n"
           "  the exact hull of the mapped vertices (rounding + boxing in local coordinates + loose min/max): %.3g with min/max, %.3g with --from-vertices\n",
           st.round_mm, st.round_v, st.excess_mm, st.excess_v);
    printf("test_gltf: --animated: %ld loads (each file at 1, 3, 32 and 128 cells per key interval, and each animation alone), %ld animation keys read as written, %ld poses (key times, %d random times between "
           "each two, times before and after), %ld instance axes at them inside their boxes (exact maps; slerp in MPFR at 256 bits)\n",
           st.anim_files, st.anim_keys, st.anim_poses, ANIM_T, st.anim_checks);
    printf("test_gltf: --animated --animation k: %ld single-animation loads checked the same way, each inside the "
           "all-animations boxes; %ld out-of-range indices refused\n", st.anim_only, st.anim_only_refused);
    printf("test_gltf: --animated: excess of a box over the hull of its sampled images, relative to the hull's extent: "
           "max %.3g (at most %g), mean %.3g over %ld axes at %d cells per key interval; max %.3g at %d cells\n",
           st.anim_excess, ANIM_MAX_EXCESS, st.anim_axes ? st.anim_excess_sum / (double)st.anim_axes : 0.0, st.anim_axes,
           GLTF_ANIM_CELLS, st.anim_excess4, 4 * GLTF_ANIM_CELLS);
    long nimat = argc > 4 ? atol(argv[4]) : 20000;
    glt_test_imat_box(nimat, &glt_n_fail, &st.imat_fin, &st.imat_inf);
    printf("test_gltf: cbx_transform_box_imat on %ld random interval matrices and boxes (zeros, subnormals, near-overflow): "
           "%ld cases in the fast range hold the exact extremes of every row (GMP), %ld with an axis outside it "
           "(infinite or huge ends) have exactly that axis [-inf, +inf] with CBX_ERANGE\n", nimat, st.imat_fin, st.imat_inf);
    /* the tool itself */
    long before = glt_n_fail, nfiles = st.files;
    char p1[1200], p2[1200], p3[1200];
    snprintf(p1, sizeof p1, "%s/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", adir);
    snprintf(p2, sizeof p2, "%s/trs.gltf", ddir);
    snprintf(p3, sizeof p3, "%s/RecursiveNodes/RecursiveNodes.gltf", adir);
    st.files = 0;
    run_tool(tool, p1, 0, 0, &st);
    run_tool(tool, p2, 0, 0, &st);
    run_tool(tool, p3, 0, 2, &st);
    snprintf(p3, sizeof p3, "%s/claims.gltf", ddir);
    run_tool(tool, p3, 0, 1, &st);
    snprintf(p3, sizeof p3, "%s/anim_rot.gltf", ddir);
    run_tool(tool, p3, 0, 1, &st);                 /* the note: static pose only */
    run_tool(tool, p3, GLTF_ANIMATED, 0, &st);
    snprintf(p3, sizeof p3, "%s/anim_time.gltf", ddir);
    run_tool(tool, p3, GLTF_ANIMATED, 2, &st);
    printf("test_gltf: the tool on %ld files: printed boxes equal gltf_load's bit for bit, exit statuses as expected%s\n",
           st.files, glt_n_fail > before ? " (NOT: see above)" : "");
    printf("test_gltf: %.1f s, %ld failure%s\n", (double)(clock() - t0) / CLOCKS_PER_SEC, glt_n_fail, glt_n_fail == 1 ? "" : "s");
    /* the suites' last line (scripts/cross.sh, scripts/evidence.py): the
     * items are the files, mesh instances, random imat_box cases and tool runs */
    long items = nfiles + st.instances + st.imat_fin + st.imat_inf + st.files;
    printf("%ld passed, %ld failed\n", items > glt_n_fail ? items - glt_n_fail : 0, glt_n_fail);
    for (int k = 0; k < nf; k++) free(files[k]);
    free(files);
    free(ex);
    return glt_n_fail ? 1 : 0;
}
