/*
 * The scene tool's one file reader, shared by its two formats (scene.c,
 * gltf.c): the whole file into one malloc'd buffer, with one spare byte
 * after the data (a text reader puts its NUL there).  At most 1 GB.
 */
#ifndef CBX_TOOL_READALL_H
#define CBX_TOOL_READALL_H

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>

/* 0: *out holds the *n bytes of the file (and room for one more);
 * -1: it cannot be opened (errno from fopen); -2: a read error (errno
 * EIO) or the file is above 1 GB or memory ran out (errno EFBIG).  On
 * failure *out is NULL and *n is 0. */
static inline int tool_read_all(const char *path, unsigned char **out, size_t *n)
{
    FILE *f = fopen(path, "rb");
    *out = NULL;
    *n = 0;
    if (!f)
        return -1;
    size_t cap = 1 << 16, len = 0, r;
    unsigned char *b = malloc(cap + 1);
    while (b && (r = fread(b + len, 1, cap - len, f)) > 0) {
        len += r;
        if (len == cap) {
            unsigned char *b2 = cap < ((size_t)1 << 30) ? realloc(b, 2 * cap + 1) : NULL;
            if (!b2) { free(b); b = NULL; errno = EFBIG; break; }
            b = b2;
            cap *= 2;
        }
    }
    int bad = ferror(f);
    fclose(f);
    if (!b || bad) {
        free(b);
        if (bad) errno = EIO;
        return -2;
    }
    *out = b;
    *n = len;
    return 0;
}

#endif /* CBX_TOOL_READALL_H */
