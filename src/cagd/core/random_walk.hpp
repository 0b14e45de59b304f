#pragma once
/// @file
/// Seeded random planar walks: test and benchmark data of any length, the same points for the same
/// seed on every platform (std::mt19937 and std::uniform_real_distribution over libstdc++).
/// random_walk(n, seed, min_len, max_len, max_turn): n points starting at the origin heading along
/// +x; each step turns by an angle drawn uniformly from [-max_turn, max_turn] radians (below π: no
/// hairpins) and then walks a chord of length drawn uniformly from [min_len, max_len].
#include <cmath>
#include <random>

#include "cagd/core/points.hpp"

namespace cagd {

/// n points of a seeded random walk (see above): chords in [min_len, max_len], turns within ±max_turn.
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

}  // namespace cagd
