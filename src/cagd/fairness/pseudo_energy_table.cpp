#include "cagd/fairness/pseudo_energy_table.hpp"

#include <unistd.h>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <thread>

#include "cagd/core/parallel.hpp"

namespace cagd::fairness {

namespace {

using detail::next_node;

}  // namespace

const char* to_string(NodePlacement p) {
    switch (p) {
        case NodePlacement::periodic: return "periodic";
        case NodePlacement::endpoints: return "endpoints";
        default: return "midpoints";
    }
}

NodePlacement parse_node_placement(const std::string& text) {
    if (text == "periodic") return NodePlacement::periodic;
    if (text == "endpoints") return NodePlacement::endpoints;
    if (text == "midpoints") return NodePlacement::midpoints;
    fail_input("cagd::fairness::parse_node_placement",
               "placement must be periodic, endpoints or midpoints, got '" + text + "'");
}

const char* to_string(TableMethod m) {
    switch (m) {
        case TableMethod::fast: return "fast";
        case TableMethod::reference: return "reference";
        default: return "nlopt";
    }
}

std::vector<double> AngleGrid::nodes() const {
    if (n < 2) fail_input("cagd::fairness::AngleGrid", "n must be >= 2, got " + std::to_string(n));
    std::vector<double> out(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
        double f = 0.0;  // fraction of the way from −π to π
        switch (placement) {
            case NodePlacement::periodic: f = 2.0 * k / n; break;
            case NodePlacement::endpoints: f = 2.0 * k / (n - 1); break;
            case NodePlacement::midpoints: f = (2.0 * k + 1.0) / n; break;
        }
        // π·(f − 1) is exactly 0 when f = 1 and exactly ∓π at the ends.
        out[static_cast<std::size_t>(k)] = std::numbers::pi * (f - 1.0);
    }
    return out;
}

PseudoEnergyTable PseudoEnergyTable::build(const AngleGrid& grid, TableMethod method, int threads, bool use_symmetry,
                                           const std::function<void(long, long)>& progress) {
    if (threads < 1)
        fail_input("cagd::fairness::PseudoEnergyTable::build", "threads must be >= 1, got " + std::to_string(threads));
    PseudoEnergyTable t;
    t.grid_ = grid;
    t.method_ = method;
    t.axis_ = detail::PeriodicAxis(grid.nodes());
    const int n = grid.n;
    t.values_.assign(static_cast<std::size_t>(n * n), PseudoEnergyMinimum{});
    // Index of the node at −θ (the placements are symmetric about 0; ±π map to themselves).
    std::vector<int> negate(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
        const double target = -t.axis_.nodes[static_cast<std::size_t>(k)];
        int best = 0;
        for (int m = 0; m < n; ++m)
            if (std::abs(std::remainder(t.axis_.nodes[static_cast<std::size_t>(m)] - target, 2 * std::numbers::pi)) <
                std::abs(std::remainder(t.axis_.nodes[static_cast<std::size_t>(best)] - target, 2 * std::numbers::pi)))
                best = m;
        negate[static_cast<std::size_t>(k)] = best;
    }
    // The orbit representative of (i, j): the smallest linear index among its images.
    const auto representative = [&](int i, int j) {
        const int ni = negate[static_cast<std::size_t>(i)], nj = negate[static_cast<std::size_t>(j)];
        return std::min({i * n + j, j * n + i, ni * n + nj, nj * n + ni});
    };
    std::vector<long> todo;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            if (!use_symmetry || representative(i, j) == i * n + j) todo.push_back(i * n + j);
    parallel_for(
        static_cast<long>(todo.size()), threads,
        [&](long k) {
            const long idx = todo[static_cast<std::size_t>(k)];
            const double a = t.axis_.nodes[static_cast<std::size_t>(idx / n)],
                         b = t.axis_.nodes[static_cast<std::size_t>(idx % n)];
            t.values_[static_cast<std::size_t>(idx)] = method == TableMethod::fast ? minimize_pseudo_energy(a, b)
                                                       : method == TableMethod::reference
                                                           ? minimize_pseudo_energy_reference(a, b)
                                                           : minimize_pseudo_energy_nlopt(a, b);
        },
        progress);
    if (use_symmetry) {
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const int rep = representative(i, j);
                if (rep == i * n + j) continue;
                const PseudoEnergyMinimum& src = t.values_[static_cast<std::size_t>(rep)];
                PseudoEnergyMinimum m = src;
                const int ri = rep / n, rj = rep % n;
                const int ni = negate[static_cast<std::size_t>(i)], nj = negate[static_cast<std::size_t>(j)];
                m.theta0 = t.axis_.nodes[static_cast<std::size_t>(i)];
                m.theta1 = t.axis_.nodes[static_cast<std::size_t>(j)];
                bool swapped = false, negated = false;
                if (ri == j && rj == i)
                    swapped = true;
                else if (ri == ni && rj == nj)
                    negated = true;
                else
                    swapped = negated = true;  // (−θ1, −θ0)
                if (swapped) {
                    std::swap(m.r0, m.r1);
                    std::swap(m.runner_up_r0, m.runner_up_r1);
                }
                if (swapped != negated) m.area = -m.area;
                t.values_[static_cast<std::size_t>(i * n + j)] = m;
            }
    }
    t.pack();
    return t;
}

void PseudoEnergyTable::pack() {
    packed_.resize(values_.size());
    for (std::size_t k = 0; k < values_.size(); ++k) {
        const PseudoEnergyMinimum& m = values_[k];
        const bool usable = m.type != SegmentType::x && m.outcome.ok();
        packed_[k] = {m.pseudo_energy, m.r0, m.r1, m.length, m.area, usable ? m.type : SegmentType::x};
    }
}

PseudoEnergyTable::CellPosition PseudoEnergyTable::locate_cell(double theta0, double theta1) const {
    const char* who = "cagd::fairness::PseudoEnergyTable::lookup";
    require_tangent_angle(who, theta0, "theta0");
    require_tangent_angle(who, theta1, "theta1");
    if (is_undefined_node(theta0, theta1))
        fail_input(who,
                   "(" + full_precision(theta0) + ", " + full_precision(theta1) +
                       ") is an undefined node (theta0, theta1 in {0, +-pi}): r0, r1 do not exist there (paper §4.1)");
    CellPosition c;
    axis_.locate(theta0, c.i, c.u);
    axis_.locate(theta1, c.j, c.v);
    return c;
}

namespace {

// Bilinear blend of the cell (i, j) at local (u, v) over its defined corners of type `want`
// (x: every defined corner), the weights renormalised; `at(a, b)` gives a node's value.
template <class NodeValue>
TableValue blend_cell(int n, int i, int j, double u, double v, SegmentType want, const NodeValue& at, double theta0,
                      double theta1) {
    const int i1 = next_node(i, n), j1 = next_node(j, n);
    const int ci[4] = {i, i1, i, i1}, cj[4] = {j, j, j1, j1};
    const double w[4] = {(1 - u) * (1 - v), u * (1 - v), (1 - u) * v, u * v};
    TableValue out;
    double wsum = 0.0;
    for (int k = 0; k < 4; ++k) {
        const TableValue& m = at(ci[k], cj[k]);
        if (m.type == SegmentType::x) continue;  // undefined or failed node
        if (want != SegmentType::x && m.type != want) continue;
        wsum += w[k];
        out.pseudo_energy += w[k] * m.pseudo_energy;
        out.r0 += w[k] * m.r0;
        out.r1 += w[k] * m.r1;
        out.length += w[k] * m.length;
        out.area += w[k] * m.area;
    }
    if (!(wsum > 0.0)) {
        // Only possible when every corner of the cell is undefined or of the other type with
        // zero weight: fall back to the nearest defined corner of the wanted type.
        for (int k = 0; k < 4; ++k) {
            const TableValue& m = at(ci[k], cj[k]);
            if (m.type != SegmentType::x && (want == SegmentType::x || m.type == want)) return m;
        }
        fail_input("cagd::fairness::PseudoEnergyTable::lookup",
                   "no defined table node near (" + full_precision(theta0) + ", " + full_precision(theta1) + ")");
    }
    out.pseudo_energy /= wsum;
    out.r0 /= wsum;
    out.r1 /= wsum;
    out.length /= wsum;
    out.area /= wsum;
    out.type = want;
    return out;
}

// The corners of `want`'s type (and defined) in the cell (i, j), read at local (u, v) by one of the
// three further same-type rules of CellRule: each yields weights over those corners that sum to 1.
template <class NodeValue>
TableValue blend_same_type(CellRule rule, int n, int i, int j, double u, double v, SegmentType want,
                           const NodeValue& at) {
    const int i1 = next_node(i, n), j1 = next_node(j, n);
    const int ci[4] = {i, i1, i, i1}, cj[4] = {j, j, j1, j1};
    const double cu[4] = {0, 1, 0, 1}, cv[4] = {0, 0, 1, 1};
    TableValue m[4];
    int used[4], count = 0;
    for (int k = 0; k < 4; ++k) {
        m[k] = at(ci[k], cj[k]);
        if (m[k].type != SegmentType::x && m[k].type == want) used[count++] = k;
    }
    if (count == 0)
        fail_input("cagd::fairness::PseudoEnergyTable::lookup",
                   "no defined corner of the nearest node's type in the cell");  // (the nearest is one)
    double w[4] = {0, 0, 0, 0};
    if (rule == CellRule::same_type_mean_filled) {
        // Bilinear over all four corners, every other-type corner carrying the same-type mean.
        const double b[4] = {(1 - u) * (1 - v), u * (1 - v), (1 - u) * v, u * v};
        double missing = 0.0;
        for (int k = 0; k < 4; ++k) missing += b[k];
        for (int c = 0; c < count; ++c) missing -= b[used[c]];
        for (int c = 0; c < count; ++c) w[used[c]] = b[used[c]] + missing / count;
    } else if (rule == CellRule::same_type_inverse_distance) {
        double sum = 0.0;
        for (int c = 0; c < count; ++c) {
            const double d = std::hypot(u - cu[used[c]], v - cv[used[c]]);
            if (d == 0.0) return m[used[c]];  // at the node itself
            w[used[c]] = 1.0 / d;
            sum += w[used[c]];
        }
        for (int c = 0; c < count; ++c) w[used[c]] /= sum;
    } else if (count == 1 || count == 4) {  // same_type_linear: one corner, or bilinear over four
        if (count == 1) return m[used[0]];
        const double b[4] = {(1 - u) * (1 - v), u * (1 - v), (1 - u) * v, u * v};
        for (int k = 0; k < 4; ++k) w[k] = b[k];
    } else if (count == 2) {  // linear along the segment joining the two, at the point's projection
        const int a = used[0], b = used[1];
        const double du = cu[b] - cu[a], dv = cv[b] - cv[a];
        const double t = std::clamp(((u - cu[a]) * du + (v - cv[a]) * dv) / (du * du + dv * dv), 0.0, 1.0);
        w[a] = 1 - t;
        w[b] = t;
    } else {  // three corners: the plane through them (barycentric coordinates, one corner the right angle)
        int right = used[0];
        for (int c = 0; c < 3; ++c) {
            int across = 0;  // corners of the three that differ from this one in exactly one coordinate
            for (int e = 0; e < 3; ++e) across += (cu[used[e]] != cu[used[c]]) != (cv[used[e]] != cv[used[c]]);
            if (across == 2) right = used[c];
        }
        int along_u = right, along_v = right;
        for (int c = 0; c < 3; ++c) {
            if (used[c] != right && cv[used[c]] == cv[right]) along_u = used[c];
            if (used[c] != right && cu[used[c]] == cu[right]) along_v = used[c];
        }
        const double su = std::abs(u - cu[right]), sv = std::abs(v - cv[right]);
        w[along_u] = su;
        w[along_v] = sv;
        w[right] = 1 - su - sv;
    }
    TableValue out;
    for (int k = 0; k < 4; ++k) {
        if (w[k] == 0.0) continue;
        out.pseudo_energy += w[k] * m[k].pseudo_energy;
        out.r0 += w[k] * m[k].r0;
        out.r1 += w[k] * m[k].r1;
        out.length += w[k] * m[k].length;
        out.area += w[k] * m[k].area;
    }
    out.type = want;
    return out;
}

bool is_same_type_variant(CellRule c) {
    return c == CellRule::same_type_linear || c == CellRule::same_type_inverse_distance ||
           c == CellRule::same_type_mean_filled;
}

}  // namespace

TableValue PseudoEnergyTable::lookup(double theta0, double theta1, bool same_type_only) const {
    const CellPosition cell =
        locate_cell(theta0, theta1);  // (not a structured binding: the lambdas below capture i, j)
    const int i = cell.i, j = cell.j;
    const double u = cell.u, v = cell.v;
    const int n = grid_.n;
    const auto at = [&](int a, int b) -> const TableValue& { return packed_[static_cast<std::size_t>(a * n + b)]; };
    const SegmentType want =
        same_type_only ? at(u < 0.5 ? i : next_node(i, n), v < 0.5 ? j : next_node(j, n)).type : SegmentType::x;
    return blend_cell(n, i, j, u, v, want, at, theta0, theta1);
}

const char* to_string(CellRule c) {
    switch (c) {
        case CellRule::same_type: return "same_type";
        case CellRule::all_corners: return "all_corners";
        case CellRule::nearest_node_down: return "nearest_node_down";
        case CellRule::nearest_node_up: return "nearest_node_up";
        case CellRule::same_type_linear: return "same_type_linear";
        case CellRule::same_type_inverse_distance: return "same_type_inverse_distance";
        case CellRule::same_type_mean_filled: return "same_type_mean_filled";
    }
    return "?";
}

TableValue PseudoEnergyTable::node_value(int i, int j, double runner_up_within) const {
    const auto k = static_cast<std::size_t>(i * grid_.n + j);
    const TableValue& v = packed_[k];
    const PseudoEnergyMinimum& m = values_[k];
    if (!(runner_up_within > 0.0) || v.type == SegmentType::x || !std::isfinite(m.runner_up) ||
        m.runner_up - m.pseudo_energy > runner_up_within)
        return v;
    if (!(m.runner_up_r0 > 0.0 && m.runner_up_r1 > 0.0))
        fail_input(
            "cagd::fairness::PseudoEnergyTable::lookup",
            "node (" + full_precision(m.theta0) + ", " + full_precision(m.theta1) + ") has no runner-up r0, r1 stored");
    const PseudoEnergyMinimum r = measure_segment(m.theta0, m.theta1, m.runner_up_r0, m.runner_up_r1);
    return {r.pseudo_energy, r.r0, r.r1, r.length, r.area, r.type};
}

int PseudoEnergyTable::runner_up_nodes(double within) const {
    int count = 0;
    for (std::size_t k = 0; k < values_.size(); ++k)
        count += packed_[k].type != SegmentType::x && std::isfinite(values_[k].runner_up) &&
                 values_[k].runner_up - values_[k].pseudo_energy <= within;
    return count;
}

TableValue PseudoEnergyTable::lookup(double theta0, double theta1, const TableReading& reading) const {
    if (reading.is_default()) return lookup(theta0, theta1, true);
    const CellPosition cell =
        locate_cell(theta0, theta1);  // (not a structured binding: the lambdas below capture i, j)
    const int i = cell.i, j = cell.j;
    const double u = cell.u, v = cell.v;
    const int n = grid_.n;
    const auto at = [&](int a, int b) { return node_value(a, b, reading.runner_up_within); };
    TableValue out;
    bool done = false;
    if (reading.cell == CellRule::nearest_node_down || reading.cell == CellRule::nearest_node_up) {
        const bool up = reading.cell == CellRule::nearest_node_up;
        const auto pick = [&](int lower, double t) {
            return (std::abs(t - 0.5) <= 1e-9 ? up : t > 0.5) ? next_node(lower, n) : lower;
        };
        out = at(pick(i, u), pick(j, v));
        done = out.type != SegmentType::x;
    }
    if (!done && is_same_type_variant(reading.cell)) {
        // (An undefined nearest node falls back to all_corners, as for same_type.)
        const SegmentType want = at(u < 0.5 ? i : next_node(i, n), v < 0.5 ? j : next_node(j, n)).type;
        if (want != SegmentType::x) {
            out = blend_same_type(reading.cell, n, i, j, u, v, want, at);
            done = true;
        }
    }
    if (!done) {
        const SegmentType want = reading.cell == CellRule::same_type
                                     ? at(u < 0.5 ? i : next_node(i, n), v < 0.5 ? j : next_node(j, n)).type
                                     : SegmentType::x;
        out = blend_cell(n, i, j, u, v, want, at, theta0, theta1);
    }
    if (reading.radii) {
        const PseudoEnergyMinimum m = measure_segment(theta0, theta1, out.r0, out.r1);
        out.pseudo_energy = m.pseudo_energy;
        out.length = m.length;
        out.area = m.area;
    }
    return out;
}

}  // namespace cagd::fairness
