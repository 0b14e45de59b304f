#pragma once
/// @file
/// How far a curve's data spans move when its points move: the locality footprint of `cagd compare`
/// (method_comparison.hpp) and the viewer's shading of a drag. Two interpolants of the same method
/// on the same number of points (one with a point moved) are compared span by span, at the same
/// fractions of each span's parameter interval.
#include <cstddef>
#include <vector>

#include <Eigen/Dense>

#include "cagd/methods/method_registry.hpp"

namespace cagd::compare {

using methods::Interpolant;

/// The parameter at fraction f ∈ [0, 1] of data span k of `a`: u_k + f (u_{k+1} − u_k).
double span_parameter(const Interpolant& a, std::size_t k, double f);
/// How far each data span of `a` moved in `b` (the same method on the same points but some moved):
/// per span k, the largest distance between the two curves at the same fraction of the span's
/// parameter interval, over `samples_per_span` + 1 equally spaced fractions (the ends included).
/// The locality footprint counts the spans whose distance exceeds its tolerance; the viewer shades
/// every span by it. InvalidInput unless both have the same number of spans and samples_per_span ≥ 1.
std::vector<double> span_displacements(const Interpolant& a, const Interpolant& b, int samples_per_span = 8);
/// The positions span_displacements compares: per data span k, the curve at samples_per_span + 1
/// equally spaced fractions j / samples_per_span of the span's parameter interval, in row
/// k·(samples_per_span + 1) + j. Kept, they let one curve be compared with many (the viewer's
/// anchor of a drag with every frame). InvalidInput unless samples_per_span ≥ 1.
Eigen::MatrixXd span_samples(const Interpolant& a, int samples_per_span = 8);
/// span_displacements from two curves' span_samples taken with the same samples_per_span: per span,
/// the largest distance between corresponding rows. InvalidInput unless both have the same shape, a
/// whole number of spans of samples_per_span + 1 rows.
std::vector<double> span_displacements(const Eigen::MatrixXd& a_samples, const Eigen::MatrixXd& b_samples,
                                       int samples_per_span);
/// The locality footprint: how many data spans of `a` and `b` (the same method, the same number of
/// points, one moved) moved by more than `tolerance` — span_displacements at 8 samples per span
/// counted, without sampling the spans that cannot have moved (a local method's unchanged spans,
/// found from equal data; the curvature profile's by its offset bound).
int spans_moved(const Interpolant& a, const Interpolant& b, double tolerance);

}  // namespace cagd::compare
