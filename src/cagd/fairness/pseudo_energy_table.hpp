#pragma once
/// @file
/// Lookup tables of J(θ0, θ1), r0, r1, L, S and the segment type over a grid of direction
/// pairs (pseudo_energy section 4.1, eq 8, 14). The table of J(θ), θ1(θ) over a grid of angles
/// (eq 11) is fairness/angle_minimum_table.hpp.
///
/// Node placement (the paper: "divide (−π, π)² into a lattice (Θ_i, Θ_j), i, j = 1..m, m = 36",
/// and it lists (|Θ_i|, |Θ_j|) = (π, 0), (0, π), (π, π) and (0, 0) as nodes, so 0 and ±π are nodes):
///   periodic   Θ_k = −π + 2πk/N, k = 0..N−1 — N distinct directions; for N = 36 every 10°,
///              −180° … 170°, containing 0 and ±π. The default: the only equally spaced 36-node
///              placement containing both 0 and ±π without storing the direction ±π twice.
///   endpoints  Θ_k = −π + 2πk/(N−1), k = 0..N−1 — both −π and π; 0 only for odd N.
///   midpoints  Θ_k = −π + 2π(k + ½)/N — cell centres; no node is undefined.
/// J is exactly 2π-periodic in each angle (θ and θ ± 2π give the same tangent), so every
/// placement is interpolated periodically.
///
/// Undefined nodes (θ0, θ1 ∈ {0, ±π}) are stored with type x and are never used by the
/// interpolation; querying one exactly throws InvalidInput (J(0, 0) = 0 but r0, r1 do not exist).
///
/// Interpolation (section 4.1): bilinear in the grid cell containing (θ0, θ1), using only the
/// cell corners whose type equals the type of the nearest node (the weights of the others are
/// dropped and the rest renormalised), so a query never mixes the s- and c-branches across the
/// jump of Fig. 7. When the nearest node is undefined (x), all defined corners are used.
/// Cost: O(log N) per lookup (one binary search per axis), no allocation.
///
/// Build: the fast minimiser at every node, two threads by default. `use_symmetry` computes one
/// node per orbit of the symmetry group {(θ0, θ1), (θ1, θ0), (−θ0, −θ1), (−θ1, −θ0)} and fills the
/// others (J, L invariant; r0 ↔ r1 under the swap; S changes sign under (θ1, θ0) and (−θ0, −θ1)),
/// which the placements here allow since each is symmetric about 0. The reference build
/// (Romberg + Ceres CG) computes every node, so the symmetry is a checked result there.
/// Cache: a text file whose first line records format version, grid, placement and method; `load`
/// refuses a file whose line differs, so a changed grid or method rebuilds (the format:
/// pseudo_energy_table_file.cpp).
#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "cagd/fairness/detail/periodic_grid.hpp"
#include "cagd/fairness/pseudo_energy_minimum.hpp"

namespace cagd::fairness {

/// Where the N nodes of each axis lie (see above).
enum class NodePlacement { periodic, endpoints, midpoints };

/// The largest grid a table file may declare (a 0.5° grid; `cagd energy-table --grid` has the same
/// limit): a load checks it before it reads a row.
inline constexpr int kMaxTableGrid = 720;
/// "periodic", "endpoints" or "midpoints".
const char* to_string(NodePlacement p);
NodePlacement parse_node_placement(const std::string& text);  ///< throws InvalidInput

/// The nodes of a table: N per axis and their placement.
struct AngleGrid {
    int n = 36;                                         ///< nodes per axis, ≥ 2
    NodePlacement placement = NodePlacement::periodic;  ///< where they lie
    /// The N node angles, ascending.
    std::vector<double> nodes() const;  ///< ascending, in [−π, π]
};

/// fast: minimize_pseudo_energy; reference: Romberg + Ceres CG; nlopt: the independent second minimiser.
enum class TableMethod { fast, reference, nlopt };
/// "fast", "reference" or "nlopt".
const char* to_string(TableMethod m);

/// The values at (θ0, θ1), read from the table.
struct TableValue {
    double pseudo_energy = 0.0;         ///< J
    double r0 = 0.0;                    ///< r0
    double r1 = 0.0;                    ///< r1
    double length = 0.0;                ///< L
    double area = 0.0;                  ///< S
    SegmentType type = SegmentType::x;  ///< the type whose nodes were used
};

/// How a table is read between its nodes. Section 4.1 says the values are interpolated; what is
/// interpolated, over which corners, and which minimum a node holds are left open (erratum
/// pseudo_energy-E4 compares every combination with Tables 5–6):
///   cell              same_type: bilinear over the corners of the nearest corner's type (our
///                     reading, lookup(θ0, θ1, true)); all_corners: plain bilinear over the defined
///                     corners (lookup(θ0, θ1, false)); nearest_node_down / _up: the value of the
///                     nearest node, a coordinate half-way between two nodes (to 1e-9 of the
///                     spacing) going to the lower / upper one (an undefined nearest node falls back
///                     to all_corners)
///                     The corners of the nearest corner's type read in three further ways, each of
///                     which equals plain bilinear interpolation in a cell of one type:
///                     same_type_linear: the linear function through those corners (one: its value;
///                     two: linear along the segment joining them, at the point's projection on it;
///                     three: the plane through them; four: bilinear); same_type_inverse_distance:
///                     Shepard's weights 1/d (d the distance to the corner in the cell's (u, v)
///                     coordinates; a node itself at d = 0); same_type_mean_filled: bilinear over all
///                     four corners with each other-type (or undefined) corner's value replaced by
///                     the mean of the same-type corners'
///   radii             interpolate r0, r1 only and measure J, L, S of the segment they make (fast
///                     quadrature) — else J, L, S are interpolated themselves (eq 17, 20)
///   runner_up_within  > 0: a node whose second local minimum is within this of the global one in J
///                     holds the second instead (as a minimiser that stopped in the other basin
///                     would); its J, L, S measured at the runner-up's r0, r1
enum class CellRule {
    same_type,
    all_corners,
    nearest_node_down,
    nearest_node_up,
    same_type_linear,
    same_type_inverse_distance,
    same_type_mean_filled
};
/// "same_type", "all_corners", "nearest_node_down", "nearest_node_up", "same_type_linear",
/// "same_type_inverse_distance" or "same_type_mean_filled".
const char* to_string(CellRule c);
/// How a table is read between its nodes (see above).
struct TableReading {
    CellRule cell = CellRule::same_type;  ///< which corners, or which node
    bool radii = false;                   ///< interpolate r0, r1 and measure J, L, S of their segment
    double runner_up_within = 0.0;        ///< a node whose runner-up is within this of J holds the runner-up (0: never)
    /// Whether this is the reading of lookup(θ0, θ1): same_type, values interpolated, no runner-up.
    bool is_default() const { return cell == CellRule::same_type && !radii && !(runner_up_within > 0.0); }
};

/// The table of J(θ0, θ1), r0, r1, L, S and type over a grid of direction pairs (see above).
class PseudoEnergyTable {
public:
    /// progress(done, total) is called from the building threads now and then (may be empty).
    static PseudoEnergyTable build(const AngleGrid& grid, TableMethod method, int threads = 2, bool use_symmetry = true,
                                   const std::function<void(long, long)>& progress = {});
    /// Loads a table written by save() / `cagd energy-table`; grid, placement and method come from
    /// its first line. Throws InvalidInput for a missing, foreign, truncated or other-format file.
    static PseudoEnergyTable load(const std::string& path);
    /// load(path) when the file holds a table of this grid and method, else build and save it (locked: a concurrent
    /// caller waits).
    static PseudoEnergyTable load_or_build(const std::string& path, const AngleGrid& grid, TableMethod method,
                                           int threads = 2);
    /// The table from the user's cache (io/user_cache.hpp), built and saved there on a miss with
    /// the build notice and progress; built in memory when the cache is off or cannot be written.
    /// The same table as build(grid, method, threads), bit for bit.
    static PseudoEnergyTable user_cached(const AngleGrid& grid, TableMethod method, int threads = 2);

    /// The grid.
    const AngleGrid& grid() const { return grid_; }
    /// The minimiser that built it.
    TableMethod method() const { return method_; }
    /// The node angles of each axis.
    const std::vector<double>& nodes() const { return axis_.nodes; }
    /// The minimum at node (i, j).
    const PseudoEnergyMinimum& node(int i, int j) const { return values_[static_cast<std::size_t>(i * grid_.n + j)]; }

    /// Interpolated values at (θ0, θ1) ∈ [−π, π]²; throws InvalidInput outside, for non-finite
    /// angles, or at an undefined node. same_type_only = false gives plain bilinear interpolation
    /// over all defined corners (for comparison with the paper's rule).
    TableValue lookup(double theta0, double theta1, bool same_type_only = true) const;
    /// The same under any reading (TableReading above); the default reading is lookup(θ0, θ1).
    TableValue lookup(double theta0, double theta1, const TableReading& reading) const;
    /// Nodes whose second local minimum is within `within` of the global one in J.
    int runner_up_nodes(double within) const;

    /// Writes the table to `path` as an OutputFile (io/output_file.hpp): whole or not at all; OutputError on a failed
    /// write.
    void save(const std::string& path) const;
    /// The same text to a stream. Undefined nodes (θ0 or θ1 at 0 or ±π, eq 8) and nodes without a
    /// second minimum carry inf in J and runner_up: the format's own marks, read back by load().
    void save(std::ostream& out) const;
    /// The first line of the file: format version, grid, placement and method.
    std::string header_line() const;

private:
    static PseudoEnergyTable load_or_build(const std::string& path, const AngleGrid& grid, TableMethod method,
                                           int threads, bool user_cache);
    AngleGrid grid_;
    TableMethod method_ = TableMethod::fast;
    detail::PeriodicAxis axis_;
    std::vector<PseudoEnergyMinimum> values_;
    std::vector<TableValue> packed_;  ///< what lookup reads: J, r0, r1, L, S, type (x = unusable), 48 bytes a node
    void pack();
    /// The cell of (θ0, θ1): lower-left node (i, j) and local coordinates (u, v) ∈ [0, 1); checks the angles.
    struct CellPosition {
        int i = 0, j = 0;
        double u = 0.0, v = 0.0;
    };
    CellPosition locate_cell(double theta0, double theta1) const;
    TableValue node_value(int i, int j, double runner_up_within) const;
};

}  // namespace cagd::fairness
