/*
 * certbox: world-space bounds of every leaf of a scene file, and of the
 * whole scene (format: examples/scene-format.md).
 *   certbox [--json] [--hex] FILE
 *   certbox [--json] [--hex] [--from-vertices] FILE.gltf|FILE.glb  (gltf.c)
 * Exit status: 0 every bound proven (CBX_OK); 1 some leaf's status is not
 * CBX_OK (printed as such, with a note on stderr); 2 bad usage or a bad
 * file (FILE:LINE: message on stderr, nothing on stdout).
 */
#include <stdio.h>
#include <string.h>
#include "scene.h"
#include "gltf.h"


int main(int argc, char **argv)
{
    int g = gltf_main(argc, argv);     /* glTF content: its own reader */
    if (g >= 0)
        return g;
    int json = 0, hex = 0;
    const char *path = NULL;
    for (int k = 1; k < argc; k++) {
        if (strcmp(argv[k], "--json") == 0) json = 1;
        else if (strcmp(argv[k], "--hex") == 0) hex = 1;
        else if (!path && argv[k][0] != '-') path = argv[k];
        else { path = NULL; break; }
    }
    if (!path) {
        fprintf(stderr, "usage: certbox [--json] [--hex] [--from-vertices] FILE\n");
        return 2;
    }
    scene s;
    char err[512];
    if (scene_load(&s, path, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    scene_eval(&s);
    if (json) printf("{\"leaves\": [\n");
    for (int k = 0; k < s.nl; k++) {
        const sc_leaf *L = &s.leaves[k];
        if (json) {
            printf("  {\"name\": \"%s\", \"kind\": \"%s\", ", L->name, scene_kind_name(L->kind));
            tool_print_box(&L->world, hex, 1);
            printf(", \"status\": \"%s\"}%s\n", cbx_status_name(L->st), k + 1 < s.nl ? "," : "");
        } else {
            printf("leaf %s %s ", L->name, scene_kind_name(L->kind));
            tool_print_box(&L->world, hex, 0);
            printf(" %s\n", cbx_status_name(L->st));
        }
    }
    if (json) {
        printf("], \"scene\": {");
        tool_print_box(&s.world, hex, 1);
        printf(", \"status\": \"%s\"}}\n", cbx_status_name(s.st));
    } else {
        printf("scene ");
        tool_print_box(&s.world, hex, 0);
        printf(" %s\n", cbx_status_name(s.st));
    }
    int rc = s.st == CBX_OK ? 0 : 1;
    if (rc)
        fprintf(stderr, "certbox: some bound is not proven (status %s): see the leaves above\n",
                cbx_status_name(s.st));
    scene_free(&s);
    return rc;
}
