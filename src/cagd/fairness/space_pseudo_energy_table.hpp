#pragma once
/// @file
/// The 3-D table of the space pseudo-energy (pseudo_energy section 6, extended to space): J(θ0, θ1, φ), its minimisers
/// r0, r1, the length L and the segment type over the box [0, π] × [0, π] × [0, 2π) that
/// pseudo_energy section 6 proposes, with trilinear lookup.
///
/// Nodes (our choice, stated): θ at the midpoints Θ_k = (k + ½)·π/N, k = 0..N−1 — so no node lies on
/// the undefined directions θ0, θ1 ∈ {0, π}, where r0, r1 do not exist — and φ periodic,
/// Φ_k = 2πk/M, k = 0..M−1 (φ and φ + 2π are the same direction). Lookups with θ within half a
/// cell of 0 or π use the edge cell with its weight clamped (the value at the nearest node row:
/// constant extension, accurate to the table's own resolution).
///
/// Lookup (the planar section 4.1 rule, generalised): trilinear in the cell containing
/// (θ0, θ1, φ) over the corners whose type (space_pseudo_energy.hpp: c/s by the end binormals) is
/// that of the nearest corner, the weights of the others dropped and the rest renormalised, so a
/// value never mixes two branches of the minimiser. It returns J, r0, r1 and L (what section 5
/// needs in space: the length; a space curve encloses no area).
///
/// Build: the fast minimiser at every node, threaded (core/parallel.hpp), with progress; the
/// symmetries J(θ0, θ1, φ) = J(θ0, θ1, 2π − φ) (reflection) and = J(θ1, θ0, φ) with r0 ↔ r1
/// (reversal) compute one node per orbit and fill the others. The nodes are independent, so the
/// table is the same, byte for byte, for any number of threads — or of MPI ranks, which compute
/// blocks of `orbit_nodes()` with `compute_orbits` and send them to one rank that `assemble`s.
/// Cache: text, first line naming format, grid and method; `load_or_build` rebuilds on a mismatch.
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "cagd/fairness/pseudo_energy_table.hpp"
#include "cagd/fairness/space_pseudo_energy.hpp"

namespace cagd::fairness {

/// The nodes of a space table: cell midpoints in θ0 and θ1, equally spaced on the φ circle.
struct SpaceAngleGrid {
    int n_theta = 36;  ///< nodes per θ axis (cell midpoints), ≥ 2
    int n_phi = 72;    ///< nodes on the φ circle, ≥ 4 and even (the reflection maps nodes to nodes)
    /// The θ nodes, ascending, in (0, π).
    std::vector<double> theta_nodes() const;
    /// The φ nodes, ascending, in [0, 2π).
    std::vector<double> phi_nodes() const;
    /// Nodes in all.
    long size() const { return static_cast<long>(n_theta) * n_theta * n_phi; }
};

/// The values of the space table at (θ0, θ1, φ).
struct SpaceTableValue {
    double pseudo_energy = 0.0;         ///< J
    double r0 = 0.0;                    ///< r0
    double r1 = 0.0;                    ///< r1
    double length = 0.0;                ///< L
    SegmentType type = SegmentType::x;  ///< the type whose nodes were used
};

/// The 3-D table of J(θ0, θ1, φ) and its minimisers (see above).
class SpacePseudoEnergyTable {
public:
    /// One node per symmetry orbit, in a fixed order: the work list of a build.
    static std::vector<long> orbit_nodes(const SpaceAngleGrid& grid);
    /// The minima at orbit_nodes()[begin, end) (threads ≥ 1), in that order.
    static std::vector<SpacePseudoEnergyMinimum> compute_orbits(const SpaceAngleGrid& grid, TableMethod method,
                                                                long begin, long end, int threads,
                                                                const std::function<void(long, long)>& progress = {});
    /// The table from the minima of every orbit (in orbit_nodes() order).
    static SpacePseudoEnergyTable assemble(const SpaceAngleGrid& grid, TableMethod method,
                                           const std::vector<SpacePseudoEnergyMinimum>& orbits);
    /// Every node by the given minimiser, one orbit of the symmetries at a time, on `threads` threads.
    static SpacePseudoEnergyTable build(const SpaceAngleGrid& grid, TableMethod method, int threads = 2,
                                        const std::function<void(long, long)>& progress = {});
    static SpacePseudoEnergyTable load(const std::string& path);  ///< InvalidInput for a foreign or damaged file
    /// load(path) when the file holds this grid's table, else build and save it.
    static SpacePseudoEnergyTable load_or_build(const std::string& path, const SpaceAngleGrid& grid, TableMethod method,
                                                int threads = 2);
    /// The table from the user's cache (io/user_cache.hpp), built and saved there on a miss with
    /// the build notice and progress; built in memory when the cache is off or cannot be written.
    static SpacePseudoEnergyTable user_cached(const SpaceAngleGrid& grid, TableMethod method, int threads = 2);

    /// The grid.
    const SpaceAngleGrid& grid() const { return grid_; }
    /// The minimiser that built it.
    TableMethod method() const { return method_; }
    /// The position of node (i, j, k) in the node order (φ fastest).
    long index(int i, int j, int k) const { return (static_cast<long>(i) * grid_.n_theta + j) * grid_.n_phi + k; }
    /// The values at node (i, j, k).
    const SpaceTableValue& node(int i, int j, int k) const { return values_[static_cast<std::size_t>(index(i, j, k))]; }

    /// θ0, θ1 ∈ [0, π], φ any finite angle (taken mod 2π); InvalidInput otherwise.
    SpaceTableValue lookup(double theta0, double theta1, double phi) const;

    /// Writes the table to `path` as an OutputFile (io/output_file.hpp): whole or not at all; OutputError on a failed
    /// write.
    void save(const std::string& path) const;
    /// The same text to a stream.
    void save(std::ostream& out) const;
    /// The file's first line: format version, grid and method.
    std::string header_line() const;

private:
    static SpacePseudoEnergyTable load_or_build(const std::string& path, const SpaceAngleGrid& grid, TableMethod method,
                                                int threads, bool user_cache);
    SpaceAngleGrid grid_;
    TableMethod method_ = TableMethod::fast;
    std::vector<double> theta_, phi_;
    std::vector<SpaceTableValue> values_;
};

}  // namespace cagd::fairness
