#pragma once
/// @file
/// The table of J(θ) = min over θ1 of J(θ, θ1) and its minimiser θ1(θ) (pseudo_energy section 4.1,
/// eq 11): the tangent choice of eq (12) reads it. Nodes and interpolation as the 2-D table's
/// (fairness/pseudo_energy_table.hpp), in one angle.
#include <string>
#include <utility>
#include <vector>

#include "cagd/fairness/detail/periodic_grid.hpp"
#include "cagd/fairness/pseudo_energy_minimum.hpp"
#include "cagd/fairness/pseudo_energy_table.hpp"

namespace cagd::fairness {

/// J(θ) and θ1(θ) of eq (11) at the nodes of a grid, and their linear interpolation. Two builds:
///   build            exact minimisation over θ1 at each node (fast minimiser, scan step 2°, Brent);
///                    given a fast table on 1° nodes (endpoints placement, 361 nodes, or any
///                    180·k + 1), the 2° scan at each of its nodes θ is read from the table instead
///                    of recomputed (the same minimiser at the same angles: 181 of the ~190
///                    minimisations per node), and only Brent's refinement minimises afresh;
///   from_energy_table the paper's construction (section 4.1): at each node Θ_i, minimise the
///                    *interpolated* J(Θ_i, θ1) of the 2-D table over θ1 (scan step 0.25°, Brent),
///                    so J(θ) inherits the table's interpolation error. Cheap (no quadrature).
class AngleMinimumTable {
public:
    /// Exact minimisation at every node of the grid.
    static AngleMinimumTable build(const AngleGrid& grid, int threads = 2);
    /// Throws InvalidInput unless scan_source is a fast table on an endpoints grid of 180·k + 1 nodes.
    static AngleMinimumTable build(const AngleGrid& grid, const PseudoEnergyTable& scan_source, int threads = 2);
    /// The paper's construction from a 2-D table, read by its default reading.
    static AngleMinimumTable from_energy_table(const PseudoEnergyTable& table);
    /// The same with J(Θ_i, θ1) read by `reading` (its cell rule and runner-up choice; J itself is
    /// interpolated even when reading.radii asks for r0, r1).
    static AngleMinimumTable from_energy_table(const PseudoEnergyTable& table, const TableReading& reading);
    /// build(), kept in `path`: loaded when the file holds this grid's table (values at %.17g, so a
    /// load equals a build bit for bit), otherwise built and saved (temporary file, then rename).
    static AngleMinimumTable load_or_build(const std::string& path, const AngleGrid& grid, int threads = 2);
    /// load_or_build with the 2° scans read from `scan_source` (see build).
    static AngleMinimumTable load_or_build(const std::string& path, const AngleGrid& grid,
                                           const PseudoEnergyTable& scan_source, int threads = 2);
    /// The node angles.
    const std::vector<double>& nodes() const { return axis_.nodes; }
    /// J(θ), θ1(θ) at the nodes.
    const std::vector<AngleMinimum>& values() const { return values_; }
    /// Linear interpolation; throws InvalidInput outside [−π, π]. Returns {J(θ), θ1(θ)}.
    std::pair<double, double> lookup(double theta) const;
    /// J(θ) alone, the same interpolation; inline (below): eq (12) reads it six times per point.
    double pseudo_energy(double theta) const;

private:
    AngleGrid grid_;
    detail::PeriodicAxis axis_;
    std::vector<AngleMinimum> values_;
    static AngleMinimumTable build(const AngleGrid& grid, const PseudoEnergyTable* scan_source, int threads);
    static AngleMinimumTable load_or_build(const std::string& path, const AngleGrid& grid,
                                           const PseudoEnergyTable* scan_source, int threads);
};

inline double AngleMinimumTable::pseudo_energy(double theta) const {
    require_tangent_angle("cagd::fairness::AngleMinimumTable::pseudo_energy", theta, "theta");
    int i = 0;
    double u = 0.0;
    axis_.locate(theta, i, u);
    const std::size_t a = static_cast<std::size_t>(i),
                      b = static_cast<std::size_t>(detail::next_node(i, static_cast<int>(axis_.nodes.size())));
    return (1 - u) * values_[a].pseudo_energy + u * values_[b].pseudo_energy;
}

}  // namespace cagd::fairness
