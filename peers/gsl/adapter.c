/* GSL as its users call it: gsl_spline per coordinate over chord length, one spline per coordinate
 * x(t), y(t)[, z(t)] with t the accumulated chord length. Each span is a cubic in t, so its value
 * and derivative at both ends (gsl_spline_eval, gsl_spline_eval_deriv) give its Bézier points
 * exactly up to rounding. Configurations: cspline (natural ends; closed: cspline_periodic), akima
 * (closed: akima_periodic), steffen (open only). GPL, like GSL: a program of its own, never linked
 * into the library or the command. Protocol: peers/protocol.mjs (docs/peers.md). */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_spline.h>
#include <gsl/gsl_version.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../protocol.h"

static void error_line(const char* message) {
    printf("{\"error\":\"%s\"}\n", message);
}

/* The curve through the n points p (n × d, row-major), open or closed. */
static void answer(const char* configuration, int closed, int n, int d, double* p) {
    const gsl_interp_type* type = NULL;
    if (strcmp(configuration, "cspline") == 0) type = closed ? gsl_interp_cspline_periodic : gsl_interp_cspline;
    else if (strcmp(configuration, "akima") == 0) type = closed ? gsl_interp_akima_periodic : gsl_interp_akima;
    else if (strcmp(configuration, "steffen") == 0) type = closed ? NULL : gsl_interp_steffen;
    else {
        error_line("unknown configuration; gsl has cspline, akima, steffen");
        return;
    }
    if (!type) {
        error_line("GSL has no periodic steffen spline");
        return;
    }
    const int m = closed ? n + 1 : n; /* a closed curve repeats its first point */
    double* t = malloc(sizeof(double) * (size_t)m);
    double* v = malloc(sizeof(double) * (size_t)m * (size_t)d);
    for (int i = 0; i < m; ++i)
        for (int k = 0; k < d; ++k) v[k * m + i] = p[(i % n) * d + k];
    t[0] = 0;
    for (int i = 1; i < m; ++i) {
        double s = 0;
        for (int k = 0; k < d; ++k) s += (v[k * m + i] - v[k * m + i - 1]) * (v[k * m + i] - v[k * m + i - 1]);
        t[i] = t[i - 1] + sqrt(s);
    }
    if ((unsigned)m < gsl_interp_type_min_size(type)) {
        char message[96];
        snprintf(message, sizeof message, "GSL's %s needs at least %u points", type->name,
                 gsl_interp_type_min_size(type) - (closed ? 1u : 0u));
        error_line(message);
        free(t), free(v);
        return;
    }
    gsl_spline* spline[3] = {NULL, NULL, NULL};
    gsl_interp_accel* accel = gsl_interp_accel_alloc();
    int status = 0;
    for (int k = 0; k < d && !status; ++k) {
        spline[k] = gsl_spline_alloc(type, (size_t)m);
        status = gsl_spline_init(spline[k], t, v + (size_t)k * (size_t)m, (size_t)m);
    }
    if (status) {
        char message[160];
        snprintf(message, sizeof message, "gsl_spline_init: %s", gsl_strerror(status));
        error_line(message);
    } else {
        print_document_head("gsl", GSL_VERSION, configuration, closed, "chord length", p, n, d);
        for (int i = 0; i < m; ++i) printf(i ? ",%.17g" : "%.17g", t[i]);
        printf("],\"pieces\":[");
        for (int i = 0; i + 1 < m; ++i) {
            const double h = t[i + 1] - t[i];
            double c[4][3];
            for (int k = 0; k < d; ++k) {
                /* Values and slopes at the span's ends, each from this span's side. */
                const double a = v[k * m + i], b = v[k * m + i + 1];
                const double da = gsl_spline_eval_deriv(spline[k], t[i], accel);
                const double db = gsl_spline_eval_deriv(spline[k], t[i + 1], accel);
                c[0][k] = a, c[1][k] = a + h * da / 3, c[2][k] = b - h * db / 3, c[3][k] = b;
            }
            printf(i ? ",[" : "[");
            for (int j = 0; j < 4; ++j) {
                if (j) putchar(',');
                print_point(c[j], d);
            }
            putchar(']');
        }
        printf("]}\n");
    }
    for (int k = 0; k < d; ++k) gsl_spline_free(spline[k]);
    gsl_interp_accel_free(accel);
    free(t), free(v);
}

int main(int argc, char** argv) {
    gsl_set_error_handler_off();
    return serve(argc, argv, "gsl", GSL_VERSION, answer);
}
