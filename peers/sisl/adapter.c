/* SISL as a CAD kernel's users call it: s1356 interpolates the points (all of type 1, ordinary
 * points) by a cubic B-spline (order 4) over SISL's own chord-length parameterization, then s1730
 * converts it to Bézier form, whose segments are the exact pieces. Configurations: free (open: no
 * end condition; closed: SISL's closed curve, iopen = 0), natural (open: zero curvature at both ends),
 * periodic (closed: iopen = -1). AGPL, like SISL: a program of its own, never linked into the
 * library or the command. Protocol: peers/protocol.mjs (docs/peers.md). */
#include <sisl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../protocol.h"

static void answer(const char* configuration, int closed, int n, int d, double* p) {
    int natural = strcmp(configuration, "natural") == 0, periodic = strcmp(configuration, "periodic") == 0;
    if (!natural && !periodic && strcmp(configuration, "free") != 0) {
        printf("{\"error\":\"unknown configuration; sisl has free, natural, periodic\"}\n");
        return;
    }
    if ((natural && closed) || (periodic && !closed)) {
        printf("{\"error\":\"sisl's %s is for %s curves only\"}\n", configuration, natural ? "open" : "closed");
        return;
    }
    int* types = malloc(sizeof(int) * (size_t)n);
    for (int i = 0; i < n; ++i) types[i] = 1;
    double end_parameter = 0, *parameters = NULL;
    SISLCurve *curve = NULL, *bezier = NULL;
    int unique = 0, status = 0;
    const int iopen = !closed ? 1 : periodic ? -1 : 0;
    s1356(p, n, d, types, natural, natural, iopen, 4, 0.0, &end_parameter, &curve, &parameters, &unique, &status);
    if (status >= 0 && curve) s1730(curve, &bezier, &status);
    if (status < 0 || !bezier) {
        printf("{\"error\":\"SISL s1356/s1730 status %d\"}\n", status);
    } else {
        print_document_head("sisl", SISL_VERSION, configuration, closed, "chord length (SISL's)", p, n, d);
        /* Bézier form: order-4 knots of multiplicity 4, segment j's coefficients 4j … 4j + 3. A
         * periodic curve may start at another point than the first: its segments are rotated to
         * start at the segment nearest the first point, the wrapped breaks shifted by the period. */
        const int segments = bezier->in / 4;
        int first = 0;
        double nearest = -1;
        for (int j = 0; j < segments; ++j) {
            double s = 0;
            for (int k = 0; k < d; ++k) s += (bezier->ecoef[4 * j * d + k] - p[k]) * (bezier->ecoef[4 * j * d + k] - p[k]);
            if (nearest < 0 || s < nearest) nearest = s, first = j;
        }
        const double period = bezier->et[4 * segments + 3] - bezier->et[3];
        for (int i = 0; i < segments; ++i)
            printf(i ? ",%.17g" : "%.17g", bezier->et[4 * ((first + i) % segments) + 3] + (first + i >= segments ? period : 0));
        printf(",%.17g", bezier->et[4 * first + 3] + period);
        printf("],\"pieces\":[");
        for (int i = 0; i < segments; ++i) {
            const int j = (first + i) % segments;
            printf(i ? ",[" : "[");
            for (int c = 0; c < 4; ++c) {
                if (c) putchar(',');
                print_point(bezier->ecoef + (size_t)(4 * j + c) * (size_t)d, d);
            }
            putchar(']');
        }
        printf("]}\n");
    }
    if (curve) freeCurve(curve);
    if (bezier) freeCurve(bezier);
    free(parameters);
    free(types);
}

int main(int argc, char** argv) {
    return serve(argc, argv, "sisl", SISL_VERSION, answer);
}
