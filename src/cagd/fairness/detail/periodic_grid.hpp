#pragma once
// Cells of an equally spaced periodic grid of tangent angles (the pseudo-energy tables' axes),
// inline: every table lookup of eq (12) starts here.
#include <algorithm>
#include <numbers>
#include <utility>
#include <vector>

namespace cagd::fairness::detail {

// The node after node i of n around the period (i in [0, n)): a comparison, not a modulo (an
// integer division, on every lookup).
inline int next_node(int i, int n) { return i + 1 == n ? 0 : i + 1; }

// An equally spaced periodic axis of angle nodes (first node x0, spacing h; the period 2π closes it)
// with 1/h kept: what every lookup's cell search needs, computed once.
struct PeriodicAxis {
    std::vector<double> nodes;
    double inv_h = 0.0;

    PeriodicAxis() = default;
    explicit PeriodicAxis(std::vector<double> x)
        : nodes(std::move(x)), inv_h(nodes.size() > 1 ? 1.0 / (nodes[1] - nodes[0]) : 0.0) {}

    // Cell of `theta`: i = the last node ≤ theta (wrapping to the last cell for theta beyond the
    // last node) and the fraction u ∈ [0, 1] across the cell, toward node next_node(i, n) (2π added
    // to it when it wraps).
    void locate(double theta, int& i, double& u) const {
        const int n = static_cast<int>(nodes.size());
        const double x0 = nodes.front();
        if (theta < x0) theta += 2 * std::numbers::pi;
        i = std::clamp(static_cast<int>((theta - x0) * inv_h), 0, n - 1);  // a guess; the tests make it exact
        if (i + 1 < n && nodes[static_cast<std::size_t>(i + 1)] <= theta)
            ++i;
        else if (i > 0 && nodes[static_cast<std::size_t>(i)] > theta)
            --i;
        const double left = nodes[static_cast<std::size_t>(i)];
        const double right = i + 1 < n ? nodes[static_cast<std::size_t>(i + 1)] : x0 + 2 * std::numbers::pi;
        u = std::clamp((theta - left) / (right - left), 0.0, 1.0);
    }
};

}  // namespace cagd::fairness::detail
