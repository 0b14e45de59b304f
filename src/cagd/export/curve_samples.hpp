#pragma once
/// @file
/// The CSV of samples of a curve (`cagd interpolate`'s historical output): a header
///     t, x, y[, z], dx, dy[, dz], ddx, ddy[, ddz]
/// (the parameter column is named by the caller: t, the method's own, or u, the span index), then
/// one row per sample with the position and the first and second derivatives with respect to that
/// parameter, 15 significant digits. Samples: `per_piece` equal parameter steps on every piece
/// between consecutive breakpoints, and the end; or, with arc_length_samples = N ≥ 2, N samples
/// at equal arc length from the start to the end (analysis/arc_length_parameter.hpp: each within
/// about 1e-12 of the length of its target).
/// Outcome not_representable, naming the column and row, when a value is not finite (the caller
/// then publishes nothing). InvalidInput for more than max_rows rows, checked before any work.
#include <ostream>
#include <string>

#include "cagd/core/curve.hpp"
#include "cagd/core/errors.hpp"

namespace cagd::exports {

/// How a curve is sampled into CSV (see above).
struct SampleOptions {
    int per_piece = 16;                  ///< samples per piece, ≥ 1 (equal parameter steps)
    int arc_length_samples = 0;          ///< N ≥ 2: N samples at equal arc length instead; 0: off
    std::string parameter_column = "t";  ///< the name of the parameter column
    long max_rows = 10'000'000;          ///< the most rows written
};

/// Writes the sample CSV of `curve` (see above).
Outcome write_curve_samples(std::ostream& out, const Curve& curve, const SampleOptions& options);

}  // namespace cagd::exports
