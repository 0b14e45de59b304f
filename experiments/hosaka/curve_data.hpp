#pragma once
// The point sets we chose for hosaka section 3 (the paper prints none), shared by the
// experiments c2_spline and higher_order:
//   uneven  six planar points whose chords range from 0.21 to 2.0 (k_i of eq 19 from 0.11 to 6.0)
//   even    seven points of y = sin x at x = 0..6 (k_i near 1)
#include <cmath>

#include "cagd/core/points.hpp"

namespace cagd::hosaka_data {

inline PointList uneven_points() {
    PointList p(6, 2);
    p << 0, 0, 1, 0.8, 1.15, 0.95, 3.0, 1.2, 3.2, 0.9, 5.0, 0.0;
    return p;
}

inline PointList even_points() {
    PointList p(7, 2);
    for (int i = 0; i < 7; ++i) p.row(i) << i, std::sin(double(i));
    return p;
}

}  // namespace cagd::hosaka_data
