#pragma once
// Seeded random planar walks for the benchmarks: chords of length in [min_len, max_len], heading
// changing by at most max_turn radians per step (below π: no hairpins).
#include <cmath>
#include <random>

#include "cagd/core/points.hpp"

namespace cagd::bench {

inline PointList random_walk(long n, unsigned seed, double min_len, double max_len, double max_turn) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> len(min_len, max_len), turn(-max_turn, max_turn);
    PointList p(n, 2);
    p.row(0) << 0, 0;
    double heading = 0;
    for (long i = 1; i < n; ++i) {
        heading += turn(rng);
        const double l = len(rng);
        p.row(i) << p(i - 1, 0) + l * std::cos(heading), p(i - 1, 1) + l * std::sin(heading);
    }
    return p;
}

}  // namespace cagd::bench
