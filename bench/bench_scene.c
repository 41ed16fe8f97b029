/*
 * The scene tool on big scenes (issue 18): time and peak memory of
 * `certbox FILE > /dev/null` on generated scenes of N nodes and L leaves.
 *   bench_scene [-nodes N] [-leaves L] [-tool PATH] [-o DIR]
 * Writes each scene to DIR (build/..., never to git), runs the tool once per
 * scene in a child process (wall time from CLOCK_MONOTONIC; user and system
 * time and peak resident memory ru_maxrss from wait4), prints a table with
 * the machine and the date, and writes it to DIR/scene.md.  Exit 1 when the
 * tool fails on a scene.
 * Scenes:
 *   chain      N nodes, each `translate 1 0 0` under the one before; L boxes
 *              on the deepest node (issue 18's case: work was L x N)
 *   chain-rot  the same with one `matrix` per node (a rotation by 0.001
 *              degrees about z and a translation), spheres: general matrices
 *   tree       N nodes, each under a random earlier node (depth about ln N),
 *              mixed operations and a motion node now and then; L leaves
 *              (boxes, spheres, ellipsoids) on random nodes
 */
#define _DEFAULT_SOURCE 1
#include <fcntl.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#ifndef BENCH_FLAGS
#define BENCH_FLAGS "(unknown)"
#endif

static uint64_t rng_state = 0x9e3779b97f4a7c15u;
static uint64_t rnd(void)       /* xorshift64* */
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return rng_state * 2685821657736338717u;
}
static long rnd_below(long n) { return (long)(rnd() % (uint64_t)n); }
static double rnd_unit(void) { return (double)(rnd() >> 11) * 0x1p-53; }

static int gen(const char *path, const char *kind, long nodes, long leaves)
{
    FILE *f = fopen(path, "w");
    if (!f) { perror(path); return -1; }
    fprintf(f, "certbox-scene 1\n# bench_scene %s: %ld nodes, %ld leaves\n", kind, nodes, leaves);
    if (strcmp(kind, "tree") != 0) {
        int rot = strcmp(kind, "chain-rot") == 0;
        double c = cos(0.001 * 3.14159265358979323846 / 180), sn = sin(0.001 * 3.14159265358979323846 / 180);
        for (long i = 0; i < nodes; i++) {
            if (i == 0) fprintf(f, "node n0\n");
            else fprintf(f, "node n%ld n%ld\n", i, i - 1);
            if (rot)    /* one operation per node (the format allows 10^6 in all) */
                fprintf(f, "  matrix %.17g %.17g 0 0.5  %.17g %.17g 0 0  0 0 1 0\n", c, -sn, sn, c);
            else
                fprintf(f, "  translate 1 0 0\n");
        }
        for (long k = 0; k < leaves; k++) {
            if (rot) fprintf(f, "sphere l%ld n%ld %ld 0 0 0.5\n", k, nodes - 1, k % 1000);
            else fprintf(f, "box l%ld n%ld %ld 0 0 %ld 1 1\n", k, nodes - 1, k, k + 1);
        }
    } else {
        for (long i = 0; i < nodes; i++) {
            if (i == 0) fprintf(f, "node n0\n");
            else fprintf(f, "node n%ld n%ld\n", i, rnd_below(i));
            /* 0.875 operations per node on average: 10^6 nodes stay within
             * the format's 10^6 operations */
            switch (rnd_below(8)) {
            case 0: fprintf(f, "  translate %.6f 0 1\n  motion\n  translate %.6f 1 1\n", rnd_unit(), rnd_unit()); break;
            case 1: case 2: break;      /* a group node */
            case 3: fprintf(f, "  rotate 0 0 1 90\n"); break;
            case 4: fprintf(f, "  scale 0.5 2 1\n"); break;
            case 5: fprintf(f, "  rotate 1 1 0 %.3f\n", 360 * rnd_unit()); break;
            default: fprintf(f, "  translate %.6f %.6f 0\n", rnd_unit(), rnd_unit());
            }
        }
        for (long k = 0; k < leaves; k++) {
            long n = rnd_below(nodes);
            switch (rnd_below(3)) {
            case 0: fprintf(f, "box l%ld n%ld 0 0 0 1 2 3\n", k, n); break;
            case 1: fprintf(f, "sphere l%ld n%ld 0.5 0 0 0.25\n", k, n); break;
            default: fprintf(f, "ellipsoid l%ld n%ld 0 0 0 1 2 0.5 0.6 -0.8 0 0.8 0.6 0 0 0 1\n", k, n);
            }
        }
    }
    if (fclose(f) != 0) { perror(path); return -1; }
    return 0;
}

typedef struct run { double wall, user, sys; long maxrss_kb; int status; } run;

static int run_tool(const char *tool, const char *scene, run *r)
{
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    pid_t pid = fork();
    if (pid < 0) { perror("fork"); return -1; }
    if (pid == 0) {
        int fd = open("/dev/null", O_WRONLY);
        if (fd >= 0) dup2(fd, 1);
        execl(tool, tool, scene, (char *)NULL);
        _exit(127);
    }
    int st;
    struct rusage ru;
    if (wait4(pid, &st, 0, &ru) != pid) { perror("wait4"); return -1; }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    r->wall = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    r->user = (double)ru.ru_utime.tv_sec + 1e-6 * (double)ru.ru_utime.tv_usec;
    r->sys = (double)ru.ru_stime.tv_sec + 1e-6 * (double)ru.ru_stime.tv_usec;
    r->maxrss_kb = ru.ru_maxrss;        /* Linux: kilobytes */
    r->status = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + (WIFSIGNALED(st) ? WTERMSIG(st) : 0);
    return 0;
}

static void machine(char *model, size_t n, int *cores)
{
    snprintf(model, n, "(unknown)");
    *cores = 0;
    FILE *f = fopen("/proc/cpuinfo", "r");
    char line[512];
    while (f && fgets(line, sizeof line, f)) {
        if (strncmp(line, "model name", 10) == 0) {
            char *c = strchr(line, ':');
            if (c && *cores == 0) {
                c += 1 + (c[1] == ' ');
                c[strcspn(c, "\n")] = '\0';
                snprintf(model, n, "%s", c);
            }
            (*cores)++;
        }
    }
    if (f) fclose(f);
}

int main(int argc, char **argv)
{
    long nodes = 1000000, leaves = 1000000;
    const char *tool = "build/certbox", *dir = "build/bench-out";
    for (int k = 1; k + 1 < argc; k += 2) {
        if (strcmp(argv[k], "-nodes") == 0) nodes = atol(argv[k + 1]);
        else if (strcmp(argv[k], "-leaves") == 0) leaves = atol(argv[k + 1]);
        else if (strcmp(argv[k], "-tool") == 0) tool = argv[k + 1];
        else if (strcmp(argv[k], "-o") == 0) dir = argv[k + 1];
        else { fprintf(stderr, "usage: bench_scene [-nodes N] [-leaves L] [-tool PATH] [-o DIR]\n"); return 2; }
    }
    if (nodes < 1 || leaves < 1) { fprintf(stderr, "bench_scene: N and L must be positive\n"); return 2; }
    mkdir(dir, 0777);
    char model[256], when[64], out[1024];
    int cores;
    machine(model, sizeof model, &cores);
    time_t tt = time(NULL);
    strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S UTC", gmtime(&tt));
    snprintf(out, sizeof out, "%s/scene.md", dir);
    FILE *md = fopen(out, "w");
    if (!md) { perror(out); return 2; }
    char head[2048];
    snprintf(head, sizeof head,
             "# The scene tool on big scenes (bench/bench_scene.c)\n\n"
             "machine: %s, %d cores; date: %s\n"
             "tool: %s (%s), output to /dev/null; time and peak memory of the whole run "
             "(reading, parsing, evaluating, printing)\n\n"
             "| scene | nodes | leaves | file MB | wall s | user s | sys s | peak RSS MB | exit |\n"
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n",
             model, cores, when, tool, BENCH_FLAGS);
    fputs(head, stdout);
    fputs(head, md);
    static const char *kinds[] = {"chain", "chain-rot", "tree"};
    int bad = 0;
    for (int k = 0; k < 3; k++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/scene-%s-%ld-%ld.scene", dir, kinds[k], nodes, leaves);
        if (gen(path, kinds[k], nodes, leaves) != 0) { bad = 1; continue; }
        struct stat sb;
        double mb = stat(path, &sb) == 0 ? (double)sb.st_size / 1e6 : 0;
        run r;
        if (run_tool(tool, path, &r) != 0) { bad = 1; continue; }
        char row[512];
        snprintf(row, sizeof row, "| %s | %ld | %ld | %.1f | %.2f | %.2f | %.2f | %.0f | %d |\n", kinds[k], nodes,
                 leaves, mb, r.wall, r.user, r.sys, (double)r.maxrss_kb / 1024.0, r.status);
        fputs(row, stdout);
        fputs(row, md);
        fflush(stdout);
        if (r.status != 0) bad = 1;
        remove(path);       /* hundreds of MB: not kept */
    }
    fclose(md);
    printf("bench_scene: %s (wrote %s)\n", bad ? "FAILED (the tool failed on some scene)" : "passed", out);
    return bad;
}
