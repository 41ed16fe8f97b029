/*
 * glTF 2.0 input (see gltf.h and docs/gltf.md).
 *
 * Soundness: no number is ever rounded without being paid for.  Every
 * node's local map is an interval matrix (cbx_imat): a `matrix` node's
 * entries are degenerate intervals; a TRS node's T * R(q)/|q|^2 * S is
 * computed here in outward interval arithmetic (each rounded operation
 * enclosed: RN, then one ulp outward unless FMA / TwoSum show the
 * operation exact).  A node's world map is its parent's world map times
 * its local map, once per node, by the library's cbx_imat_compose; the box
 * of a primitive (its accessor's min/max, or its vertices with
 * --from-vertices) is then mapped by the library's cbx_transform_box_imat.
 * Both are proven (Frama-C/WP, certbox.h): the composition encloses every
 * product of maps of the two interval matrices, the box contains the image
 * of the box under every map of the world interval matrix, so under the
 * exact product of the node chain.  An entry or an axis whose inputs leave
 * their fast range (an infinite end, a linear entry or box end above
 * 2^509, a translation above 2^1018 in magnitude) is the whole line
 * [-inf, +inf], CBX_ERANGE.
 */
#define _XOPEN_SOURCE 700          /* realpath */
/* 64-bit file offsets and inode numbers on 32-bit hosts too: without
 * it, readdir / stat fail with EOVERFLOW on file systems with large inode
 * numbers (armhf under qemu-user, scripts/cross.sh) */
#define _FILE_OFFSET_BITS 64
#include "gltf.h"
#include "readall.h"

#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* GLB magic, or JSON's `{` after blanks: no parser needed */
int gltf_sniff(const char *path)
{
    FILE *f = fopen(path, "rb");
    unsigned char b[64];
    if (!f)
        return 0;
    size_t n = fread(b, 1, sizeof b, f);
    fclose(f);
    if (n >= 4 && memcmp(b, "glTF", 4) == 0)
        return 1;
    for (size_t k = 0; k < n; k++) {
        if (b[k] == ' ' || b[k] == '\t' || b[k] == '\r' || b[k] == '\n') continue;
        return b[k] == '{';
    }
    return 0;
}

/* The tool's box output (both formats; also without jansson). */
static void num(char *buf, size_t n, double x, int hex)
{
    snprintf(buf, n, hex ? "%a" : "%.17g", x);
}

void tool_print_box(const cbx_box *b, int hex, int json)
{
    char t[6][40];
    for (int j = 0; j < 3; j++) {
        num(t[j], sizeof t[j], b->lo[j], hex);
        num(t[3 + j], sizeof t[3 + j], b->hi[j], hex);
    }
    if (json)
        printf("\"lo\": [\"%s\", \"%s\", \"%s\"], \"hi\": [\"%s\", \"%s\", \"%s\"]",
               t[0], t[1], t[2], t[3], t[4], t[5]);
    else
        printf("lo %s %s %s hi %s %s %s", t[0], t[1], t[2], t[3], t[4], t[5]);
}

#ifndef CBX_GLTF
/* Built without jansson (the Makefile found none): glTF files are named as
 * such and refused, other files go on to the tool's own format. */
int gltf_main(int argc, char **argv)
{
    for (int k = 1; k < argc; k++)
        if (argv[k][0] != '-' && gltf_sniff(argv[k])) {
            fprintf(stderr, "%s: a glTF file, but this certbox was built without glTF input (jansson, "
                            "libjansson-dev, was not found): install it (sh scripts/deps.sh test) and rebuild\n",
                    argv[k]);
            return 2;
        }
    return -1;
}
#else
#include <jansson.h>

/* ---- outward interval arithmetic ------------------------------------- */
typedef struct iv { double lo, hi; } iv;

static double dn(double x) { return nextafter(x, -HUGE_VAL); }
static double up(double x) { return nextafter(x, HUGE_VAL); }

/* Below this magnitude an FMA residual may itself underflow: widen. */
#define GL_TINY 0x1p-969

/* Keep the invariant lo < +inf and hi > -inf, so that lo + lo and
 * hi + hi never meet inf - inf (an end at +inf means "above DBL_MAX"). */
static iv clampiv(iv a)
{
    if (a.lo == HUGE_VAL) a.lo = DBL_MAX;
    if (a.hi == -HUGE_VAL) a.hi = -DBL_MAX;
    return a;
}

/* [lo, hi] contains the exact x * y (0 * inf = 0: ends are bounds on
 * reals, never values); an infinite operand gives an infinite end. */
static iv mul_enc(double x, double y)
{
    iv r;
    if (x == 0.0 || y == 0.0) { r.lo = r.hi = 0.0; return r; }
    double p = x * y;
    if (isinf(p) && !isinf(x) && !isinf(y)) {     /* overflow */
        r.lo = p > 0 ? DBL_MAX : -HUGE_VAL;
        r.hi = p > 0 ? HUGE_VAL : -DBL_MAX;
    } else if (isinf(p) || fabs(p) < GL_TINY) {
        r.lo = isinf(p) ? p : dn(p);
        r.hi = isinf(p) ? p : up(p);
    } else {
        double e = fma(x, y, -p);                 /* exact: x*y - p */
        r.lo = !(e >= 0) ? dn(p) : p;             /* NaN e: widen both */
        r.hi = !(e <= 0) ? up(p) : p;
    }
    return r;
}

/* [lo, hi] contains the exact x + y (never inf - inf, see clampiv) */
static iv add_enc(double x, double y)
{
    iv r;
    double s = x + y;
    if (isinf(s)) {
        if (isinf(x) || isinf(y)) { r.lo = r.hi = s; }
        else { r.lo = s > 0 ? DBL_MAX : -HUGE_VAL; r.hi = s > 0 ? HUGE_VAL : -DBL_MAX; }
        return r;
    }
    double bb = s - x;                            /* TwoSum: exact error */
    double e = (x - (s - bb)) + (y - bb);
    r.lo = !(e >= 0) ? dn(s) : s;                 /* NaN e (a spurious */
    r.hi = !(e <= 0) ? up(s) : s;                 /* overflow): widen  */
    return r;
}

/* [lo, hi] contains the exact x / y for y > 0 finite */
static iv div_enc(double x, double y)
{
    iv r;
    double q = x / y;
    if (isinf(x)) { r.lo = r.hi = q; return r; }
    if (isinf(q)) { r.lo = q > 0 ? DBL_MAX : -HUGE_VAL; r.hi = q > 0 ? HUGE_VAL : -DBL_MAX; return r; }
    if (q == 0.0 || fabs(q) < GL_TINY || fabs(x) < GL_TINY) {
        r.lo = x == 0.0 ? 0.0 : dn(q);
        r.hi = x == 0.0 ? 0.0 : up(q);
        return r;
    }
    double e = fma(q, y, -x);                     /* q*y - x, exact */
    r.lo = !(e <= 0) ? dn(q) : q;                 /* q > x/y when e > 0 */
    r.hi = !(e >= 0) ? up(q) : q;
    return r;
}

static iv pt(double x) { iv r; r.lo = r.hi = x; return r; }

static iv iv_add(iv a, iv b)
{
    iv r;
    r.lo = add_enc(a.lo, b.lo).lo;
    r.hi = add_enc(a.hi, b.hi).hi;
    return clampiv(r);
}

static iv iv_neg(iv a) { iv r; r.lo = -a.hi; r.hi = -a.lo; return r; }

/* the hull of four enclosures (the end products of two intervals) */
static iv hull4(const iv p[4])
{
    iv r = p[0];
    for (int k = 1; k < 4; k++) {
        if (p[k].lo < r.lo) r.lo = p[k].lo;
        if (p[k].hi > r.hi) r.hi = p[k].hi;
    }
    return clampiv(r);
}

static iv iv_mul(iv a, iv b)
{
    iv p[4] = { mul_enc(a.lo, b.lo), mul_enc(a.lo, b.hi), mul_enc(a.hi, b.lo), mul_enc(a.hi, b.hi) };
    return hull4(p);
}

/* a / n for an interval n with 0 < n.lo <= n.hi < inf */
static iv iv_div(iv a, iv n)
{
    iv p[4] = { div_enc(a.lo, n.lo), div_enc(a.lo, n.hi), div_enc(a.hi, n.lo), div_enc(a.hi, n.hi) };
    return hull4(p);
}

/* x^2 for an interval x (>= 0) */
static iv iv_sqi(iv x)
{
    iv r = iv_mul(x, x);
    if (r.lo < 0) r.lo = 0.0;                     /* a square is >= 0 */
    return r;
}

/* The rotation of q = (x, y, z, w) times |q|^2 (the unit formula, homogeneous
 * form), and |q|^2, for q in the box Q, in intervals. */
static void unit_formula(const iv Q[4], iv R[3][3], iv *n)
{
    iv x = Q[0], y = Q[1], z = Q[2], w = Q[3];
    iv xx = iv_sqi(x), yy = iv_sqi(y), zz = iv_sqi(z), ww = iv_sqi(w);
    *n = iv_add(iv_add(xx, yy), iv_add(zz, ww));
    iv xy = iv_mul(x, y), xz = iv_mul(x, z), yz = iv_mul(y, z);
    iv wx = iv_mul(w, x), wy = iv_mul(w, y), wz = iv_mul(w, z), two = pt(2.0);
    R[0][0] = iv_add(iv_add(ww, xx), iv_neg(iv_add(yy, zz)));
    R[1][1] = iv_add(iv_add(ww, yy), iv_neg(iv_add(xx, zz)));
    R[2][2] = iv_add(iv_add(ww, zz), iv_neg(iv_add(xx, yy)));
    R[0][1] = iv_mul(two, iv_add(xy, iv_neg(wz)));
    R[1][0] = iv_mul(two, iv_add(xy, wz));
    R[0][2] = iv_mul(two, iv_add(xz, wy));
    R[2][0] = iv_mul(two, iv_add(xz, iv_neg(wy)));
    R[1][2] = iv_mul(two, iv_add(yz, iv_neg(wx)));
    R[2][1] = iv_mul(two, iv_add(yz, wx));
}


static void setm(gl_imat *m, int i, int j, iv v) { m->lo[i][j] = v.lo; m->hi[i][j] = v.hi; }

/* The interval enclosure of T * R(q)/|q|^2 * S.  q is scaled by a power
 * of two first (exactly: the rotation does not change) so that its
 * squares neither overflow nor all underflow.  -1 if q is zero or its
 * components span too wide a range to scale exactly. */
static int trs_local(const double t[3], const double q0[4], const double s[3], gl_imat *L)
{
    double q[4], mx = 0.0;
    for (int k = 0; k < 4; k++)
        if (fabs(q0[k]) > mx) mx = fabs(q0[k]);
    if (mx == 0.0)
        return -1;
    int e = 0;
    if (mx < 0x1p-500 || mx > 0x1p500)
        frexp(mx, &e);
    for (int k = 0; k < 4; k++) {
        q[k] = ldexp(q0[k], -e);
        if (ldexp(q[k], e) != q0[k])
            return -1;                             /* not exact */
    }
    iv Q[4] = { pt(q[0]), pt(q[1]), pt(q[2]), pt(q[3]) }, R[3][3], n;
    unit_formula(Q, R, &n);
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++)
            setm(L, i, j, iv_mul(iv_div(R[i][j], n), pt(s[j])));
        setm(L, i, 3, pt(t[i]));
    }
    return 0;
}

/* ---- loading context and errors --------------------------------------- */
typedef struct ctx {
    gl_doc *d;
    const char *path;
    char *err;
    size_t errlen;
    char dir[PATH_MAX];
    FILE *notes;
    int fromv, anim;
    const unsigned char *bin; size_t nbin; int has_bin;
    json_t *root;
    size_t nbv, nbuffers, ntex;
} ctx;

/* Messages quote the file's own strings (a uri, an extension's name, a
 * key, jansson's "near '...'"): their control bytes (a JSON "\n" or
 * "\u001b" decodes to one) are written as \xNN, so that an error stays one
 * line and cannot drive the terminal.  dst gets at most n - 1 bytes. */
static void esc_ctl(char *dst, size_t n, const char *src)
{
    size_t m = 0;
    for (const unsigned char *s = (const unsigned char *)src; *s && m + 1 < n; s++) {
        if (*s >= 0x20 && *s != 0x7f) {
            dst[m++] = (char)*s;
        } else {
            if (m + 5 > n) break;
            snprintf(dst + m, 5, "\\x%02x", *s);
            m += 4;
        }
    }
    dst[m] = '\0';
}

/* "FILE: msg" (msg names the JSON pointer or the byte) */
static int fail(ctx *c, const char *fmt, ...)
{
    char msg[400], e[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    esc_ctl(e, sizeof e, msg);
    snprintf(c->err, c->errlen, "%s: %s", c->path, e);
    return -1;
}

static void note(ctx *c, const char *fmt, ...)
{
    char msg[400], e[400];
    c->d->notes++;
    if (!c->notes)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    esc_ctl(e, sizeof e, msg);
    fprintf(c->notes, "%s: note: %s\n", c->path, e);
}

/* ---- JSON helpers (errors name the JSON pointer) ---------------------- */
/* Array `key` of root (NULL and size 0 if absent); -1 if not an array. */
static int top_array(ctx *c, const char *key, json_t **arr, size_t *n)
{
    json_t *a = json_object_get(c->root, key);
    *arr = a;
    *n = 0;
    if (!a)
        return 0;
    if (!json_is_array(a))
        return fail(c, "/%s: must be an array", key);
    *n = json_array_size(a);
    return 0;
}

/* Non-negative integer member `key` of obj: 1 if absent (*out = dflt),
 * 0 if present and below limit (limit < 0: no limit), -1 otherwise. */
static int get_uint(ctx *c, json_t *obj, const char *key, const char *ptr, long long limit,
                    const char *what, long long dflt, long long *out)
{
    json_t *v = json_object_get(obj, key);
    *out = dflt;
    if (!v)
        return 1;
    if (!json_is_integer(v) || json_integer_value(v) < 0)
        return fail(c, "%s/%s: must be a non-negative integer", ptr, key);
    long long x = json_integer_value(v);
    if (limit >= 0 && x >= limit)
        return fail(c, "%s/%s: %s index %lld out of range (the file has %lld)", ptr, key, what, x, limit);
    if (x > ((long long)1 << 53))
        return fail(c, "%s/%s: %lld is too large", ptr, key, x);
    *out = x;
    return 0;
}

static int need_uint(ctx *c, json_t *obj, const char *key, const char *ptr, long long limit,
                     const char *what, long long *out)
{
    int r = get_uint(c, obj, key, ptr, limit, what, 0, out);
    if (r == 1)
        return fail(c, "%s: missing member '%s'", ptr, key);
    return r;
}

/* Array member of n numbers (n = 0: any length); 1 if absent. */
static int get_nums(ctx *c, json_t *obj, const char *key, const char *ptr, size_t n, double *out)
{
    json_t *a = json_object_get(obj, key);
    if (!a)
        return 1;
    if (!json_is_array(a) || json_array_size(a) != n)
        return fail(c, "%s/%s: must be an array of %zu numbers", ptr, key, n);
    for (size_t k = 0; k < n; k++) {
        json_t *v = json_array_get(a, k);
        if (!json_is_number(v))
            return fail(c, "%s/%s/%zu: must be a number", ptr, key, k);
        out[k] = json_number_value(v);           /* nearest double (strtod) */
    }
    return 0;
}

/* Checks every element of the top-level arrays shares: an object, its
 * `name` a string, its `extensions` an object of objects. */
static int check_common(ctx *c, json_t *o, const char *ptr)
{
    if (!json_is_object(o))
        return fail(c, "%s: must be an object", ptr);
    json_t *nm = json_object_get(o, "name");
    if (nm && !json_is_string(nm))
        return fail(c, "%s/name: must be a string", ptr);
    json_t *ex = json_object_get(o, "extensions");
    if (ex) {
        const char *k;
        json_t *v;
        if (!json_is_object(ex))
            return fail(c, "%s/extensions: must be an object", ptr);
        json_object_foreach(ex, k, v)
            if (!json_is_object(v))
                return fail(c, "%s/extensions/%s: must be an object", ptr, k);
    }
    return 0;
}

/* A material's textureInfo (index required, in range). */
static int check_texinfo(ctx *c, json_t *m, const char *key, const char *ptr, const char *num)
{
    json_t *t = json_object_get(m, key);
    char p[200];
    long long x;
    if (!t)
        return 0;
    snprintf(p, sizeof p, "%s/%s", ptr, key);
    if (check_common(c, t, p) != 0)
        return -1;
    json_t *v = num ? json_object_get(t, num) : NULL;
    if (v && !json_is_number(v))
        return fail(c, "%s/%s: must be a number", p, num);
    if (need_uint(c, t, "index", p, (long long)c->ntex, "texture", &x) < 0
        || get_uint(c, t, "texCoord", p, -1, "", 0, &x) < 0)
        return -1;
    return 0;
}

/* Materials are not used for bounds, but a broken one is a broken file. */
static int check_materials(ctx *c)
{
    json_t *arr, *tex;
    size_t n;
    if (top_array(c, "textures", &tex, &c->ntex) != 0 || top_array(c, "materials", &arr, &n) != 0)
        return -1;
    for (size_t k = 0; k < n; k++) {
        json_t *m = json_array_get(arr, k);
        char p[64];
        snprintf(p, sizeof p, "/materials/%zu", k);
        if (check_common(c, m, p) != 0)
            return -1;
        json_t *pbr = json_object_get(m, "pbrMetallicRoughness");
        if (pbr) {
            char q[100];
            snprintf(q, sizeof q, "%s/pbrMetallicRoughness", p);
            if (check_common(c, pbr, q) != 0 || check_texinfo(c, pbr, "baseColorTexture", q, NULL) != 0
                || check_texinfo(c, pbr, "metallicRoughnessTexture", q, NULL) != 0)
                return -1;
            static const char *const f[] = {"metallicFactor", "roughnessFactor"};
            for (int i = 0; i < 2; i++) {
                json_t *v = json_object_get(pbr, f[i]);
                if (v && !json_is_number(v))
                    return fail(c, "%s/%s: must be a number", q, f[i]);
            }
        }
        if (check_texinfo(c, m, "normalTexture", p, "scale") != 0
            || check_texinfo(c, m, "occlusionTexture", p, "strength") != 0
            || check_texinfo(c, m, "emissiveTexture", p, NULL) != 0)
            return -1;
    }
    return 0;
}

/* ---- buffers ---------------------------------------------------------- */
static int b64val(int ch)
{
    if (ch >= 'A' && ch <= 'Z') return ch - 'A';
    if (ch >= 'a' && ch <= 'z') return ch - 'a' + 26;
    if (ch >= '0' && ch <= '9') return ch - '0' + 52;
    if (ch == '+') return 62;
    if (ch == '/') return 63;
    return -1;
}

/* Strict base64 (RFC 4648, padded); -1 and the bad character's offset. */
static int b64_decode(const char *s, size_t n, unsigned char **out, size_t *outn, size_t *bad)
{
    *out = NULL;
    *outn = 0;
    if (n % 4 != 0) { *bad = n; return -1; }
    unsigned char *o = malloc(n / 4 * 3 + 1);
    if (!o) { *bad = 0; return -1; }
    size_t m = 0;
    for (size_t k = 0; k < n; k += 4) {
        int v[4], pad = 0;
        for (int i = 0; i < 4; i++) {
            char ch = s[k + (size_t)i];
            if (ch == '=' && k + 4 == n && i >= 2 && (i == 3 || s[k + 3] == '=')) { v[i] = 0; pad++; continue; }
            v[i] = b64val((unsigned char)ch);
            if (v[i] < 0 || pad) { free(o); *bad = k + (size_t)i; return -1; }
        }
        unsigned long w = ((unsigned long)v[0] << 18) | ((unsigned long)v[1] << 12) | ((unsigned long)v[2] << 6) | (unsigned long)v[3];
        o[m++] = (unsigned char)(w >> 16);
        if (pad < 2) o[m++] = (unsigned char)(w >> 8);
        if (pad < 1) o[m++] = (unsigned char)w;
    }
    *out = o;
    *outn = m;
    return 0;
}

static int hexval(int ch)
{
    if (ch >= '0' && ch <= '9') return ch - '0';
    if (ch >= 'a' && ch <= 'f') return ch - 'a' + 10;
    if (ch >= 'A' && ch <= 'F') return ch - 'A' + 10;
    return -1;
}

/* A relative URI, percent-decoded, that stays inside the file's folder. */
static int open_rel(ctx *c, const char *uri, const char *ptr, unsigned char **data, size_t *n)
{
    char dec[PATH_MAX], full[2 * PATH_MAX + 2], real[PATH_MAX];
    size_t m = 0;
    for (const char *s = uri; *s; s++) {
        int ch = (unsigned char)*s;
        if (ch == '%') {
            int h = hexval((unsigned char)s[1]), l = h < 0 ? -1 : hexval((unsigned char)s[2]);
            if (h < 0 || l < 0)
                return fail(c, "%s/uri: bad percent-encoding in '%s'", ptr, uri);
            ch = h * 16 + l;
            s += 2;
        }
        if (ch == 0)
            return fail(c, "%s/uri: '%s' encodes a NUL byte", ptr, uri);
        if (m + 1 >= sizeof dec)
            return fail(c, "%s/uri: too long", ptr);
        dec[m++] = (char)ch;
    }
    dec[m] = '\0';
    if (m == 0)
        return fail(c, "%s/uri: empty", ptr);
    const char *colon = strchr(dec, ':'), *slash = strchr(dec, '/');
    if (colon && (!slash || colon < slash))
        return fail(c, "%s/uri: '%s': only relative paths and data: URIs are read", ptr, uri);
    if (dec[0] == '/' || strchr(dec, '\\'))
        return fail(c, "%s/uri: '%s' is an absolute path: refused (it would leave the file's folder)", ptr, uri);
    for (const char *s = dec; *s;) {
        const char *e = strchr(s, '/');
        size_t len = e ? (size_t)(e - s) : strlen(s);
        if (len == 2 && s[0] == '.' && s[1] == '.')
            return fail(c, "%s/uri: '%s' has a '..' component: refused (it would leave the file's folder)", ptr, uri);
        s += len + (e ? 1 : 0);
    }
    snprintf(full, sizeof full, "%s/%s", c->dir, dec);
    if (!realpath(full, real))
        return fail(c, "%s/uri: cannot open '%s': %s", ptr, dec, strerror(errno));
    size_t dl = strlen(c->dir);
    if (strncmp(real, c->dir, dl) != 0 || (real[dl] != '/' && strcmp(c->dir, "/") != 0))
        return fail(c, "%s/uri: '%s' resolves outside the file's folder (a symbolic link?): refused", ptr, uri);
    if (tool_read_all(real, data, n) != 0)
        return fail(c, "%s/uri: cannot read '%s': %s", ptr, dec, strerror(errno));
    return 0;
}

/* Load buffer k (once); checks its length against byteLength. */
static int load_buffer(ctx *c, long long k)
{
    gl_doc *d = c->d;
    if (d->bufs[k])
        return 0;
    json_t *B = json_array_get(json_object_get(c->root, "buffers"), (size_t)k);
    char p[64];
    long long bl;
    snprintf(p, sizeof p, "/buffers/%lld", k);
    if (need_uint(c, B, "byteLength", p, -1, "", &bl) != 0)
        return -1;
    json_t *u = json_object_get(B, "uri");
    unsigned char *data = NULL;
    size_t n = 0;
    if (!u) {
        if (k != 0 || !c->has_bin)
            return fail(c, "%s: no uri and no GLB BIN chunk for it", p);
        data = malloc(c->nbin ? c->nbin : 1);
        if (!data)
            return fail(c, "out of memory");
        memcpy(data, c->bin, c->nbin);
        n = c->nbin;
    } else if (!json_is_string(u)) {
        return fail(c, "%s/uri: must be a string", p);
    } else if (strncmp(json_string_value(u), "data:", 5) == 0) {
        const char *s = json_string_value(u), *b = strstr(s, ";base64,");
        const char *comma = strchr(s, ',');
        if (!b || comma < b)
            return fail(c, "%s/uri: only base64 data: URIs are read", p);
        size_t bad;
        if (b64_decode(b + 8, strlen(b + 8), &data, &n, &bad) != 0)
            return fail(c, "%s/uri: bad base64 at character %zu of the data", p, bad);
    } else if (open_rel(c, json_string_value(u), p, &data, &n) != 0) {
        return -1;
    }
    d->bufs[k] = data;
    d->nbufs[k] = n;
    if ((unsigned long long)bl > n)
        return fail(c, "%s: byteLength %lld but the data has %zu bytes (short or missing .bin?)", p, bl, n);
    d->nbufs[k] = (size_t)bl;
    return 0;
}

/* The fields every bufferView V (at JSON pointer p) must have: its buffer
 * index, byteOffset (0 if absent) and byteLength; -1 after an error. */
static int view_head(ctx *c, json_t *V, const char *p, long long *b, long long *off, long long *bl)
{
    if (check_common(c, V, p) != 0
        || need_uint(c, V, "buffer", p, (long long)c->nbuffers, "buffer", b) != 0
        || get_uint(c, V, "byteOffset", p, -1, "", 0, off) < 0
        || need_uint(c, V, "byteLength", p, -1, "", bl) != 0)
        return -1;
    return 0;
}

/* The bytes of bufferView v: *base, *len, *stride (0 if absent). */
static int buffer_view(ctx *c, long long v, const unsigned char **base, size_t *len, size_t *stride)
{
    json_t *V = json_array_get(json_object_get(c->root, "bufferViews"), (size_t)v);
    char p[64];
    long long b, off, bl, st;
    snprintf(p, sizeof p, "/bufferViews/%lld", v);
    if (view_head(c, V, p, &b, &off, &bl) != 0
        || get_uint(c, V, "byteStride", p, -1, "", 0, &st) < 0)
        return -1;
    if (st != 0 && (st < 4 || st > 252))
        return fail(c, "%s/byteStride: %lld is outside 4..252", p, st);
    if (load_buffer(c, b) != 0)
        return -1;
    if ((unsigned long long)off + (unsigned long long)bl > c->d->nbufs[b])
        return fail(c, "%s: bytes %lld..%lld run past the end of buffer %lld (%zu bytes)",
                    p, off, off + bl, b, c->d->nbufs[b]);
    *base = c->d->bufs[b] + off;
    *len = (size_t)bl;
    *stride = (size_t)st;
    return 0;
}

/* ---- accessors -------------------------------------------------------- */
/* Accessor ai's members every use reads: its JSON pointer p,
 * componentType, count, bufferView (-1 if absent), byteOffset, type (a
 * string) and normalized (a boolean, false if absent). */
typedef struct acc_info {
    json_t *J;
    char p[64];
    long long ct, cnt, bv, off;
    const char *type;
    int norm;
} acc_info;

static int acc_head(ctx *c, long long ai, acc_info *a)
{
    a->J = json_array_get(json_object_get(c->root, "accessors"), (size_t)ai);
    snprintf(a->p, sizeof a->p, "/accessors/%lld", ai);
    if (check_common(c, a->J, a->p) != 0 || need_uint(c, a->J, "componentType", a->p, -1, "", &a->ct) != 0
        || need_uint(c, a->J, "count", a->p, -1, "", &a->cnt) != 0
        || get_uint(c, a->J, "bufferView", a->p, (long long)c->nbv, "bufferView", -1, &a->bv) < 0
        || get_uint(c, a->J, "byteOffset", a->p, -1, "", 0, &a->off) < 0)
        return -1;
    json_t *ty = json_object_get(a->J, "type"), *nz = json_object_get(a->J, "normalized");
    if (!json_is_string(ty))
        return fail(c, "%s/type: missing or not a string", a->p);
    if (nz && !json_is_boolean(nz))
        return fail(c, "%s/normalized: must be true or false", a->p);
    a->type = json_string_value(ty);
    a->norm = nz && json_is_true(nz);
    return 0;
}

/* The data of accessor p (cnt elements of es bytes at byteOffset off of
 * bufferView bv, or none when bv < 0: zeros): *base (NULL for zeros) and
 * *stride, checked to lie inside the bufferView. */
static int acc_data(ctx *c, const char *p, long long bv, long long off, long long cnt, size_t es,
                    const unsigned char **base, size_t *stride)
{
    *base = NULL;
    *stride = es;
    if (bv < 0)
        return off != 0 ? fail(c, "%s/byteOffset: set without a bufferView", p) : 0;
    size_t len, vst;
    if (buffer_view(c, bv, base, &len, &vst) != 0)
        return -1;
    if (vst) *stride = vst;
    if (*stride < es)
        return fail(c, "%s: byteStride %zu is less than the element size %zu", p, *stride, es);
    unsigned long long need = (unsigned long long)off + (unsigned long long)*stride * (unsigned long long)(cnt - 1) + es;
    if (need > len)
        return fail(c, "%s: needs %llu bytes of bufferView %lld, which has %zu", p, need, bv, len);
    *base += off;
    return 0;
}

static int csize(int ct)
{
    switch (ct) {
    case 5120: case 5121: return 1;
    case 5122: case 5123: return 2;
    case 5125: case 5126: return 4;
    default: return 0;
    }
}

static uint32_t rd32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* Component j of element at p (little-endian, as glTF stores it). */
static double comp(const unsigned char *p, int ct, int j, double *den, int norm)
{
    int s = csize(ct);
    const unsigned char *q = p + (size_t)j * (size_t)s;
    double v;
    *den = 1.0;
    switch (ct) {
    case 5126: { uint32_t u = rd32(q); float f; memcpy(&f, &u, 4); return (double)f; }
    case 5125: return (double)rd32(q);
    case 5120: v = (double)(signed char)q[0]; if (norm) { *den = 127.0; if (v < -127.0) v = -127.0; } return v;
    case 5121: v = (double)q[0]; if (norm) *den = 255.0; return v;
    case 5122: { int x = q[0] | q[1] << 8; if (x >= 32768) x -= 65536; v = (double)x;
                 if (norm) { *den = 32767.0; if (v < -32767.0) v = -32767.0; } return v; }
    default: v = (double)(q[0] | q[1] << 8); if (norm) *den = 65535.0; return v;
    }
}

long gltf_sparse_index(const gl_doc *d, int a, long s)
{
    const gl_acc *A = &d->accs[a];
    double den;
    return (long)comp(A->sp_idx + (size_t)s * (size_t)csize(A->sp_ict), A->sp_ict, 0, &den, 0);
}

long gltf_first_zero(const gl_doc *d, int a)
{
    const gl_acc *A = &d->accs[a];
    if (A->base || A->sp_n >= A->count)
        return -1;
    /* the indices strictly increase: the first gap */
    long lo = 0, hi = A->sp_n;                     /* index s == s below lo */
    while (lo < hi) {
        long m = lo + (hi - lo) / 2;
        if (gltf_sparse_index(d, a, m) == m) lo = m + 1; else hi = m;
    }
    return lo;
}

void gltf_vertex(const gl_doc *d, int a, long k, double num[3], double *den)
{
    const gl_acc *A = &d->accs[a];
    const unsigned char *p = NULL;
    long lo = 0, hi = A->sp_n;                     /* binary search of k */
    while (lo < hi) {
        long m = lo + (hi - lo) / 2, x = gltf_sparse_index(d, a, m);
        if (x == k) { p = A->sp_val + (size_t)m * 3u * (size_t)csize(A->ctype); break; }
        if (x < k) lo = m + 1; else hi = m;
    }
    if (!p && A->base)
        p = A->base + (size_t)k * A->stride;
    *den = 1.0;
    for (int j = 0; j < 3; j++)
        num[j] = p ? comp(p, A->ctype, j, den, A->normalized) : 0.0;
}

/* Check the data of accessor `ai` as a POSITION (role 0) or index (role
 * 1) accessor; for POSITION, fill the vertex hull and the claim check. */
static int check_accessor(ctx *c, long long ai, int role, long long nvert)
{
    gl_doc *d = c->d;
    gl_acc *A = &d->accs[ai];
    if (role == 0 && A->used)
        return 0;
    acc_info I;
    if (acc_head(c, ai, &I) != 0)
        return -1;
    json_t *J = I.J;
    const char *p = I.p;
    long long ct = I.ct, cnt = I.cnt, bv = I.bv, off = I.off;
    if (cnt < 1 || cnt > INT32_MAX)
        return fail(c, "%s/count: %lld is outside 1..2^31-1", p, cnt);
    const char *t = I.type;
    int ncomp = role == 0 ? 3 : 1;
    if (role == 0 && (strcmp(t, "VEC3") != 0 || !(ct == 5126 || (ct >= 5120 && ct <= 5123))))
        return fail(c, "%s: a POSITION accessor must be VEC3 of FLOAT (5126), or of the KHR_mesh_quantization "
                       "types 5120..5123; this one is %s of %lld", p, t, ct);
    if (role == 1 && (strcmp(t, "SCALAR") != 0 || !(ct == 5121 || ct == 5123 || ct == 5125)))
        return fail(c, "%s: an index accessor must be SCALAR of 5121, 5123 or 5125; this one is %s of %lld", p, t, ct);
    size_t es = (size_t)ncomp * (size_t)csize((int)ct);
    const unsigned char *base = NULL;
    size_t stride = es;
    if (acc_data(c, p, bv, off, cnt, es, &base, &stride) != 0)
        return -1;
    A->ctype = (int)ct;
    A->normalized = I.norm;
    A->count = (long)cnt;
    A->base = base;
    A->stride = stride;
    if (role == 1) {
        for (long k = 0; base && k < A->count; k++) {      /* no bufferView: zeros */
            double den, v = base ? comp(base + (size_t)k * stride, (int)ct, 0, &den, 0) : 0.0;
            if (v >= (double)nvert)
                return fail(c, "%s: index %.0f (element %ld) is out of range: the POSITION accessor has %lld vertices",
                            p, v, k, nvert);
        }
        return 0;
    }
    /* sparse substitution */
    json_t *S = json_object_get(J, "sparse");
    if (S) {
        char q[100];
        long long sc, ib, io, ic, vb, vo;
        snprintf(q, sizeof q, "%s/sparse", p);
        json_t *I = json_object_get(S, "indices"), *V = json_object_get(S, "values");
        if (!json_is_object(S) || !json_is_object(I) || !json_is_object(V))
            return fail(c, "%s: must be an object with objects 'indices' and 'values'", q);
        char qi[120], qv[120];
        snprintf(qi, sizeof qi, "%s/indices", q);
        snprintf(qv, sizeof qv, "%s/values", q);
        if (need_uint(c, S, "count", q, -1, "", &sc) != 0
            || need_uint(c, I, "bufferView", qi, (long long)c->nbv, "bufferView", &ib) != 0
            || get_uint(c, I, "byteOffset", qi, -1, "", 0, &io) < 0
            || need_uint(c, I, "componentType", qi, -1, "", &ic) != 0
            || need_uint(c, V, "bufferView", qv, (long long)c->nbv, "bufferView", &vb) != 0
            || get_uint(c, V, "byteOffset", qv, -1, "", 0, &vo) < 0)
            return -1;
        if (sc < 1 || sc > cnt)
            return fail(c, "%s/count: %lld is outside 1..%lld", q, sc, cnt);
        if (ic != 5121 && ic != 5123 && ic != 5125)
            return fail(c, "%s/componentType: %lld is not 5121, 5123 or 5125", qi, ic);
        const unsigned char *ibase, *vbase;
        size_t ilen, vlen, dummy;
        if (buffer_view(c, ib, &ibase, &ilen, &dummy) != 0 || buffer_view(c, vb, &vbase, &vlen, &dummy) != 0)
            return -1;
        if ((unsigned long long)io + (unsigned long long)sc * (unsigned long long)csize((int)ic) > ilen)
            return fail(c, "%s: %lld indices run past the end of bufferView %lld", qi, sc, ib);
        if ((unsigned long long)vo + (unsigned long long)sc * es > vlen)
            return fail(c, "%s: %lld values run past the end of bufferView %lld", qv, sc, vb);
        /* no table of count entries (count may be 2^31 - 1 with a few
         * bytes of data): the indices are searched (they must strictly
         * increase, as the spec says) */
        double prev = -1.0;
        for (long k = 0; k < sc; k++) {
            double den, ix = comp(ibase + io + (size_t)k * (size_t)csize((int)ic), (int)ic, 0, &den, 0);
            if (ix >= (double)cnt)
                return fail(c, "%s: index %.0f out of range (count %lld)", qi, ix, cnt);
            if (ix <= prev)
                return fail(c, "%s: index %.0f (element %ld) does not strictly increase", qi, ix, k);
            prev = ix;
        }
        A->sp_n = (long)sc;
        A->sp_ict = (int)ic;
        A->sp_idx = ibase + io;
        A->sp_val = vbase + vo;
    }
    /* min / max as written */
    int rmin = get_nums(c, J, "min", p, 3, A->min), rmax = get_nums(c, J, "max", p, 3, A->max);
    if (rmin < 0 || rmax < 0)
        return -1;
    A->has_minmax = rmin == 0 && rmax == 0;
    if (A->has_minmax)
        for (int j = 0; j < 3; j++)
            if (A->min[j] > A->max[j])
                return fail(c, "%s: min[%d] = %.17g > max[%d] = %.17g", p, j, A->min[j], j, A->max[j]);
    A->used = 1;
    /* the vertices: hull (outward for normalized integers) and claims */
    for (int j = 0; j < 3; j++) { A->vbox.lo[j] = HUGE_VAL; A->vbox.hi[j] = -HUGE_VAL; }
    A->outside = 0;
    A->first_out = -1;
    if (A->no_data)
        return 0;
    /* with a bufferView, every vertex (count is bounded by the data);
     * without, the sparse entries and one zero vertex standing for the
     * count - sp_n others (gltf_first_zero) */
    long nvis = A->base ? A->count : A->sp_n + (A->sp_n < A->count), kz = gltf_first_zero(d, (int)ai);
    for (long e = 0; e < nvis; e++) {
        double num[3], den;
        int out = 0;
        long k = A->base ? e : e < A->sp_n ? gltf_sparse_index(d, (int)ai, e) : kz;
        long mult = A->base || e < A->sp_n ? 1 : A->count - A->sp_n;
        gltf_vertex(d, (int)ai, k, num, &den);
        for (int j = 0; j < 3; j++) {
            iv v = den == 1.0 ? pt(num[j]) : div_enc(num[j], den);
            if (isnan(num[j])) { A->vnan = 1; out = 1; continue; }
            if (isinf(num[j])) A->vinf = 1;
            if (v.lo < A->vbox.lo[j]) A->vbox.lo[j] = v.lo;
            if (v.hi > A->vbox.hi[j]) A->vbox.hi[j] = v.hi;
            if (A->has_minmax && (v.lo < A->min[j] || v.hi > A->max[j])) out = 1;
        }
        if (out && A->has_minmax) {
            if (A->outside == 0 || k < A->first_out) A->first_out = k;
            A->outside += mult;
        }
    }
    return 0;
}

/* ---- nodes ------------------------------------------------------------ */
static int load_nodes(ctx *c, json_t *nodes, size_t nn, size_t nmesh)
{
    gl_doc *d = c->d;
    for (size_t k = 0; k < nn; k++)
        d->nodes[k].parent = -1;
    for (size_t k = 0; k < nn; k++) {
        json_t *N = json_array_get(nodes, k);
        gl_node *g = &d->nodes[k];
        char p[64];
        long long m;
        snprintf(p, sizeof p, "/nodes/%zu", k);
        if (check_common(c, N, p) != 0 || get_uint(c, N, "mesh", p, (long long)nmesh, "mesh", -1, &m) < 0)
            return -1;
        g->mesh = (int)m;
        json_t *ch = json_object_get(N, "children");
        if (ch) {
            if (!json_is_array(ch))
                return fail(c, "%s/children: must be an array", p);
            for (size_t i = 0; i < json_array_size(ch); i++) {
                json_t *v = json_array_get(ch, i);
                if (!json_is_integer(v) || json_integer_value(v) < 0 || json_integer_value(v) >= (long long)nn)
                    return fail(c, "%s/children/%zu: must be a node index below %zu", p, i, nn);
                long long cidx = json_integer_value(v);
                if (cidx == (long long)k)
                    return fail(c, "%s/children/%zu: node %zu is its own child (a cycle)", p, i, k);
                if (d->nodes[cidx].parent >= 0)
                    return fail(c, "%s/children/%zu: node %lld has two parents (nodes %d and %zu): "
                                   "the node tree must be a forest", p, i, cidx, d->nodes[cidx].parent, k);
                d->nodes[cidx].parent = (int)k;
            }
        }
        int rm = get_nums(c, N, "matrix", p, 16, g->matrix);
        g->t[0] = g->t[1] = g->t[2] = 0.0;
        g->s[0] = g->s[1] = g->s[2] = 1.0;
        g->r[0] = g->r[1] = g->r[2] = 0.0;
        g->r[3] = 1.0;
        int rt = get_nums(c, N, "translation", p, 3, g->t), rr = get_nums(c, N, "rotation", p, 4, g->r),
            rs = get_nums(c, N, "scale", p, 3, g->s);
        if (rm < 0 || rt < 0 || rr < 0 || rs < 0)
            return -1;
        if (rm == 0) {
            if (rt == 0 || rr == 0 || rs == 0)
                return fail(c, "%s: has both `matrix` and TRS properties", p);
            if (g->matrix[3] != 0.0 || g->matrix[7] != 0.0 || g->matrix[11] != 0.0 || g->matrix[15] != 1.0)
                return fail(c, "%s/matrix: the last row (elements 3, 7, 11, 15, column-major) must be 0 0 0 1; "
                               "a projective matrix is refused", p);
            g->has_matrix = 1;
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 4; j++)
                    setm(&g->local, i, j, pt(g->matrix[4 * j + i]));
        } else if (trs_local(g->t, g->r, g->s, &g->local) != 0) {
            return fail(c, "%s/rotation: the quaternion is zero, or its components span too wide a range", p);
        }
        json_t *skin = json_object_get(N, "skin");
        if (skin)
            note(c, "%s: a skinned mesh: its box is for the bind pose as if not skinned (not the rendered pose)", p);
        json_t *ext = json_object_get(N, "extensions");
        if (ext && json_object_get(ext, "EXT_mesh_gpu_instancing"))
            note(c, "%s: EXT_mesh_gpu_instancing: its instances are not bounded", p);
    }
    /* cycles: with one parent per node, a node whose parent chain never
     * reaches a root is on (or below) a cycle */
    int *state = calloc(nn ? nn : 1, sizeof *state);
    if (!state)
        return fail(c, "out of memory");
    for (size_t k = 0; k < nn; k++) {
        size_t x = k;
        while (state[x] == 0) {
            state[x] = 1;                          /* on the current walk */
            if (d->nodes[x].parent < 0) break;
            x = (size_t)d->nodes[x].parent;
        }
        if (state[x] == 1 && d->nodes[x].parent >= 0) {
            free(state);
            return fail(c, "/nodes/%zu: the node hierarchy has a cycle through node %zu", x, x);
        }
        for (x = k; state[x] == 1; x = (size_t)d->nodes[x].parent) {
            state[x] = 2;
            if (d->nodes[x].parent < 0) break;
        }
    }
    free(state);
    return 0;
}

/* World map of node k: its parent's world map (computed first: the
 * scenes are walked top-down) times its local map; once per node.  The
 * composition's status is not kept: an entry it could not bound is
 * [-inf, +inf], and every box mapped through it gets that axis whole with
 * CBX_ERANGE from cbx_transform_box_imat (no NaN reaches it: the local
 * maps are finite or infinite intervals, never NaN). */
static const gl_imat *world_of(gl_doc *d, int k)
{
    gl_node *g = &d->nodes[k];
    if (!g->world_done) {
        if (g->parent < 0)
            g->world = g->local;
        else
            (void)cbx_imat_compose(world_of(d, g->parent), &g->local, &g->world);
        g->world_done = 1;
    }
    return &g->world;
}

/* "r/a/b/k": the node indices from the root; a deep path keeps its tail */
static void node_path(const gl_doc *d, int k, char *buf, size_t n)
{
    char tmp[256];
    size_t pos = sizeof tmp - 1;
    tmp[pos] = '\0';
    for (int x = k; x >= 0; x = d->nodes[x].parent) {
        char num[24];
        int len = snprintf(num, sizeof num, x == k ? "%d" : "%d/", x);
        if (pos < (size_t)len + 4) {
            pos -= 3;
            memcpy(tmp + pos, "...", 3);
            break;
        }
        pos -= (size_t)len;
        memcpy(tmp + pos, num, (size_t)len);
    }
    snprintf(buf, n, "%s", tmp + pos);
}

static void worse(cbx_status *acc, cbx_status st)
{
    int a = *acc == CBX_EINVAL ? 3 : *acc == CBX_ERANGE ? 2 : *acc == CBX_EMPTY ? 1 : 0;
    int b = st == CBX_EINVAL ? 3 : st == CBX_ERANGE ? 2 : st == CBX_EMPTY ? 1 : 0;
    if (b > a) *acc = st;
}

static int add_leaf(ctx *c, int scene, int node, int prim, long long acc)
{
    gl_doc *d = c->d;
    if (d->nl == d->capl) {
        int cap = d->capl ? 2 * d->capl : 64;
        gl_leaf *l = realloc(d->leaves, (size_t)cap * sizeof *l);
        if (!l)
            return fail(c, "out of memory");
        d->leaves = l;
        d->capl = cap;
    }
    gl_leaf *L = &d->leaves[d->nl++];
    memset(L, 0, sizeof *L);
    L->scene = scene;
    L->node = node;
    L->mesh = d->nodes[node].mesh;
    L->prim = prim;
    L->acc = (int)acc;
    node_path(d, node, L->path, sizeof L->path);
    const gl_acc *A = &d->accs[acc];
    L->st = CBX_OK;
    if (c->fromv) {
        L->local = A->vbox;
        if (A->vnan) L->st = CBX_EINVAL;
    } else {
        for (int j = 0; j < 3; j++) { L->local.lo[j] = A->min[j]; L->local.hi[j] = A->max[j]; }
    }
    if (L->st == CBX_EINVAL) {
        for (int j = 0; j < 3; j++) { L->world.lo[j] = -HUGE_VAL; L->world.hi[j] = HUGE_VAL; }
    } else {
        worse(&L->st, cbx_transform_box_imat(world_of(d, node), &L->local, &L->world));
    }
    return 0;
}

/* The count of the primitive's index accessor, if any (*n unchanged). */
static int r_indices(ctx *c, json_t *pr, const char *q, long long *n)
{
    long long ind;
    int r = get_uint(c, pr, "indices", q, (long long)c->d->na, "accessor", -1, &ind);
    if (r == 0) {
        json_t *J = json_array_get(json_object_get(c->root, "accessors"), (size_t)ind);
        json_t *v = json_is_object(J) ? json_object_get(J, "count") : NULL;
        if (json_is_integer(v)) *n = json_integer_value(v);
    }
    return r < 0 ? -1 : 0;
}

/* Check mesh m's primitives (once) and their accessors. */
static int check_mesh(ctx *c, json_t *meshes, long long m, int *checked)
{
    if (checked[m])
        return 0;
    checked[m] = 1;
    json_t *M = json_array_get(meshes, (size_t)m);
    char p[64];
    snprintf(p, sizeof p, "/meshes/%lld", m);
    json_t *P = json_object_get(M, "primitives");
    if (!json_is_array(P) || json_array_size(P) == 0)
        return fail(c, "%s/primitives: must be a non-empty array", p);
    for (size_t k = 0; k < json_array_size(P); k++) {
        json_t *pr = json_array_get(P, k);
        char q[100];
        long long pos, ind;
        snprintf(q, sizeof q, "%s/primitives/%zu", p, k);
        if (check_common(c, pr, q) != 0)
            return -1;
        json_t *at = json_object_get(pr, "attributes");
        if (!json_is_object(at))
            return fail(c, "%s/attributes: missing or not an object", q);
        char qa[120];
        snprintf(qa, sizeof qa, "%s/attributes", q);
        if (need_uint(c, at, "POSITION", qa, (long long)c->d->na, "accessor", &pos) != 0)
            return -1;
        json_t *ex = json_object_get(pr, "extensions");
        if (ex && json_object_get(ex, "KHR_draco_mesh_compression")) {
            json_t *J = json_array_get(json_object_get(c->root, "accessors"), (size_t)pos);
            if (!json_object_get(J, "bufferView") && !json_object_get(J, "sparse")) {
                c->d->accs[pos].no_data = 1;
                if (c->fromv)
                    return fail(c, "%s: Draco-compressed vertices: --from-vertices cannot read them", q);
                note(c, "%s: Draco-compressed: the vertices were not checked against min/max", q);
            }
        }
        if (check_accessor(c, pos, 0, 0) != 0)
            return -1;
        const gl_acc *A = &c->d->accs[pos];
        if (!c->fromv && !A->has_minmax)
            return fail(c, "/accessors/%lld: a POSITION accessor without min/max (use --from-vertices to bound its vertices)", pos);
        if (A->vnan)
            note(c, "/accessors/%lld: some vertex has a NaN coordinate", pos);
        if (A->outside) {
            double num[3], den;
            gltf_vertex(c->d, (int)pos, A->first_out, num, &den);
            note(c, "/accessors/%lld: %ld of %ld vertices lie outside its min/max (first: vertex %ld = %.9g %.9g %.9g)%s",
                 pos, A->outside, A->count, A->first_out, num[0] / den, num[1] / den, num[2] / den,
                 c->fromv ? "" : "; its boxes are wrong: use --from-vertices");
        }
        long long mode, nv = A->count;
        if (get_uint(c, pr, "mode", q, 7, "mode", 4, &mode) < 0)
            return -1;
        if (r_indices(c, pr, q, &nv) < 0)
            return -1;
        if ((mode == 4 && nv % 3 != 0) || (mode == 1 && nv % 2 != 0) || ((mode == 2 || mode == 3) && nv < 2)
            || ((mode == 5 || mode == 6) && nv < 3))
            note(c, "%s: mode %lld with %lld vertices: a truncated primitive", q, mode, nv);
        if (json_object_get(pr, "targets"))
            note(c, "%s: morph targets: the box is for the unmorphed positions only", q);
        int r = get_uint(c, pr, "indices", q, (long long)c->d->na, "accessor", -1, &ind);
        if (r < 0)
            return -1;
        if (r == 0) {
            gl_acc save = c->d->accs[ind];
            int rc = check_accessor(c, ind, 1, A->count);
            if (save.used)
                c->d->accs[ind] = save;                /* also a POSITION: keep that */
            if (rc != 0)
                return -1;
        }
    }
    return 0;
}

static const char *const ok_required[] = {
    "KHR_mesh_quantization", "KHR_draco_mesh_compression", "KHR_texture_transform",
    "KHR_materials_pbrSpecularGlossiness", "KHR_materials_unlit", "KHR_technique_webgl",
    "KHR_texture_basisu", "KHR_lights_punctual", "KHR_materials_emissive_strength",
};

static int check_extensions(ctx *c)
{
    json_t *r = json_object_get(c->root, "extensionsRequired");
    if (!r)
        return 0;
    if (!json_is_array(r))
        return fail(c, "/extensionsRequired: must be an array");
    for (size_t k = 0; k < json_array_size(r); k++) {
        json_t *v = json_array_get(r, k);
        if (!json_is_string(v))
            return fail(c, "/extensionsRequired/%zu: must be a string", k);
        int ok = 0;
        for (size_t i = 0; i < sizeof ok_required / sizeof *ok_required; i++)
            ok |= strcmp(json_string_value(v), ok_required[i]) == 0;
        if (!ok)
            return fail(c, "/extensionsRequired/%zu: extension %s is required and not supported", k, json_string_value(v));
    }
    return 0;
}

/* ---- the document ----------------------------------------------------- */
static int parse_json(ctx *c, const unsigned char *txt, size_t n, const char *where)
{
    json_error_t je;
    c->root = json_loadb((const char *)txt, n, JSON_REJECT_DUPLICATES, &je);
    if (!c->root) {
        char e[sizeof je.text];
        esc_ctl(e, sizeof e, je.text);
        snprintf(c->err, c->errlen, "%s:%d:%d: %s%s", c->path, je.line, je.column, where, e);
        return -1;
    }
    if (!json_is_object(c->root))
        return fail(c, "/: the document must be a JSON object");
    return 0;
}

/* GLB: 12-byte header, a JSON chunk, an optional BIN chunk (spec 4.4). */
static int parse_glb(ctx *c)
{
    const unsigned char *f = c->d->file;
    size_t n = c->d->nfile;
    if (n < 12)
        return fail(c, "byte 0: %zu bytes: too short for a GLB header (12 bytes)", n);
    if (rd32(f + 4) != 2)
        return fail(c, "byte 4: GLB version %lu (only version 2 is read)", (unsigned long)rd32(f + 4));
    if (rd32(f + 8) != n)
        return fail(c, "byte 8: GLB length %lu differs from the file size %zu", (unsigned long)rd32(f + 8), n);
    if (n < 20)
        return fail(c, "byte 12: no JSON chunk (the file ends)");
    size_t jl = rd32(f + 12);
    if (rd32(f + 16) != 0x4E4F534Au)
        return fail(c, "byte 16: the first chunk's type is 0x%08lx, not JSON", (unsigned long)rd32(f + 16));
    if (jl > n - 20)
        return fail(c, "byte 12: JSON chunk length %zu runs past the end of the file (%zu bytes)", jl, n);
    if (jl % 4 != 0)
        return fail(c, "byte 12: JSON chunk length %zu is not a multiple of 4", jl);
    size_t off = 20 + jl;
    while (off < n) {
        if (n - off < 8)
            return fail(c, "byte %zu: truncated chunk header", off);
        size_t cl = rd32(f + off);
        uint32_t ty = rd32(f + off + 4);
        if (cl > n - off - 8)
            return fail(c, "byte %zu: chunk length %zu runs past the end of the file (%zu bytes)", off, cl, n);
        if (ty == 0x004E4942u) {
            if (c->has_bin)
                return fail(c, "byte %zu: a second BIN chunk", off);
            c->has_bin = 1;
            c->bin = f + off + 8;
            c->nbin = cl;
        }
        off += 8 + cl;
    }
    return parse_json(c, f + 20, jl, "in the GLB JSON chunk: ");
}

void gltf_free(gl_doc *d)
{
    if (d->json) json_decref((json_t *)d->json);
    for (int k = 0; k < d->nbuf; k++) free(d->bufs[k]);
    free(d->bufs);
    free(d->nbufs);
    free(d->accs);
    free(d->nodes);
    free(d->leaves);
    free(d->scenes);
    for (int a = 0; a < d->nanim; a++) {
        for (int s = 0; s < d->anims[a].nsmp; s++) {
            free(d->anims[a].smp[s].t);
            free(d->anims[a].smp[s].v);
        }
        free(d->anims[a].smp);
        free(d->anims[a].ch);
    }
    free(d->anims);
    free(d->file);
    memset(d, 0, sizeof *d);
}

/* ---- animations (--animated) ------------------------------------------ */
/* The numbers of animation accessor ai (for ptr, the sampler's member):
 * count elements of ncomp components of type `type`, FLOAT, or with ints
 * the normalized integer types the spec allows for rotations (5120..5123:
 * their numerators, one common factor per element, which leaves a
 * rotation unchanged).  Not sparse; every number finite. */
static int anim_acc(ctx *c, long long ai, const char *ptr, const char *type, int ncomp, int ints, long want,
                    double **out, long *count)
{
    acc_info I;
    if (acc_head(c, ai, &I) != 0)
        return -1;
    const char *p = I.p;
    long long ct = I.ct, cnt = I.cnt, bv = I.bv, off = I.off;
    int norm = I.norm;
    if (strcmp(I.type, type) != 0)
        return fail(c, "%s (%s): must be of type %s", p, ptr, type);
    if (!(ct == 5126 || (ints && norm && ct >= 5120 && ct <= 5123)))
        return fail(c, "%s (%s): must be FLOAT (5126)%s; this one is %lld", p, ptr,
                    ints ? ", or normalized 5120..5123" : "", ct);
    if (cnt < 1 || cnt > INT32_MAX / 12)
        return fail(c, "%s/count: %lld is outside 1..%d", p, cnt, INT32_MAX / 12);
    if (json_object_get(I.J, "sparse"))
        return fail(c, "%s (%s): a sparse animation accessor is not read", p, ptr);
    size_t es = (size_t)ncomp * (size_t)csize((int)ct), stride = es;
    const unsigned char *base = NULL;
    if (acc_data(c, p, bv, off, cnt, es, &base, &stride) != 0)
        return -1;
    /* checked before reading: without a bufferView the count is not
     * bounded by any data (key times that are all zero never increase) */
    if (want >= 0 && cnt != want)
        return fail(c, "%s: %lld elements where %ld are needed (one per key time; three for CUBICSPLINE)",
                    ptr, cnt, want);
    if (!base && cnt > 1 && want < 0)
        return fail(c, "%s (%s): %lld key times without a bufferView: all zero, not increasing", p, ptr, cnt);
    double *v = malloc((size_t)cnt * (size_t)ncomp * sizeof *v);
    if (!v)
        return fail(c, "out of memory");
    for (long long k = 0; k < cnt; k++)
        for (int j = 0; j < ncomp; j++) {
            double den, x = base ? comp(base + (size_t)k * stride, (int)ct, j, &den, norm) : 0.0;
            if (!isfinite(x)) {
                free(v);
                return fail(c, "%s (%s): element %lld is not finite", p, ptr, k);
            }
            v[k * ncomp + j] = x;
        }
    *out = v;
    *count = (long)cnt;
    return 0;
}

/* The animations' samplers and channels (GLTF_ANIMATED), or a note that
 * the boxes are for the static pose. */
static int load_anims(ctx *c)
{
    gl_doc *d = c->d;
    json_t *A;
    size_t na;
    if (top_array(c, "animations", &A, &na) != 0)
        return -1;
    if (na == 0)
        return 0;
    if (!c->anim) {
        note(c, "/animations: %zu animation%s not bounded: the boxes are for the static pose "
                "(--animated bounds every pose)", na, na == 1 ? " is" : "s are");
        return 0;
    }
    if (na > INT_MAX / 2)
        return fail(c, "too many animations");
    if (d->only_anim >= 0 && (size_t)d->only_anim >= na)
        return fail(c, "/animations: --animation %d: the file has %zu animation%s", d->only_anim, na, na == 1 ? "" : "s");
    d->anims = calloc(na, sizeof *d->anims);
    if (!d->anims)
        return fail(c, "out of memory");
    d->nanim = (int)na;
    static const char *const paths[3] = { "translation", "rotation", "scale" };
    for (size_t a = 0; a < na; a++) {
        json_t *N = json_array_get(A, a), *S, *C;
        gl_anim *G = &d->anims[a];
        char p[64];
        snprintf(p, sizeof p, "/animations/%zu", a);
        if (check_common(c, N, p) != 0)
            return -1;
        S = json_object_get(N, "samplers");
        C = json_object_get(N, "channels");
        if (!json_is_array(S) || json_array_size(S) == 0 || !json_is_array(C) || json_array_size(C) == 0)
            return fail(c, "%s: must have non-empty arrays 'samplers' and 'channels'", p);
        if (json_array_size(S) > INT_MAX / 2 || json_array_size(C) > INT_MAX / 2)
            return fail(c, "%s: too many samplers or channels", p);
        G->smp = calloc(json_array_size(S), sizeof *G->smp);
        G->ch = calloc(json_array_size(C), sizeof *G->ch);
        if (!G->smp || !G->ch)
            return fail(c, "out of memory");
        G->nsmp = (int)json_array_size(S);
        for (int s = 0; s < G->nsmp; s++) {
            json_t *X = json_array_get(S, (size_t)s), *ip;
            gl_sampler *M = &G->smp[s];
            char q[100];
            long long in;
            snprintf(q, sizeof q, "%s/samplers/%d", p, s);
            if (check_common(c, X, q) != 0 || need_uint(c, X, "input", q, (long long)d->na, "accessor", &in) != 0
                || need_uint(c, X, "output", q, (long long)d->na, "accessor", &M->output) != 0)
                return -1;
            ip = json_object_get(X, "interpolation");
            M->interp = GL_LINEAR;
            if (ip) {
                const char *v = json_is_string(ip) ? json_string_value(ip) : "";
                if (strcmp(v, "LINEAR") == 0) M->interp = GL_LINEAR;
                else if (strcmp(v, "STEP") == 0) M->interp = GL_STEP;
                else if (strcmp(v, "CUBICSPLINE") == 0) M->interp = GL_CUBICSPLINE;
                else return fail(c, "%s/interpolation: must be LINEAR, STEP or CUBICSPLINE", q);
            }
            strcat(q, "/input");
            if (anim_acc(c, in, q, "SCALAR", 1, 0, -1, &M->t, &M->n) != 0)
                return -1;
            for (long k = 1; k < M->n; k++)
                if (!(M->t[k] > M->t[k - 1]))
                    return fail(c, "%s: key time %ld (%.17g) is not above the one before (%.17g)", q, k,
                                M->t[k], M->t[k - 1]);
        }
        G->nch = (int)json_array_size(C);
        for (int k = 0; k < G->nch; k++) {
            json_t *X = json_array_get(C, (size_t)k), *T, *pa;
            gl_channel *H = &G->ch[k];
            char q[100], qt[120];
            long long smp, node;
            snprintf(q, sizeof q, "%s/channels/%d", p, k);
            snprintf(qt, sizeof qt, "%s/target", q);
            H->node = -1;
            if (check_common(c, X, q) != 0 || need_uint(c, X, "sampler", q, G->nsmp, "sampler", &smp) != 0)
                return -1;
            T = json_object_get(X, "target");
            if (!T)
                return fail(c, "%s: missing member 'target'", q);
            if (check_common(c, T, qt) != 0 || get_uint(c, T, "node", qt, d->nn, "node", -1, &node) < 0)
                return -1;
            pa = json_object_get(T, "path");
            if (!json_is_string(pa))
                return fail(c, "%s/path: missing or not a string", qt);
            const char *pv = json_string_value(pa);
            H->path = -1;
            for (int j = 0; j < 3; j++)
                if (strcmp(pv, paths[j]) == 0) H->path = j;
            if (H->path < 0) {
                if (strcmp(pv, "weights") != 0)   /* morph weights: flagged with the targets */
                    note(c, "%s/path: '%s' is not bounded", qt, pv);
                continue;
            }
            if (node < 0)                         /* no node: an extension's target */
                continue;
            if (d->nodes[node].has_matrix)
                return fail(c, "%s/node: node %lld has a `matrix`: an animated node must use TRS", qt, node);
            for (int j = 0; j < k; j++)
                if (G->ch[j].node == node && G->ch[j].path == H->path)
                    return fail(c, "%s: node %lld's %s is animated twice (channel %d too)", qt, node, pv, j);
            gl_sampler *M = &G->smp[smp];
            int nc = H->path == 1 ? 4 : 3;
            char qo[120];
            snprintf(qo, sizeof qo, "%s/samplers/%lld/output", p, smp);
            if (!M->v) {
                long cnt, want = M->interp == GL_CUBICSPLINE ? 3 * M->n : M->n;
                if (anim_acc(c, M->output, qo, nc == 4 ? "VEC4" : "VEC3", nc, nc == 4, want, &M->v, &cnt) != 0)
                    return -1;
                M->ncomp = nc;
                for (long e = 0; nc == 4 && e < M->n; e++) {
                    const double *v = M->v + 4 * (M->interp == GL_CUBICSPLINE ? 3 * e + 1 : e);
                    if (v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0 && v[3] == 0.0)
                        return fail(c, "%s: the rotation of key %ld is zero", qo, e);
                }
            } else if (M->ncomp != nc) {
                return fail(c, "%s: read as %s by one channel and as %s by %s", qo,
                            M->ncomp == 4 ? "a rotation" : "a translation or scale", pv, q);
            }
            H->node = (int)node;
            H->sampler = (int)smp;
        }
    }
    return 0;
}

/* the hull of two enclosures */
static iv hull2(iv a, iv b)
{
    iv r;
    r.lo = a.lo < b.lo ? a.lo : b.lo;
    r.hi = a.hi > b.hi ? a.hi : b.hi;
    return r;
}

/* the rotation matrix of q (any non-zero scale), entry-wise enclosed;
 * [-1, 1] entries (every rotation's) if q cannot be bounded here */
static int rot_point(const double q[4], iv R[3][3])
{
    static const double zero[3] = { 0, 0, 0 }, one[3] = { 1, 1, 1 };
    gl_imat L;
    int lost = trs_local(zero, q, one, &L) != 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            R[i][j].lo = lost ? -1.0 : L.lo[i][j];
            R[i][j].hi = lost ? 1.0 : L.hi[i][j];
        }
    return lost;
}

/* the rotation of every q/|q| with q in the box Q (componentwise
 * intervals): the unit formula over |q|^2, in intervals; [-1, 1] entries
 * where Q may hold 0 or its numbers are too large to bound here */
static int rot_box(const iv Q[4], iv R[3][3])
{
    int lost = 0;
    for (int k = 0; k < 4; k++)
        if (!(fabs(Q[k].lo) <= 0x1p250 && fabs(Q[k].hi) <= 0x1p250)) lost = 1;
    iv n;
    unit_formula(Q, R, &n);
    if (!(n.lo >= 0x1p-500)) lost = 1;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            iv e = lost ? pt(0.0) : iv_div(R[i][j], n);
            R[i][j].lo = lost || e.lo < -1.0 ? -1.0 : e.lo;   /* a rotation's entries are in [-1, 1] */
            R[i][j].hi = lost || e.hi > 1.0 ? 1.0 : e.hi;
        }
    return lost;
}

/* (1 - u) a + u b at a point u of [0, 1], enclosed */
static iv lerp_at(double a, double b, double u)
{
    return iv_add(iv_mul(add_enc(1.0, -u), pt(a)), mul_enc(u, b));
}

/* Sampler M over the cell [ca, cb) (inside one interval between its key
 * times, or before the first, or after the last; a single time when
 * ca == cb): for translation and scale, V[0..2] encloses the value at
 * every t of the cell (its end cb is the next cell's start: a STEP
 * sampler's jump there is left to it); for a rotation, R encloses its
 * rotation matrix.  1 if the rotation could not
 * be bounded (R is then [-1, 1]), 0 otherwise. */
static int sample_cell(const gl_sampler *M, double ca, double cb, iv V[3], iv R[3][3])
{
    long lo = 0, hi = M->n;                       /* first key time above ca */
    while (lo < hi) {
        long m = lo + (hi - lo) / 2;
        if (M->t[m] <= ca) lo = m + 1; else hi = m;
    }
    long i = lo - 1;                              /* t[i] <= ca < t[i + 1] */
    int nc = M->ncomp, cub = M->interp == GL_CUBICSPLINE, ofs = cub ? nc : 0, st = cub ? 3 * nc : nc;
    if (i < 0 || i + 1 >= M->n) {                 /* clamped: the first or last key */
        const double *v = M->v + (size_t)(i < 0 ? 0 : M->n - 1) * (size_t)st + (size_t)ofs;
        if (nc == 4) return rot_point(v, R);
        for (int j = 0; j < 3; j++) V[j] = pt(v[j]);
        return 0;
    }
    const double *a = M->v + (size_t)i * (size_t)st + (size_t)ofs, *b = a + st;
    if (M->interp == GL_STEP) {                   /* cells are half-open: [ca, cb) */
        if (nc == 4) return rot_point(a, R);
        for (int j = 0; j < 3; j++) V[j] = pt(a[j]);
        return 0;
    }
    /* the cell's parameters u = (t - t[i]) / (t[i+1] - t[i]) in [ul, uh] */
    iv den = add_enc(M->t[i + 1], -M->t[i]);
    double ul = 0.0, uh = 1.0;
    if (den.lo > 0) {
        ul = iv_div(add_enc(ca, -M->t[i]), den).lo;
        uh = iv_div(add_enc(cb, -M->t[i]), den).hi;
        if (!(ul >= 0.0)) ul = 0.0;
        if (!(uh <= 1.0)) uh = 1.0;
        if (ul > uh) ul = uh;
    }
    if (M->interp == GL_LINEAR) {
        if (nc == 4) {                            /* slerp: the library's cells */
            cbx_trs k0, k1;
            cbx_imat P[8];
            size_t np = 0;
            memset(&k0, 0, sizeof k0);
            k0.s[0] = k0.s[1] = k0.s[2] = 1.0;
            k1 = k0;
            memcpy(k0.q, a, sizeof k0.q);
            memcpy(k1.q, b, sizeof k1.q);
            if (cbx_trs_pieces(&k0, &k1, CBX_SLERP, ul, uh, 0, P, 8, &np) != CBX_OK || np == 0) {
                for (int r = 0; r < 3; r++) for (int j = 0; j < 3; j++) { R[r][j].lo = -1.0; R[r][j].hi = 1.0; }
                return 1;
            }
            for (int r = 0; r < 3; r++)
                for (int j = 0; j < 3; j++) {
                    R[r][j].lo = P[0].lo[r][j];
                    R[r][j].hi = P[0].hi[r][j];
                    for (size_t k = 1; k < np; k++) {
                        if (P[k].lo[r][j] < R[r][j].lo) R[r][j].lo = P[k].lo[r][j];
                        if (P[k].hi[r][j] > R[r][j].hi) R[r][j].hi = P[k].hi[r][j];
                    }
                }
            return 0;
        }
        for (int j = 0; j < 3; j++)               /* linear in u: its ends */
            V[j] = hull2(lerp_at(a[j], b[j], ul), lerp_at(a[j], b[j], uh));
        return 0;
    }
    /* CUBICSPLINE: the segment in Bezier form, points a, a + D aout / 3,
     * b - D bin / 3, b (D = t[i+1] - t[i]); the part over [ul, uh] lies in
     * the hull of its own Bezier points, the blossoms P(ul, ul, ul),
     * P(ul, ul, uh), P(ul, uh, uh), P(uh, uh, uh) (de Casteljau steps in
     * intervals) */
    const double *aout = a + nc, *bin = b - nc;
    iv W[4];
    for (int j = 0; j < nc; j++) {
        iv P[4];
        P[0] = pt(a[j]);
        P[1] = iv_add(pt(a[j]), iv_div(iv_mul(den, pt(aout[j])), pt(3.0)));
        P[2] = iv_add(pt(b[j]), iv_neg(iv_div(iv_mul(den, pt(bin[j])), pt(3.0))));
        P[3] = pt(b[j]);
        static const int sel[4][3] = { { 0, 0, 0 }, { 0, 0, 1 }, { 0, 1, 1 }, { 1, 1, 1 } };
        for (int k = 0; k < 4; k++) {
            iv B[4] = { P[0], P[1], P[2], P[3] };
            for (int l = 0; l < 3; l++) {
                double u = sel[k][l] ? uh : ul;
                iv om = add_enc(1.0, -u);
                for (int m = 0; m + l < 3; m++)
                    B[m] = iv_add(iv_mul(om, B[m]), iv_mul(pt(u), B[m + 1]));
            }
            W[j] = k == 0 ? B[0] : hull2(W[j], B[0]);
        }
    }
    if (nc == 4)
        return rot_box(W, R);
    for (int j = 0; j < 3; j++) V[j] = W[j];
    return 0;
}

static int cmp_dbl(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

typedef struct anim_ctx {
    gl_doc *d;
    const gl_anim *G;
    int *chan;                  /* chan[3 k + path]: channel of node k, or -1 */
    signed char *aff;           /* node k or one above it is animated */
    gl_imat *world;             /* the cell's world maps */
    long *stamp, cell;          /* world[k] is this cell's when stamp[k] == cell */
    int lost;                   /* some rotation bounded as any rotation */
} anim_ctx;

/* node k's world map over the cell [ca, cb] */
static const gl_imat *cell_world(anim_ctx *A, int k, double ca, double cb)
{
    gl_doc *d = A->d;
    gl_node *g = &d->nodes[k];
    if (!A->aff[k])
        return world_of(d, k);
    if (A->stamp[k] == A->cell)
        return &A->world[k];
    gl_imat L = g->local;
    const int *ch = A->chan + 3 * (size_t)k;
    if (ch[0] >= 0 || ch[1] >= 0 || ch[2] >= 0) {
        iv T[3], S[3], R[3][3], dummy[3][3], unused[3];   /* sample_cell's outputs a path does not fill */
        for (int j = 0; j < 3; j++) { T[j] = pt(g->t[j]); S[j] = pt(g->s[j]); }
        if (ch[0] >= 0)
            (void)sample_cell(&A->G->smp[A->G->ch[ch[0]].sampler], ca, cb, T, dummy);
        if (ch[2] >= 0)
            (void)sample_cell(&A->G->smp[A->G->ch[ch[2]].sampler], ca, cb, S, dummy);
        if (ch[1] >= 0)
            A->lost |= sample_cell(&A->G->smp[A->G->ch[ch[1]].sampler], ca, cb, unused, R);
        else
            A->lost |= rot_point(g->r, R);
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++)
                setm(&L, i, j, iv_mul(R[i][j], S[j]));
            setm(&L, i, 3, T[i]);
        }
    }
    if (g->parent < 0)
        A->world[k] = L;
    else
        (void)cbx_imat_compose(cell_world(A, g->parent, ca, cb), &L, &A->world[k]);
    A->stamp[k] = A->cell;
    return &A->world[k];
}

/* --animated: each mesh instance's box is joined with its boxes over every
 * pose of every animation.  An animation's key times (all its channels')
 * cut the time line into intervals, each cut into d->cells cells
 * [ca, cb) of equal length (ends rounded, but shared by neighbours: the
 * cells cover the interval), and the last key time is a cell of its own.  In a cell, every animated node's local map is an
 * interval matrix that holds T(t) R(t) diag(S(t)) at every t of the cell
 * (each of T, R, S enclosed over the cell by sample_cell), the nodes below
 * an animated one compose their chain again (cbx_imat_compose), and each
 * of their instances' boxes is mapped by cbx_transform_box_imat.  Before
 * its first key and after its last a channel holds its first or last
 * value: the cells at the ends of the time line cover those times. */
static int anim_bound(ctx *c)
{
    gl_doc *d = c->d;
    size_t nn = (size_t)d->nn;
    anim_ctx A;
    memset(&A, 0, sizeof A);
    A.d = d;
    A.chan = malloc(3 * (nn + 1) * sizeof *A.chan);
    A.aff = malloc(nn + 1);
    A.world = malloc((nn + 1) * sizeof *A.world);
    A.stamp = malloc((nn + 1) * sizeof *A.stamp);
    int rc = 0;
    if (!A.chan || !A.aff || !A.world || !A.stamp)
        rc = fail(c, "out of memory");
    for (int a = 0; a < d->nanim && rc == 0; a++) {
        const gl_anim *G = &d->anims[a];
        if (d->only_anim >= 0 && a != d->only_anim)
            continue;
        A.G = G;
        for (size_t k = 0; k < 3 * nn; k++) A.chan[k] = -1;
        size_t nt = 0;
        for (int h = 0; h < G->nch; h++)
            if (G->ch[h].node >= 0) {
                A.chan[3 * (size_t)G->ch[h].node + (size_t)G->ch[h].path] = h;
                nt += (size_t)G->smp[G->ch[h].sampler].n;
            }
        if (nt == 0)
            continue;
        /* affected: animated, or below an animated node */
        for (size_t k = 0; k < nn; k++) {
            int x = (int)k, hit = 0;
            for (; x >= 0 && !hit; x = d->nodes[x].parent)
                hit = A.chan[3 * (size_t)x] >= 0 || A.chan[3 * (size_t)x + 1] >= 0 || A.chan[3 * (size_t)x + 2] >= 0;
            A.aff[k] = (signed char)hit;
            A.stamp[k] = -1;
        }
        double *tau = malloc(nt * sizeof *tau);
        if (!tau) { rc = fail(c, "out of memory"); break; }
        size_t m = 0;
        for (int h = 0; h < G->nch; h++)
            if (G->ch[h].node >= 0) {
                const gl_sampler *M = &G->smp[G->ch[h].sampler];
                for (long e = 0; e < M->n; e++) tau[m++] = M->t[e];
            }
        qsort(tau, m, sizeof *tau, cmp_dbl);
        size_t u = 0;
        for (size_t e = 0; e < m; e++)
            if (u == 0 || tau[e] != tau[u - 1]) tau[u++] = tau[e];
        /* the cells [ca, cb) of each interval, then the last key time
         * alone (the pose from there on) */
        size_t K = (size_t)d->cells, ncell = (u - 1) * K + 1;
        for (size_t q = 0; q < ncell; q++) {
            size_t iv0 = q / K, r = q % K;
            int last = q + 1 == ncell;
            double t0 = last ? tau[u - 1] : tau[iv0], t1 = last ? t0 : tau[iv0 + 1], w = t1 - t0;
            double ca = r == 0 || last ? t0 : t0 + w * ((double)r / (double)K);
            double cb = r + 1 == K || last ? t1 : t0 + w * ((double)(r + 1) / (double)K);
            /* the same rounded ends for neighbours; inside [t0, t1] */
            if (ca < t0) ca = t0;
            if (ca > t1) ca = t1;
            if (cb < ca) cb = ca;
            if (cb > t1) cb = t1;
            A.cell = (long)q;
            for (int k = 0; k < d->nl; k++) {
                gl_leaf *L = &d->leaves[k];
                if (!A.aff[L->node] || L->st == CBX_EINVAL)
                    continue;
                cbx_box b;
                cbx_status st = cbx_transform_box_imat(cell_world(&A, L->node, ca, cb), &L->local, &b);
                if (st == CBX_EMPTY)
                    continue;
                worse(&L->st, st);
                for (int j = 0; j < 3; j++) {
                    if (b.lo[j] < L->world.lo[j]) L->world.lo[j] = b.lo[j];
                    if (b.hi[j] > L->world.hi[j]) L->world.hi[j] = b.hi[j];
                }
            }
        }
        free(tau);
    }
    if (rc == 0 && A.lost)
        note(c, "/animations: a rotation was bounded as any rotation (a key's numbers too large or too "
                "small to bound here, or a cubic segment whose quaternions may pass through zero)");
    free(A.chan);
    free(A.aff);
    free(A.world);
    free(A.stamp);
    return rc;
}

/* the scene's box and status: the hull of its instances' */
static void scene_hull(gl_doc *d, gl_scene *G)
{
    G->st = G->n == 0 ? CBX_EMPTY : CBX_OK;
    for (int j = 0; j < 3; j++) { G->world.lo[j] = HUGE_VAL; G->world.hi[j] = -HUGE_VAL; }
    for (int k = G->first; k < G->first + G->n; k++) {
        worse(&G->st, d->leaves[k].st);
        for (int j = 0; j < 3; j++) {
            if (d->leaves[k].world.lo[j] < G->world.lo[j]) G->world.lo[j] = d->leaves[k].world.lo[j];
            if (d->leaves[k].world.hi[j] > G->world.hi[j]) G->world.hi[j] = d->leaves[k].world.hi[j];
        }
    }
}

static int load(ctx *c)
{
    gl_doc *d = c->d;
    if (tool_read_all(c->path, &d->file, &d->nfile) != 0)
        return fail(c, "cannot read: %s", strerror(errno));
    if (d->nfile >= 4 && memcmp(d->file, "glTF", 4) == 0) {
        if (parse_glb(c) != 0) return -1;
    } else if (parse_json(c, d->file, d->nfile, "") != 0) {
        return -1;
    }
    d->json = c->root;
    json_t *asset = json_object_get(c->root, "asset"), *ver = asset ? json_object_get(asset, "version") : NULL;
    if (!json_is_object(asset) || !json_is_string(ver))
        return fail(c, "/asset: missing, or without a string `version`");
    if (strncmp(json_string_value(ver), "2.", 2) != 0)
        return fail(c, "/asset/version: '%s': only glTF 2.x is read", json_string_value(ver));
    if (check_extensions(c) != 0 || check_materials(c) != 0)
        return -1;
    json_t *nodes, *meshes, *accs, *bvs, *bufs, *scenes;
    size_t nn, nm, na, ns;
    if (top_array(c, "nodes", &nodes, &nn) || top_array(c, "meshes", &meshes, &nm)
        || top_array(c, "accessors", &accs, &na) || top_array(c, "bufferViews", &bvs, &c->nbv)
        || top_array(c, "buffers", &bufs, &c->nbuffers) || top_array(c, "scenes", &scenes, &ns))
        return -1;
    if (nn > INT_MAX / 2 || na > INT_MAX / 2 || c->nbuffers > INT_MAX / 2)
        return fail(c, "too many objects");
    d->nn = (int)nn; d->na = (int)na; d->nbuf = (int)c->nbuffers;
    d->nodes = calloc(nn + 1, sizeof *d->nodes);
    d->accs = calloc(na + 1, sizeof *d->accs);
    d->bufs = calloc(c->nbuffers + 1, sizeof *d->bufs);
    d->nbufs = calloc(c->nbuffers + 1, sizeof *d->nbufs);
    d->scenes = calloc(ns + 1, sizeof *d->scenes);
    int *checked = calloc(nm + 1, sizeof *checked);
    if (!d->nodes || !d->accs || !d->bufs || !d->nbufs || !d->scenes || !checked) {
        free(checked);
        return fail(c, "out of memory");
    }
    for (size_t k = 0; k < c->nbuffers; k++) {
        char p[64];
        snprintf(p, sizeof p, "/buffers/%zu", k);
        if (check_common(c, json_array_get(bufs, k), p) != 0) { free(checked); return -1; }
    }
    /* every bufferView inside its buffer's declared byteLength, used or not */
    for (size_t k = 0; k < c->nbv; k++) {
        json_t *V = json_array_get(bvs, k);
        char p[64];
        long long b, off, bl, blen;
        snprintf(p, sizeof p, "/bufferViews/%zu", k);
        if (view_head(c, V, p, &b, &off, &bl) != 0
            || need_uint(c, json_array_get(bufs, (size_t)b), "byteLength", "/buffers", -1, "", &blen) != 0) {
            free(checked);
            return -1;
        }
        if (off + bl > blen) {
            free(checked);
            return fail(c, "%s: bytes %lld..%lld run past the end of buffer %lld (byteLength %lld)",
                        p, off, off + bl, b, blen);
        }
    }
    for (size_t k = 0; k < nm; k++) {
        char p[64];
        snprintf(p, sizeof p, "/meshes/%zu", k);
        if (check_common(c, json_array_get(meshes, k), p) != 0) { free(checked); return -1; }
    }
    long long sc;                  /* checked only: every scene is printed */
    if (get_uint(c, c->root, "scene", "", (long long)ns, "scene", 0, &sc) < 0 || load_nodes(c, nodes, nn, nm) != 0
        || load_anims(c) != 0) {
        free(checked);
        return -1;
    }
    if (ns == 0) {
        free(checked);
        return fail(c, "/scenes: the file has no scene: nothing to bound");
    }
    d->ns = (int)ns;
    int *stack = malloc((nn + 1) * sizeof *stack);
    size_t *listed = calloc(nn + 1, sizeof *listed);   /* scene s + 1 that lists the root */
    if (!stack || !listed) { free(stack); free(listed); free(checked); return fail(c, "out of memory"); }
    int rc = 0;
    for (size_t s = 0; s < ns && rc == 0; s++) {
        json_t *S = json_array_get(scenes, s), *roots;
        char p[64];
        snprintf(p, sizeof p, "/scenes/%zu", s);
        if ((rc = check_common(c, S, p)) != 0) break;
        roots = json_object_get(S, "nodes");
        if (roots && !json_is_array(roots)) { rc = fail(c, "%s/nodes: must be an array", p); break; }
        gl_scene *G = &d->scenes[s];
        G->first = d->nl;
        for (size_t r = 0; roots && r < json_array_size(roots) && rc == 0; r++) {
            json_t *v = json_array_get(roots, r);
            if (!json_is_integer(v) || json_integer_value(v) < 0 || json_integer_value(v) >= (long long)nn) {
                rc = fail(c, "%s/nodes/%zu: must be a node index below %zu", p, r, nn);
                break;
            }
            int root = (int)json_integer_value(v);
            /* the spec's uniqueItems: a root listed twice would bound
             * its subtree twice (n roots listing one mesh of n primitives:
             * n^2 instances from a file of size n) */
            if (listed[root] == s + 1) {
                rc = fail(c, "%s/nodes/%zu: node %d is listed twice", p, r, root);
                break;
            }
            listed[root] = s + 1;
            if (d->nodes[root].parent >= 0) {
                rc = fail(c, "%s/nodes/%zu: node %d is not a root (it is a child of node %d)", p, r, root, d->nodes[root].parent);
                break;
            }
            /* depth-first, children in file order */
            int top = 0;
            stack[top++] = root;
            while (top > 0 && rc == 0) {
                int x = stack[--top];
                world_of(d, x);                    /* parent done: one step */
                json_t *N = json_array_get(nodes, (size_t)x), *ch = json_object_get(N, "children");
                if (d->nodes[x].mesh >= 0) {
                    long long m = d->nodes[x].mesh;
                    if ((rc = check_mesh(c, meshes, m, checked)) != 0) break;
                    json_t *P = json_object_get(json_array_get(meshes, (size_t)m), "primitives");
                    for (size_t k = 0; k < json_array_size(P) && rc == 0; k++) {
                        json_t *at = json_object_get(json_array_get(P, k), "attributes");
                        rc = add_leaf(c, (int)s, x, (int)k, json_integer_value(json_object_get(at, "POSITION")));
                    }
                }
                for (size_t i = json_array_size(ch); i-- > 0;)
                    stack[top++] = (int)json_integer_value(json_array_get(ch, i));
            }
        }
        G->n = d->nl - G->first;
        if (G->n == 0 && rc == 0)
            note(c, "%s: the scene has no mesh instance", p);
    }
    free(stack);
    free(listed);
    free(checked);
    if (rc == 0 && d->nanim > 0)
        rc = anim_bound(c);
    for (int k = 0; k < d->ns && rc == 0; k++)
        scene_hull(d, &d->scenes[k]);
    return rc;
}

int gltf_load(gl_doc *d, const char *path, unsigned opts, FILE *notes, char *err, size_t errlen)
{
    ctx c;
    memset(d, 0, sizeof *d);
    memset(&c, 0, sizeof c);
    c.d = d;
    c.path = path;
    c.err = err;
    c.errlen = errlen;
    c.notes = notes;
    c.fromv = (opts & GLTF_FROM_VERTICES) != 0;
    c.anim = (opts & GLTF_ANIMATED) != 0;
    d->cells = (int)((opts >> 8) & 0x1fffu);
    if (d->cells < 1 || d->cells > GLTF_ANIM_CELLS_MAX)
        d->cells = GLTF_ANIM_CELLS;
    d->only_anim = (int)(opts >> 21) - 1;
    /* the folder that relative URIs may not leave */
    char tmp[PATH_MAX];
    snprintf(tmp, sizeof tmp, "%s", path);
    char *sl = strrchr(tmp, '/');
    if (sl) { if (sl == tmp) sl[1] = '\0'; else *sl = '\0'; }
    else snprintf(tmp, sizeof tmp, ".");
    if (!realpath(tmp, c.dir)) {
        fail(&c, "cannot resolve its folder: %s", strerror(errno));
        return -1;
    }
    if (load(&c) != 0) {
        if (!d->json && c.root) json_decref(c.root);
        gltf_free(d);
        return -1;
    }
    return 0;
}

/* The `name` of element k of top-level array `arr` as a JSON string
 * (escaped by jansson; malloc'd), or NULL if it has none. */
static char *name_json(const gl_doc *d, const char *arr, int k)
{
    json_t *o = json_array_get(json_object_get((json_t *)d->json, arr), (size_t)k);
    json_t *n = o ? json_object_get(o, "name") : NULL;
    return json_is_string(n) ? json_dumps(n, JSON_ENCODE_ANY) : NULL;
}

/* option opt's argument s as a whole number in lo..hi, or -1 (said) */
static long num_arg(const char *opt, const char *s, long lo, long hi)
{
    char *e;
    long n = strtol(s, &e, 10);
    if (*s == '\0' || *e || n < lo || n > hi) {
        fprintf(stderr, "certbox: %s: '%s' is not a whole number in %ld..%ld\n", opt, s, lo, hi);
        return -1;
    }
    return n;
}

int gltf_main(int argc, char **argv)
{
    int json = 0, hex = 0;
    unsigned opts = 0;
    const char *path = NULL;
    for (int k = 1; k < argc; k++) {
        if (strcmp(argv[k], "--json") == 0) json = 1;
        else if (strcmp(argv[k], "--hex") == 0) hex = 1;
        else if (strcmp(argv[k], "--from-vertices") == 0) opts |= GLTF_FROM_VERTICES;
        else if (strcmp(argv[k], "--animated") == 0) opts |= GLTF_ANIMATED;
        else if (strcmp(argv[k], "--cells") == 0 && k + 1 < argc) {
            long n = num_arg("--cells", argv[++k], 1, GLTF_ANIM_CELLS_MAX);
            if (n < 0) return 2;
            opts |= GLTF_CELLS(n);
        } else if (strcmp(argv[k], "--animation") == 0 && k + 1 < argc) {
            long n = num_arg("--animation", argv[++k], 0, GLTF_ANIM_ONLY_MAX);
            if (n < 0) return 2;
            opts |= GLTF_ANIM_ONLY(n);
        }
        else if (argv[k][0] != '-' && !path) path = argv[k];
        else return -1;                            /* the caller reports it */
    }
    if (!path || !gltf_sniff(path))
        return opts && path ? (fprintf(stderr, "certbox: --from-vertices and --animated are for glTF files\n"), 2) : -1;
    gl_doc d;
    char err[600];
    if (gltf_load(&d, path, opts, stderr, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    cbx_status all = CBX_OK;
    if (json) printf("{\"scenes\": [\n");
    for (int s = 0; s < d.ns; s++) {
        const gl_scene *G = &d.scenes[s];
        if (json) printf("  {\"leaves\": [\n");
        for (int k = G->first; k < G->first + G->n; k++) {
            const gl_leaf *L = &d.leaves[k];
            if (json) {
                char *nn = name_json(&d, "nodes", L->node), *mn = name_json(&d, "meshes", L->mesh);
                printf("    {\"path\": \"%s\", \"node\": %d, \"node_name\": %s, \"mesh\": %d, \"mesh_name\": %s, "
                       "\"primitive\": %d, \"accessor\": %d, ",
                       L->path, L->node, nn ? nn : "null", L->mesh, mn ? mn : "null", L->prim, L->acc);
                free(nn);
                free(mn);
                tool_print_box(&L->world, hex, 1);
                printf(", \"status\": \"%s\"}%s\n", cbx_status_name(L->st), k + 1 < G->first + G->n ? "," : "");
            } else {
                printf("leaf %s mesh:%d:%d ", L->path, L->mesh, L->prim);
                tool_print_box(&L->world, hex, 0);
                printf(" %s\n", cbx_status_name(L->st));
            }
        }
        if (json) {
            printf("  ], \"scene\": %d, ", s);
            tool_print_box(&G->world, hex, 1);
            printf(", \"status\": \"%s\"}%s\n", cbx_status_name(G->st), s + 1 < d.ns ? "," : "");
        } else {
            printf("scene ");
            tool_print_box(&G->world, hex, 0);
            printf(" %s\n", cbx_status_name(G->st));
        }
        worse(&all, G->st);
    }
    if (json) printf("]}\n");
    int rc = all == CBX_OK && d.notes == 0 ? 0 : 1;
    if (all != CBX_OK)
        fprintf(stderr, "certbox: some bound is not proven (status %s): see the leaves above\n", cbx_status_name(all));
    if (d.notes)
        fprintf(stderr, "certbox: %d note%s on the file's own claims or unsupported features: see above\n",
                d.notes, d.notes == 1 ? "" : "s");
    gltf_free(&d);
    return rc;
}
#endif /* CBX_GLTF */
