/* The peer protocol (docs/peers.md) for the adapters written in C: serve() reads the requests on
 * standard input (a line `curve CONFIGURATION open|closed N D`, then N lines of D coordinates) and
 * calls answer() for each, which prints one line on standard output: a curve document of the
 * peer's own pieces or {"error": "..."}. `--version` prints the peer's name and version. */
#ifndef CAGD_PEER_PROTOCOL_H
#define CAGD_PEER_PROTOCOL_H
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* One answer: the n points p (n × d, row by row) as configuration asks, open or closed. */
typedef void (*peer_answer)(const char* configuration, int closed, int n, int d, double* p);

/* Prints a point [x, y(, z)] at 17 significant digits (read back bit for bit). */
static void print_point(const double* p, int d) {
    putchar('[');
    for (int k = 0; k < d; ++k) printf(k ? ",%.17g" : "%.17g", p[k]);
    putchar(']');
}

/* Prints the points as the document's "points" member's value. */
static void print_points(const double* p, int n, int d) {
    putchar('[');
    for (int i = 0; i < n; ++i) {
        if (i) putchar(',');
        print_point(p + (size_t)i * (size_t)d, d);
    }
    putchar(']');
}

/* Prints a curve document up to its breaks' opening bracket: the members before them, the peer's
 * `name` and `version`, the configuration, what the parameter is, the points, degree 3. */
static void print_document_head(const char* name, const char* version, const char* configuration, int closed,
                                const char* parameter, const double* p, int n, int d) {
    printf("{\"format\":\"cagd-curve\",\"format_version\":1,\"library_version\":\"%s\",\"registry\":\"\","
           "\"method\":{\"closed\":%s,\"name\":\"%s:%s\",\"parameter\":\"%s\",\"parameters\":{}},\"points\":",
           version, closed ? "true" : "false", name, configuration, parameter);
    print_points(p, n, d);
    printf(",\"dimension\":%d,\"degree\":3,\"exact\":true,\"max_distance\":0,\"tolerance\":0,\"breaks\":[", d);
}

/* The adapter's main: `name version` for --version, else every request answered; 2 for a request
 * that breaks the protocol, 1 when standard output fails. */
static int serve(int argc, char** argv, const char* name, const char* version, peer_answer answer) {
    if (argc > 1 && strcmp(argv[1], "--version") == 0) {
        printf("%s %s\n", name, version);
        return 0;
    }
    char configuration[64], closedness[16];
    int n = 0, d = 0;
    while (scanf(" curve %63s %15s %d %d", configuration, closedness, &n, &d) == 4) {
        if (n < 1 || n > 10000000 || d < 2 || d > 3) {
            fprintf(stderr, "%s adapter: a request of %d points of dimension %d\n", name, n, d);
            return 2;
        }
        double* p = malloc(sizeof(double) * (size_t)n * (size_t)d);
        for (int i = 0; i < n * d; ++i)
            if (scanf("%lf", &p[i]) != 1) {
                fprintf(stderr, "%s adapter: a request ends before its %d points\n", name, n);
                free(p);
                return 2;
            }
        answer(configuration, strcmp(closedness, "closed") == 0, n, d, p);
        free(p);
    }
    return ferror(stdout) || fflush(stdout) ? 1 : 0;
}

#endif
