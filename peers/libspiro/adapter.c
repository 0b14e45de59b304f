/* libspiro as FontForge and Inkscape call it: SpiroCPsToBezier0 on the points, each a G4 point
 * ('o'), an open curve starting with '{' and ending with '}' (its ends take κ' = κ'' = 0), with a
 * Bézier context that records the pieces libspiro emits: its own cubic approximation of Levien's
 * spiro, several pieces per span (a line or quadratic piece raised to a cubic exactly). Those pieces
 * are what libspiro's users draw; they are not one per span. Configuration: spiro. Planar points
 * only. GPL, like libspiro: a program of its own, never linked into the library or the command.
 * Protocol: peers/protocol.h (docs/peers.md). */
#include <bezctx.h>
#include <spiroentrypoints.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../protocol.h"

/* The pieces libspiro emits, each four points (x, y). */
typedef struct {
    bezctx base;
    double x, y;      /* the current point */
    double* pieces;   /* 8 numbers a piece */
    int count, capacity;
} recorder;

static void add_piece(recorder* r, double x1, double y1, double x2, double y2, double x3, double y3) {
    if (r->count == r->capacity) {
        r->capacity = r->capacity ? 2 * r->capacity : 64;
        r->pieces = realloc(r->pieces, sizeof(double) * 8 * (size_t)r->capacity);
    }
    double* p = r->pieces + 8 * (size_t)r->count++;
    p[0] = r->x, p[1] = r->y, p[2] = x1, p[3] = y1, p[4] = x2, p[5] = y2, p[6] = x3, p[7] = y3;
    r->x = x3, r->y = y3;
}
static void move_to(bezctx* bc, double x, double y, int is_open) {
    (void)is_open;
    ((recorder*)bc)->x = x, ((recorder*)bc)->y = y;
}
static void line_to(bezctx* bc, double x, double y) {
    recorder* r = (recorder*)bc;
    add_piece(r, r->x + (x - r->x) / 3, r->y + (y - r->y) / 3, r->x + 2 * (x - r->x) / 3, r->y + 2 * (y - r->y) / 3, x, y);
}
static void quad_to(bezctx* bc, double x1, double y1, double x2, double y2) {
    recorder* r = (recorder*)bc;
    add_piece(r, r->x + 2 * (x1 - r->x) / 3, r->y + 2 * (y1 - r->y) / 3, x2 + 2 * (x1 - x2) / 3, y2 + 2 * (y1 - y2) / 3, x2, y2);
}
static void curve_to(bezctx* bc, double x1, double y1, double x2, double y2, double x3, double y3) {
    add_piece((recorder*)bc, x1, y1, x2, y2, x3, y3);
}
static void mark_knot(bezctx* bc, int knot) {
    (void)bc, (void)knot;
}

static void answer(const char* configuration, int closed, int n, int d, double* p) {
    if (strcmp(configuration, "spiro") != 0) {
        printf("{\"error\":\"unknown configuration; libspiro has spiro\"}\n");
        return;
    }
    if (d != 2) {
        printf("{\"error\":\"libspiro draws planar points only\"}\n");
        return;
    }
    spiro_cp* points = malloc(sizeof(spiro_cp) * (size_t)n);
    for (int i = 0; i < n; ++i) {
        points[i].x = p[2 * i], points[i].y = p[2 * i + 1];
        points[i].ty = closed ? 'o' : i == 0 ? '{' : i == n - 1 ? '}' : 'o';
    }
    recorder r = {{move_to, line_to, quad_to, curve_to, mark_knot}, 0, 0, NULL, 0, 0};
    if (!SpiroCPsToBezier0(points, n, closed, &r.base) || r.count == 0) {
        printf("{\"error\":\"libspiro found no curve through these points\"}\n");
    } else {
        print_document_head("libspiro", LIBSPIRO_VERSION, configuration, closed, "piece index", p, n, d);
        for (int i = 0; i <= r.count; ++i) printf(i ? ",%d" : "%d", i);
        printf("],\"pieces\":[");
        for (int i = 0; i < r.count; ++i) {
            printf(i ? ",[" : "[");
            for (int c = 0; c < 4; ++c) {
                if (c) putchar(',');
                print_point(r.pieces + 8 * (size_t)i + 2 * (size_t)c, 2);
            }
            putchar(']');
        }
        printf("]}\n");
    }
    free(r.pieces);
    free(points);
}

int main(int argc, char** argv) {
    return serve(argc, argv, "libspiro", LIBSPIRO_VERSION, answer);
}
