/*
 * Scene files: parsing and evaluation (see scene.h and
 * examples/scene-format.md).
 *
 * Soundness: no matrix is ever multiplied in round-to-nearest floating
 * point.  A leaf's bound in its node's coordinates comes from a proven
 * function (cbx_ellipsoid_box for spheres and ellipsoids: exact
 * dual-quadric bound, outward rounded; a box is itself), then the
 * operations of the node and of its static ancestors up to the next motion
 * node, last first, map the current box by one call of
 * cbx_transform_box_chain (proven: the image of every point of the box
 * under the exact product of those matrices lies in the result; each step
 * is cbx_transform_box_as with the class computed at load time), a motion
 * node by cbx_motion_box, and so on up to the root, or
 * for a leaf deeper than SC_WALK steps, up to where interval maps composed
 * with outward rounding take over (see "deep leaves" below).  Each step
 * contains the exact image of the previous box, so the world box contains
 * the exact image of the leaf under the exact product of the given double
 * matrices.
 */
#include "scene.h"
#include "readall.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double SC_PI = 3.14159265358979323846;

int scene_severity(cbx_status st)
{
    if (st == CBX_EINVAL) return 3;
    if (st == CBX_ERANGE) return 2;
    if (st == CBX_EMPTY) return 1;
    return 0;
}

const char *scene_kind_name(int kind)
{
    return kind == SC_BOX ? "box" : kind == SC_SPHERE ? "sphere" : "ellipsoid";
}

void scene_free(scene *s)
{
    free(s->nodes);
    free(s->ops);
    free(s->leaves);
    free(s->keys);
    free(s->hash);
    memset(s, 0, sizeof *s);
}

/* ---- parsing ------------------------------------------------------------ */
typedef struct parser {
    scene *s;
    const char *file;
    int line;
    char *err;
    size_t errlen;
    int cur;            /* node receiving operations, -1 if none */
    int side;           /* 0 before `motion`, 1 after */
    int n0, n1;         /* operations on each side of the current node */
} parser;

static int fail(parser *p, const char *fmt, ...)
{
    char msg[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    snprintf(p->err, p->errlen, "%s:%d: %s", p->file, p->line, msg);
    return -1;
}

static unsigned long name_hash(const char *n)
{
    unsigned long h = 5381;
    while (*n)
        h = h * 33u + (unsigned char)*n++;
    return h;
}

/* index+1 of a node (> 0), -(leaf+1) (< 0), or 0 if the name is unknown */
static int lookup(const scene *s, const char *name)
{
    if (s->hcap == 0)
        return 0;
    unsigned long i = name_hash(name) % (unsigned long)s->hcap;
    while (s->hash[i] != 0) {
        int v = s->hash[i];
        const char *m = v > 0 ? s->nodes[v - 1].name : s->leaves[-v - 1].name;
        if (strcmp(m, name) == 0)
            return v;
        i = (i + 1) % (unsigned long)s->hcap;
    }
    return 0;
}

static int rehash(scene *s, int cap)
{
    int *h = calloc((size_t)cap, sizeof *h);
    if (!h)
        return -1;
    free(s->hash);
    s->hash = h;
    s->hcap = cap;
    for (int k = 0; k < s->nn; k++) {
        unsigned long i = name_hash(s->nodes[k].name) % (unsigned long)cap;
        while (h[i]) i = (i + 1) % (unsigned long)cap;
        h[i] = k + 1;
    }
    for (int k = 0; k < s->nl; k++) {
        unsigned long i = name_hash(s->leaves[k].name) % (unsigned long)cap;
        while (h[i]) i = (i + 1) % (unsigned long)cap;
        h[i] = -(k + 1);
    }
    return 0;
}

/* Register the newest node (v > 0) or leaf (v < 0) in the name table. */
static int add_name(parser *p, int v)
{
    scene *s = p->s;
    if (2 * (s->nn + s->nl) >= s->hcap && rehash(s, s->hcap ? 2 * s->hcap : 64) != 0)
        return fail(p, "out of memory");
    const char *n = v > 0 ? s->nodes[v - 1].name : s->leaves[-v - 1].name;
    unsigned long i = name_hash(n) % (unsigned long)s->hcap;
    while (s->hash[i]) i = (i + 1) % (unsigned long)s->hcap;
    s->hash[i] = v;
    return 0;
}

static int grow(void **ptr, int *cap, int need, size_t elem)
{
    if (need <= *cap)
        return 0;
    int c = *cap ? *cap : 16;
    while (c < need) c *= 2;
    void *q = realloc(*ptr, (size_t)c * elem);
    if (!q)
        return -1;
    *ptr = q;
    *cap = c;
    return 0;
}

static int parse_num(parser *p, const char *tok, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(tok, &end);
    if (end == tok || *end != '\0')
        return fail(p, "bad number '%s'", tok);
    if (!isfinite(v))
        return fail(p, "number '%s' is not finite", tok);
    *out = v;
    return 0;
}

static int parse_nums(parser *p, char **tok, int n, double *out)
{
    for (int k = 0; k < n; k++)
        if (parse_num(p, tok[k], &out[k]) != 0)
            return -1;
    return 0;
}

static int check_name(parser *p, const char *name)
{
    size_t n = strlen(name);
    if (n == 0 || n >= SC_NAME_MAX)
        return fail(p, "name '%s' must have 1 to %d characters", name, SC_NAME_MAX - 1);
    for (size_t k = 0; k < n; k++) {
        char c = name[k];
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9')
              || c == '_' || c == '.' || c == '-'))
            return fail(p, "name '%s' has a character outside [A-Za-z0-9_.-]", name);
    }
    if (lookup(p->s, name) != 0)
        return fail(p, "name '%s' is already used", name);
    return 0;
}

/* The rotation about axis (x, y, z) by deg degrees.  A coordinate axis and
 * a multiple of 90 degrees give exact 0 / +-1 entries. */
static void rotation(double x, double y, double z, double deg, double r[3][3])
{
    double n[3], c, s;
    int nz = (x != 0.0) + (y != 0.0) + (z != 0.0);
    if (nz == 1 && fmod(deg, 90.0) == 0.0) {
        static const double cs[4] = {1.0, 0.0, -1.0, 0.0}, sn[4] = {0.0, 1.0, 0.0, -1.0};
        long k = (long)fmod(deg / 90.0, 4.0);
        k = (k % 4 + 4) % 4;
        c = cs[k];
        s = sn[k];
        n[0] = x > 0 ? 1.0 : x < 0 ? -1.0 : 0.0;
        n[1] = y > 0 ? 1.0 : y < 0 ? -1.0 : 0.0;
        n[2] = z > 0 ? 1.0 : z < 0 ? -1.0 : 0.0;
    } else {
        /* Scale the axis by a power of two (exact) so that its largest
         * component lies in [0.5, 1): x*x can then neither overflow nor
         * underflow to nothing (2e-162 squared did, and gave a non-rotation;
         * 1e-170 gave 0/0).  The same bits as unscaled for every axis whose
         * squares were in range: scaling by 2^k commutes with each rounding. */
        int e;
        (void)frexp(fmax(fabs(x), fmax(fabs(y), fabs(z))), &e);
        x = ldexp(x, -e); y = ldexp(y, -e); z = ldexp(z, -e);
        double len = sqrt(x * x + y * y + z * z);
        n[0] = x / len; n[1] = y / len; n[2] = z / len;
        double t = deg * (SC_PI / 180.0);
        c = cos(t);
        s = sin(t);
    }
    /* Rodrigues: R = c I + s [n]x + (1 - c) n n^T */
    double k = 1.0 - c;
    r[0][0] = c + k * n[0] * n[0];        r[0][1] = k * n[0] * n[1] - s * n[2]; r[0][2] = k * n[0] * n[2] + s * n[1];
    r[1][0] = k * n[1] * n[0] + s * n[2]; r[1][1] = c + k * n[1] * n[1];        r[1][2] = k * n[1] * n[2] - s * n[0];
    r[2][0] = k * n[2] * n[0] - s * n[1]; r[2][1] = k * n[2] * n[1] + s * n[0]; r[2][2] = c + k * n[2] * n[2];
}

static int add_op(parser *p, const cbx_affine *a)
{
    scene *s = p->s;
    if (p->cur < 0)
        return fail(p, "operation outside a node (declare `node NAME [PARENT]` first)");
    if (s->nodes[p->cur].trs)
        return fail(p, "node '%s' has keyframes: it takes no other operation", s->nodes[p->cur].name);
    if (s->no >= SC_COUNT_MAX)
        return fail(p, "more than %d operations", SC_COUNT_MAX);
    if (grow((void **)&s->ops, &s->capo, s->no + 1, sizeof *s->ops) != 0)
        return fail(p, "out of memory");
    cbx_prepare(a, &s->ops[s->no]);
    s->no++;
    s->nodes[p->cur].n++;
    if (p->side) p->n1++; else p->n0++;
    return 0;
}

/* Close the current node: a motion node needs one operation per side. */
static int close_node(parser *p)
{
    if (p->cur >= 0 && p->s->nodes[p->cur].motion && !p->s->nodes[p->cur].trs && (p->n0 != 1 || p->n1 != 1)) {
        int saved = p->line;
        p->line = p->s->nodes[p->cur].line;
        fail(p, "motion node '%s' needs exactly one operation before and one after "
                "`motion` (it has %d and %d): M(s) interpolates two given matrices; write one `matrix` per side",
             p->s->nodes[p->cur].name, p->n0, p->n1);
        p->line = saved;
        return -1;
    }
    p->cur = -1;
    return 0;
}

static int statement(parser *p, char **tok, int nt)
{
    scene *s = p->s;
    const char *w = tok[0];
    cbx_affine a;
    memset(&a, 0, sizeof a);
    if (strcmp(w, "node") == 0) {
        if (nt != 2 && nt != 3)
            return fail(p, "usage: node NAME [PARENT]");
        if (close_node(p) != 0 || check_name(p, tok[1]) != 0)
            return -1;
        int parent = -1;
        if (nt == 3) {
            int v = lookup(s, tok[2]);
            if (v <= 0)
                return fail(p, "parent '%s' is not a declared node", tok[2]);
            parent = v - 1;
        }
        if (s->nn >= SC_COUNT_MAX)
            return fail(p, "more than %d nodes", SC_COUNT_MAX);
        if (grow((void **)&s->nodes, &s->capn, s->nn + 1, sizeof *s->nodes) != 0)
            return fail(p, "out of memory");
        sc_node *n = &s->nodes[s->nn];
        memset(n, 0, sizeof *n);
        strcpy(n->name, tok[1]);
        n->parent = parent;
        n->first = s->no;
        n->line = p->line;
        s->nn++;
        p->cur = s->nn - 1;
        p->side = 0;
        p->n0 = p->n1 = 0;
        return add_name(p, s->nn);
    }
    if (strcmp(w, "translate") == 0 || strcmp(w, "scale") == 0) {
        double v[3];
        if (nt != 4)
            return fail(p, "usage: %s X Y Z", w);
        if (parse_nums(p, tok + 1, 3, v) != 0)
            return -1;
        for (int i = 0; i < 3; i++) {
            if (w[0] == 't') { a.m[i][i] = 1.0; a.m[i][3] = v[i]; }
            else a.m[i][i] = v[i];
        }
        return add_op(p, &a);
    }
    if (strcmp(w, "rotate") == 0) {
        double v[4], r[3][3];
        if (nt != 5)
            return fail(p, "usage: rotate AX AY AZ DEGREES");
        if (parse_nums(p, tok + 1, 4, v) != 0)
            return -1;
        if (v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0)
            return fail(p, "rotation axis is zero");
        if (!(fabs(v[3]) < 1e15))   /* beyond, DEG * pi / 180 has no meaningful fraction of a turn */
            return fail(p, "rotation angle too large (|DEGREES| must be below 1e15)");
        rotation(v[0], v[1], v[2], v[3], r);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                a.m[i][j] = r[i][j];
        return add_op(p, &a);
    }
    if (strcmp(w, "matrix") == 0) {
        double v[12];
        if (nt != 13)
            return fail(p, "usage: matrix M00 M01 M02 M03 M10 ... M23 (12 numbers, row-major)");
        if (parse_nums(p, tok + 1, 12, v) != 0)
            return -1;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 4; j++)
                a.m[i][j] = v[4 * i + j];
        return add_op(p, &a);
    }
    if (strcmp(w, "motion") == 0) {
        if (nt != 1)
            return fail(p, "usage: motion");
        if (p->cur < 0)
            return fail(p, "motion outside a node");
        if (s->nodes[p->cur].trs)
            return fail(p, "node '%s' has keyframes: it takes no `motion`", s->nodes[p->cur].name);
        if (s->nodes[p->cur].motion)
            return fail(p, "second `motion` in node '%s'", s->nodes[p->cur].name);
        s->nodes[p->cur].motion = 1;
        p->side = 1;
        return 0;
    }
    if (strcmp(w, "keyframes") == 0) {
        double v[20];
        int nl = 0;
        if (nt == 22 && strcmp(tok[21], "nlerp") == 0)
            nl = 1;
        else if (!(nt == 21 || (nt == 22 && strcmp(tok[21], "slerp") == 0)))
            return fail(p, "usage: keyframes TX TY TZ QX QY QZ QW SX SY SZ TX TY TZ QX QY QZ QW SX SY SZ [slerp|nlerp]");
        if (p->cur < 0)
            return fail(p, "keyframes outside a node");
        sc_node *N = &s->nodes[p->cur];
        if (N->n > 0 || N->motion)
            return fail(p, "node '%s': keyframes must be its only operation", N->name);
        if (parse_nums(p, tok + 1, 20, v) != 0)
            return -1;
        for (int k = 0; k < 2; k++)
            if (v[10 * k + 3] == 0.0 && v[10 * k + 4] == 0.0 && v[10 * k + 5] == 0.0 && v[10 * k + 6] == 0.0)
                return fail(p, "keyframe %d of node '%s': the quaternion is zero", k, N->name);
        if (s->nk > SC_COUNT_MAX)
            return fail(p, "more than %d keyframes nodes", SC_COUNT_MAX / 2);
        if (grow((void **)&s->keys, &s->capk, s->nk + 2, sizeof *s->keys) != 0)
            return fail(p, "out of memory");
        for (int k = 0; k < 2; k++) {
            cbx_trs *K = &s->keys[s->nk + k];
            for (int i = 0; i < 3; i++) {
                K->t[i] = v[10 * k + i];
                K->s[i] = v[10 * k + 7 + i];
            }
            for (int i = 0; i < 4; i++)
                K->q[i] = v[10 * k + 3 + i];
        }
        N->trs = s->nk + 1;
        N->nlerp = nl;
        N->motion = 1;
        s->nk += 2;
        return 0;
    }
    if (strcmp(w, "box") == 0 || strcmp(w, "sphere") == 0 || strcmp(w, "ellipsoid") == 0) {
        int kind = w[0] == 'b' ? SC_BOX : w[0] == 's' ? SC_SPHERE : SC_ELLIPSOID;
        int nv = nt - 3;
        if (kind == SC_BOX && nv != 6)
            return fail(p, "usage: box NAME NODE LX LY LZ HX HY HZ");
        if (kind == SC_SPHERE && nv != 4)
            return fail(p, "usage: sphere NAME NODE CX CY CZ R");
        if (kind == SC_ELLIPSOID && nv != 6 && nv != 15)
            return fail(p, "usage: ellipsoid NAME NODE CX CY CZ RX RY RZ [R00 R01 R02 R10 R11 R12 R20 R21 R22]");
        if (close_node(p) != 0 || check_name(p, tok[1]) != 0)
            return -1;
        int v = lookup(s, tok[2]);
        if (v <= 0)
            return fail(p, "node '%s' is not declared", tok[2]);
        sc_leaf L;
        memset(&L, 0, sizeof L);
        strcpy(L.name, tok[1]);
        L.node = v - 1;
        L.kind = kind;
        L.line = p->line;
        if (parse_nums(p, tok + 3, nv, L.v) != 0)
            return -1;
        if (kind == SC_BOX)
            for (int j = 0; j < 3; j++)
                if (L.v[j] > L.v[3 + j])
                    return fail(p, "box '%s': lo > hi on axis %d", L.name, j);
        if (kind == SC_SPHERE && L.v[3] < 0)
            return fail(p, "sphere '%s': negative radius", L.name);
        if (kind == SC_ELLIPSOID) {
            for (int j = 3; j < 6; j++)
                if (L.v[j] < 0)
                    return fail(p, "ellipsoid '%s': negative radius", L.name);
            if (nv == 6)
                L.v[6] = L.v[10] = L.v[14] = 1.0;
        }
        if (s->nl >= SC_COUNT_MAX)
            return fail(p, "more than %d leaves", SC_COUNT_MAX);
        if (grow((void **)&s->leaves, &s->capl, s->nl + 1, sizeof *s->leaves) != 0)
            return fail(p, "out of memory");
        s->leaves[s->nl++] = L;
        return add_name(p, -s->nl);
    }
    return fail(p, "unknown statement '%s'", w);
}

int scene_parse(scene *s, const char *text, const char *file, char *err, size_t errlen)
{
    parser p;
    char buf[SC_LINE_MAX + 2];
    int header = 0;
    memset(s, 0, sizeof *s);
    p.s = s; p.file = file; p.line = 0; p.err = err; p.errlen = errlen;
    p.cur = -1; p.side = 0; p.n0 = p.n1 = 0;
    const char *q = text;
    while (*q) {
        const char *e = strchr(q, '\n');
        size_t len = e ? (size_t)(e - q) : strlen(q);
        p.line++;
        if (len > SC_LINE_MAX) {
            fail(&p, "line longer than %d characters", SC_LINE_MAX);
            goto bad;
        }
        memcpy(buf, q, len);
        buf[len] = '\0';
        q = e ? e + 1 : q + len;
        char *hash = strchr(buf, '#');
        if (hash) *hash = '\0';
        char *tok[32];
        int nt = 0;
        char *c = buf;
        for (;;) {
            while (*c == ' ' || *c == '\t' || *c == '\r') c++;
            if (!*c) break;
            if (nt == 32) { fail(&p, "too many fields"); goto bad; }
            tok[nt++] = c;
            while (*c && *c != ' ' && *c != '\t' && *c != '\r') c++;
            if (*c) *c++ = '\0';
        }
        if (nt == 0)
            continue;
        if (!header) {
            if (nt != 2 || strcmp(tok[0], "certbox-scene") != 0 || strcmp(tok[1], "1") != 0) {
                fail(&p, "the first statement must be `certbox-scene 1`");
                goto bad;
            }
            header = 1;
            continue;
        }
        if (statement(&p, tok, nt) != 0)
            goto bad;
    }
    if (!header) {
        fail(&p, "empty file: the first statement must be `certbox-scene 1`");
        goto bad;
    }
    if (close_node(&p) != 0)
        goto bad;
    if (s->nl == 0) {
        fail(&p, "the scene has no leaf (box, sphere or ellipsoid)");
        goto bad;
    }
    return 0;
bad:
    scene_free(s);
    return -1;
}

int scene_parse_buf(scene *s, const char *text, size_t n, const char *file, char *err, size_t errlen)
{
    const char *nul = memchr(text, '\0', n);
    if (nul) {
        /* name the line (and column) of the first NUL, counted as the parser counts */
        long line = 1, col = 1;
        for (const char *c = text; c < nul; c++) {
            if (*c == '\n') { line++; col = 1; }
            else col++;
        }
        memset(s, 0, sizeof *s);
        snprintf(err, errlen, "%s:%ld: the file contains a NUL byte (column %ld)", file, line, col);
        return -1;
    }
    return scene_parse(s, text, file, err, errlen);
}

int scene_load(scene *s, const char *path, char *err, size_t errlen)
{
    unsigned char *b;
    size_t n;
    memset(s, 0, sizeof *s);
    int r = tool_read_all(path, &b, &n);
    if (r == -1) {
        snprintf(err, errlen, "%s:0: cannot open: %s", path, strerror(errno));
        return -1;
    }
    if (r != 0) {
        snprintf(err, errlen, "%s:0: cannot read the file (or it is above 1 GB)", path);
        return -1;
    }
    char *text = (char *)b;
    text[n] = '\0';
    int rc = scene_parse_buf(s, text, n, path, err, errlen);
    free(text);
    return rc;
}

/* ---- evaluation ---------------------------------------------------------- */
static void worse(cbx_status *acc, cbx_status st)
{
    if (scene_severity(st) > scene_severity(*acc))
        *acc = st;
}

/* The leaf's own bound in its node's coordinates (exact for a box). */
static cbx_status leaf_box(const sc_leaf *L, cbx_box *b)
{
    if (L->kind == SC_BOX) {
        for (int j = 0; j < 3; j++) {
            b->lo[j] = L->v[j];
            b->hi[j] = L->v[3 + j];
        }
        return CBX_OK;
    }
    double c[3], r[3], R[3][3];
    for (int j = 0; j < 3; j++) c[j] = L->v[j];
    if (L->kind == SC_SPHERE) {
        r[0] = r[1] = r[2] = L->v[3];
        memset(R, 0, sizeof R);
        R[0][0] = R[1][1] = R[2][2] = 1.0;
    } else {
        for (int j = 0; j < 3; j++) r[j] = L->v[3 + j];
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                R[i][j] = L->v[6 + 3 * i + j];
    }
    return cbx_ellipsoid_box(c, r, (const double (*)[3])R, b);
}

/* ---- deep leaves: interval maps, composed once per node -----------------
 * Walking every leaf up to the root costs leaves x depth (a 100,000-node
 * chain with 10,000 leaves took 31 s).  So a leaf walks at most SC_WALK
 * kernel steps (an operation, or a motion node; a node without operations
 * counts one) with the proven kernels as above, which is the whole way up
 * for every leaf within SC_WALK steps of the root: those boxes are
 * bit-identical to the level-by-level ones.  A deeper leaf stops at a node
 * and goes on by segments: S_n, an interval affine map that contains the
 * exact product of the given matrices from n up to its nearest motion
 * ancestor (excluded) or the root, computed once per node (parents come
 * first in the node array) as S_parent x O1 x ... x Ok in interval
 * arithmetic rounded outward; then the motion node by cbx_motion_box as
 * above, then the segment above it.  Past SC_WALK motion nodes a leaf
 * applies F_m, the whole world map of motion node m, where m's operation is
 * the entry-wise hull of M0 and M1: it holds (1 - s) M0 + s M1 for every s
 * in [0, 1], but it forgets that the entries move together, so it is used
 * only there.  Inclusion monotonicity of interval arithmetic puts the exact
 * image of the box inside each result.  The composition is not a proven
 * kernel: its rounding is argued here and checked by tests/test_scene.c
 * against exact rationals. */
#ifndef SC_WALK
#define SC_WALK 64
#endif

typedef struct sc_imap { double lo[3][4], hi[3][4]; } sc_imap;

/* Every composed entry, product and box end is kept at most 2^1000 in
 * magnitude, so no product of two in-range values overflows a sum, and
 * TwoSum is exact; beyond, the axis becomes [-inf, +inf] (CBX_ERANGE). */
static const double SC_BIG = 0x1p1000;

static int in_range(double x) { return fabs(x) <= SC_BIG; }   /* false for NaN */

/* x * y rounded down (up = 0) or up (up = 1): the rounded-to-nearest
 * product, moved one step when its exact error (fma, exact when the
 * product is at least 2^-960 in magnitude) points that way; a smaller
 * nonzero product is moved one step outward regardless. */
static double mul_dir(double x, double y, int up)
{
    if (x == 0.0 || y == 0.0)
        return 0.0;
    double p = x * y, to = up ? HUGE_VAL : -HUGE_VAL;
    if (!(fabs(p) >= 0x1p-960))
        return nextafter(p, to);
    double e = fma(x, y, -p);
    return (up ? e > 0.0 : e < 0.0) ? nextafter(p, to) : p;
}

/* x + y rounded down or up: TwoSum's exact error (|x|, |y| <= 2^1001). */
static double add_dir(double x, double y, int up)
{
    double s = x + y, b = s - x, e = (x - (s - b)) + (y - b);
    return (up ? e > 0.0 : e < 0.0) ? nextafter(s, up ? HUGE_VAL : -HUGE_VAL) : s;
}

/* [rl, rh] += [al, ah] * [bl, bh]; 0 when either factor is exactly [0, 0]
 * (so an infinite box end times a zero entry stays out of the sum).
 * Returns 0, or -1 when some value leaves the range. */
static int imul_add(double al, double ah, double bl, double bh, double *rl, double *rh)
{
    if ((al == 0.0 && ah == 0.0) || (bl == 0.0 && bh == 0.0))
        return 0;
    if (!(in_range(al) && in_range(ah) && in_range(bl) && in_range(bh)))
        return -1;
    double lo, hi;
    if (bl == bh) {                       /* a point factor: two products */
        lo = mul_dir(bl >= 0.0 ? al : ah, bl, 0);
        hi = mul_dir(bl >= 0.0 ? ah : al, bl, 1);
    } else {
        lo = fmin(fmin(mul_dir(al, bl, 0), mul_dir(al, bh, 0)), fmin(mul_dir(ah, bl, 0), mul_dir(ah, bh, 0)));
        hi = fmax(fmax(mul_dir(al, bl, 1), mul_dir(al, bh, 1)), fmax(mul_dir(ah, bl, 1), mul_dir(ah, bh, 1)));
    }
    if (!(in_range(lo) && in_range(hi)))
        return -1;
    *rl = add_dir(*rl, lo, 0);
    *rh = add_dir(*rh, hi, 1);
    return in_range(*rl) && in_range(*rh) ? 0 : -1;
}

/* r = w x o as affine maps (o applied first); r may not alias w or o.
 * Returns -1 when some entry leaves the range. */
static int imap_compose(const sc_imap *w, const sc_imap *o, sc_imap *r)
{
    int bad = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) {
            double lo = j == 3 ? w->lo[i][3] : 0.0, hi = j == 3 ? w->hi[i][3] : 0.0;
            for (int k = 0; k < 3; k++)
                bad |= imul_add(w->lo[i][k], w->hi[i][k], o->lo[k][j], o->hi[k][j], &lo, &hi);
            r->lo[i][j] = lo;
            r->hi[i][j] = hi;
        }
    return bad ? -1 : 0;
}

/* The hull of two given maps (one map: a0 == a1). */
static void imap_hull(const cbx_affine *a0, const cbx_affine *a1, sc_imap *r)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) {
            r->lo[i][j] = fmin(a0->m[i][j], a1->m[i][j]);
            r->hi[i][j] = fmax(a0->m[i][j], a1->m[i][j]);
        }
}

/* A keyframes node's operation over the whole shutter: the hull of
 * cbx_trs_pieces' interval matrices (each holds every map of its cell).
 * Returns 1 when the pieces are not all in range (then r is unused). */
static int trs_hull(const scene *s, const sc_node *N, sc_imap *r)
{
    cbx_imat pc[(2U << SC_TRS_DEPTH) + 1U];
    size_t np = 0;
    cbx_status st = cbx_trs_pieces(&s->keys[N->trs - 1], &s->keys[N->trs], N->nlerp ? CBX_NLERP : CBX_SLERP,
                                   0.0, 1.0, SC_TRS_DEPTH, pc, sizeof pc / sizeof pc[0], &np);
    if (st != CBX_OK || np == 0)
        return 1;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) {
            r->lo[i][j] = pc[0].lo[i][j];
            r->hi[i][j] = pc[0].hi[i][j];
            for (size_t k = 1; k < np; k++) {
                r->lo[i][j] = fmin(r->lo[i][j], pc[k].lo[i][j]);
                r->hi[i][j] = fmax(r->hi[i][j], pc[k].hi[i][j]);
            }
        }
    return 0;
}

/* The segment and world maps (see above), parents first. */
typedef struct sc_maps {
    sc_imap *S, *F;         /* S[n] for every node; F[fidx[n]] for motion nodes */
    unsigned char *sbad, *fbad;   /* 1: the map left the range (CBX_ERANGE) */
    int *mot, *fidx;        /* mot[n]: the nearest motion node among n and its ancestors, or -1 */
} sc_maps;

static void identity_map(sc_imap *r)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            r->lo[i][j] = r->hi[i][j] = i == j;
}

static void maps_free(sc_maps *m)
{
    free(m->S); free(m->F); free(m->sbad); free(m->fbad); free(m->mot); free(m->fidx);
    memset(m, 0, sizeof *m);
}

/* Compute every map; -1 when out of memory (nothing kept). */
static int maps_build(const scene *s, sc_maps *m)
{
    size_t nn = (size_t)s->nn, nm = 0;
    for (int n = 0; n < s->nn; n++) nm += s->nodes[n].motion != 0;
    memset(m, 0, sizeof *m);
    m->S = malloc(nn * sizeof *m->S);
    m->sbad = malloc(nn);
    m->mot = malloc(nn * sizeof *m->mot);
    m->fidx = malloc(nn * sizeof *m->fidx);
    m->F = malloc((nm ? nm : 1) * sizeof *m->F);
    m->fbad = malloc(nm ? nm : 1);
    if (!m->S || !m->sbad || !m->mot || !m->fidx || !m->F || !m->fbad) {
        maps_free(m);
        return -1;
    }
    int nf = 0;
    for (int n = 0; n < s->nn; n++) {
        const sc_node *N = &s->nodes[n];
        int p = N->parent, bad = 0;
        sc_imap cur, o, r;
        m->mot[n] = N->motion ? n : p >= 0 ? m->mot[p] : -1;
        m->fidx[n] = -1;
        if (!N->motion) {
            /* S_n = S_parent (if the parent is no motion node) x O1 x ... x Ok */
            if (p >= 0 && !s->nodes[p].motion) { cur = m->S[p]; bad = m->sbad[p]; }
            else identity_map(&cur);
            for (int q = N->first; q < N->first + N->n && !bad; q++) {
                imap_hull(&s->ops[q].a, &s->ops[q].a, &o);
                bad = imap_compose(&cur, &o, &r) != 0;
                cur = r;
            }
            m->S[n] = cur;
            m->sbad[n] = (unsigned char)bad;
        } else {
            /* F_n = the parent's world map x hull(M0, M1); the parent's world
             * map is F of its motion node x its segment map */
            if (p < 0) identity_map(&cur);
            else if (s->nodes[p].motion) { cur = m->F[m->fidx[p]]; bad = m->fbad[m->fidx[p]]; }
            else if (m->mot[p] < 0) { cur = m->S[p]; bad = m->sbad[p]; }
            else {
                int f = m->fidx[m->mot[p]];
                bad = m->fbad[f] || m->sbad[p] || imap_compose(&m->F[f], &m->S[p], &cur) != 0;
            }
            if (N->trs)
                bad |= trs_hull(s, N, &o);
            else
                imap_hull(&s->ops[N->first].a, &s->ops[N->first + 1].a, &o);
            if (bad)
                identity_map(&r);       /* marked bad below: never read as a map */
            else
                bad = imap_compose(&cur, &o, &r) != 0;
            m->fidx[n] = nf;
            m->F[nf] = r;
            m->fbad[nf++] = (unsigned char)bad;
            identity_map(&m->S[n]);     /* not used */
            m->sbad[n] = 0;
        }
    }
    return 0;
}

/* out = the hull of W applied to the box in (out may be in).  An axis that
 * leaves the range, or a map that did, is [-inf, +inf] with CBX_ERANGE. */
static cbx_status imap_box(const sc_imap *w, int wbad, const cbx_box *in, cbx_box *out)
{
    cbx_box b = *in;
    cbx_status st = CBX_OK;
    for (int j = 0; j < 3; j++)
        if (isnan(b.lo[j]) || isnan(b.hi[j]))
            wbad = 1, st = CBX_EINVAL;
    for (int i = 0; i < 3; i++) {
        double lo = w->lo[i][3], hi = w->hi[i][3];
        int bad = wbad;
        for (int k = 0; k < 3 && !bad; k++)
            bad = imul_add(w->lo[i][k], w->hi[i][k], b.lo[k], b.hi[k], &lo, &hi) != 0;
        if (bad) {
            lo = -HUGE_VAL;
            hi = HUGE_VAL;
            if (st == CBX_OK) st = CBX_ERANGE;
        }
        out->lo[i] = lo;
        out->hi[i] = hi;
    }
    return st;
}

/* ---- evaluation ------------------------------------------------------------ */
/* The kernel steps of a node in a leaf's walk (at least one per node). */
static int walk_cost(const sc_node *N)
{
    return N->motion ? 1 : N->n > 0 ? N->n : 1;
}

/* The box through one node's own operations, last first (level by level). */
static cbx_status node_box(const scene *s, const sc_node *N, cbx_box *b)
{
    cbx_status st = CBX_OK;
    if (N->trs) {
        cbx_box o;
        worse(&st, cbx_motion_trs_box(&s->keys[N->trs - 1], &s->keys[N->trs], N->nlerp ? CBX_NLERP : CBX_SLERP,
                                      0.0, 1.0, SC_TRS_DEPTH, b, &o));
        *b = o;
    } else if (N->motion) {
        cbx_box o;
        worse(&st, cbx_motion_box(&s->ops[N->first].a, &s->ops[N->first + 1].a, b, &o));
        *b = o;
    } else if (N->n > 0) {
        /* the node's operations, last first: proven as a whole (the box
         * holds the image of every point of *b under their exact product) */
        worse(&st, cbx_transform_box_chain(&s->ops[N->first], (size_t)N->n, b, b));
    }
    return st;
}

/* A run of static nodes met on a leaf's way up (path[0] the leaf's side,
 * path[np - 1] the root's), at most SC_WALK operations in all: their
 * operations in one array, the root's side first (applied last), so that
 * one call of cbx_transform_box_chain maps the box through the whole run
 * (the same steps, in the same order, as node_box node by node). */
typedef struct sc_run { int path[SC_WALK]; int np, nops; sc_op buf[SC_WALK]; } sc_run;

static cbx_status run_flush(const scene *s, sc_run *r, cbx_box *b)
{
    size_t m = 0;
    for (int q = r->np - 1; q >= 0; q--) {
        const sc_node *N = &s->nodes[r->path[q]];
        for (int o = 0; o < N->n; o++)
            r->buf[m++] = s->ops[N->first + o];
    }
    r->np = r->nops = 0;
    return m > 0 ? cbx_transform_box_chain(r->buf, m, b, b) : CBX_OK;
}

void scene_eval(scene *s)
{
    s->st = CBX_OK;
    for (int j = 0; j < 3; j++) {
        s->world.lo[j] = HUGE_VAL;
        s->world.hi[j] = -HUGE_VAL;
    }
    /* the maps only when some leaf is more than SC_WALK steps deep */
    sc_maps m;
    int have_maps = 0;
    int *depth = malloc((size_t)(s->nn > 0 ? s->nn : 1) * sizeof *depth);
    int deep = depth == NULL;
    for (int n = 0; n < s->nn && depth; n++) {
        const sc_node *N = &s->nodes[n];
        depth[n] = walk_cost(N) + (N->parent >= 0 ? depth[N->parent] : 0);
    }
    for (int k = 0; k < s->nl && !deep; k++)
        deep = depth[s->leaves[k].node] > SC_WALK;
    free(depth);
    /* out of memory: every leaf walks to the root (slow, the same promise) */
    if (deep)
        have_maps = maps_build(s, &m) == 0;
    for (int k = 0; k < s->nl; k++) {
        sc_leaf *L = &s->leaves[k];
        cbx_box b;
        cbx_status st = leaf_box(L, &b);
        int n = L->node, budget = SC_WALK;
        sc_run run;
        run.np = run.nops = 0;
        /* static nodes gathered into runs, each one proven chain; a motion
         * node (or a run that would pass SC_WALK operations, which only a
         * walk without the maps meets) goes on its own */
        while (n >= 0 && (!have_maps || walk_cost(&s->nodes[n]) <= budget)) {
            const sc_node *N = &s->nodes[n];
            budget -= walk_cost(N);
            if (!N->motion && run.np < SC_WALK && run.nops + N->n <= SC_WALK) {
                run.path[run.np++] = n;
                run.nops += N->n;
            } else {
                worse(&st, run_flush(s, &run, &b));
                worse(&st, node_box(s, N, &b));
            }
            n = N->parent;
        }
        worse(&st, run_flush(s, &run, &b));
        /* then by segments, motion nodes by cbx_motion_box (at most SC_WALK) */
        for (int motions = 0; n >= 0; ) {
            const sc_node *N = &s->nodes[n];
            if (!N->motion) {
                worse(&st, imap_box(&m.S[n], m.sbad[n], &b, &b));
                n = m.mot[n];
            } else if (motions++ < SC_WALK) {
                worse(&st, node_box(s, N, &b));
                n = N->parent;
            } else {
                worse(&st, imap_box(&m.F[m.fidx[n]], m.fbad[m.fidx[n]], &b, &b));
                break;
            }
        }
        L->world = b;
        L->st = st;
        worse(&s->st, st);
        for (int j = 0; j < 3; j++) {
            if (b.lo[j] < s->world.lo[j]) s->world.lo[j] = b.lo[j];
            if (b.hi[j] > s->world.hi[j]) s->world.hi[j] = b.hi[j];
        }
    }
    if (have_maps)
        maps_free(&m);
}
