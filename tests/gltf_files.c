/*
 * gltf_files.c: part of tests/test_gltf.c (gltf_parts.h): the files and
 * their expectations: DATA_DIR/expect.txt read, and every .gltf / .glb
 * under a folder found, recursively.
 */
#define _XOPEN_SOURCE 700
/* 64-bit file offsets and inode numbers on 32-bit hosts too: without
 * it, readdir / stat fail with EOVERFLOW on file systems with large inode
 * numbers (armhf under qemu-user, scripts/cross.sh) */
#define _FILE_OFFSET_BITS 64
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "gltf_parts.h"

int glt_read_expect(const char *path, expect **out)
{
    FILE *f = fopen(path, "r");
    if (!f) { fprintf(stderr, "cannot open %s\n", path); exit(2); }
    char line[1024];
    int n = 0, cap = 0;
    expect *e = NULL;
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\n")] = '\0';
        if (line[0] == '#' || line[0] == '\0') continue;
        if (n == cap) { cap = cap ? 2 * cap : 64; e = realloc(e, (size_t)cap * sizeof *e); if (!e) exit(2); }
        memset(&e[n], 0, sizeof e[n]);
        int pos = 0;
        if (sscanf(line, "%511s %7s %n", e[n].file, e[n].kind, &pos) < 2) { fprintf(stderr, "bad line: %s\n", line); exit(2); }
        snprintf(e[n].sub, sizeof e[n].sub, "%s", line + pos);
        n++;
    }
    fclose(f);
    *out = e;
    return n;
}

int glt_cmpstr(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

void glt_find_files(const char *dir, char ***list, int *n, int *cap)
{
    DIR *D = opendir(dir);
    struct dirent *e;
    if (!D) return;
    while ((e = readdir(D)) != NULL) {
        if (e->d_name[0] == '.') continue;
        char p[1024];
        struct stat sb;
        snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
        if (stat(p, &sb) != 0) continue;
        if (S_ISDIR(sb.st_mode)) { glt_find_files(p, list, n, cap); continue; }
        size_t len = strlen(p);
        if (!(len > 5 && strcmp(p + len - 5, ".gltf") == 0) && !(len > 4 && strcmp(p + len - 4, ".glb") == 0)) continue;
        if (*n == *cap) { *cap = *cap ? 2 * *cap : 64; *list = realloc(*list, (size_t)*cap * sizeof **list); if (!*list) exit(2); }
        (*list)[(*n)++] = strdup(p);
    }
    closedir(D);
}
