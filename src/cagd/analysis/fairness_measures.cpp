#include "cagd/analysis/fairness_measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/frenet_jet.hpp"
#include "cagd/core/errors.hpp"

namespace cagd::analysis {

FairnessMeasures fairness_measures(const Curve& c, const PointList& data, int samples) {
    return fairness_measures(c, data, FairnessSampling{samples, 64});
}

FairnessMeasures fairness_measures(const Curve& c, const PointList& data, const FairnessSampling& sampling) {
    const char* who = "cagd::analysis::fairness_measures";
    const int samples = sampling.samples, pieces = sampling.quadrature_pieces;
    if (pieces < 1) fail_input(who, "quadrature_pieces must be >= 1, got " + std::to_string(pieces));
    const int dim = c.dimension();
    if (dim != 2 && dim != 3) fail_input(who, "needs a planar or space curve, dimension is " + std::to_string(dim));
    if (data.cols() != dim || data.rows() < 1)
        fail_input(who, "needs data points of the curve's dimension " + std::to_string(dim));
    if (samples < 2) fail_input(who, "samples must be >= 2, got " + std::to_string(samples));
    const Eigen::RowVectorXd lo = data.colwise().minCoeff(), hi = data.colwise().maxCoeff();
    const double diagonal = (hi - lo).norm();
    FairnessMeasures m;
    m.dimension = dim;
    const std::vector<double> br = c.breakpoints();
    const double extent = std::max(diagonal, 1e-300);  // D of the flatness policy
    std::vector<int> signs;                            // of κ at the samples (planar)
    for (std::size_t k = 0; k + 1 < br.size(); ++k) {
        const double a = br[k], b = br[k + 1];
        const auto [len, energy] = piece_length_and_bending_energy(c, a, b, pieces);
        m.length += len;
        m.bending_energy += energy;
        m.piece_lengths.push_back(len);
        m.piece_energies.push_back(energy);
        m.pseudo_energy += len * len * energy;
        JetMatrix J, Jb;
        c.jet_into(a, 0, J);
        c.jet_into(b, 0, Jb);
        const double chord = (Jb.row(0) - J.row(0)).norm();
        // A piece that starts deeper inside the data's box than twice its length cannot leave it
        // (|r(u) − r(a)| is at most the arc length from a; twice the quadrature's length leaves room
        // for its error): its samples' overshoot is 0, and their derivatives are taken without
        // the position (derivatives_into: the same values, bit for bit; a position costs an
        // integration on some curves, e.g. 16 sincos on the curvature-profile curve).
        double depth = std::numeric_limits<double>::infinity();
        for (int d = 0; d < dim; ++d) depth = std::min({depth, J(0, d) - lo(d), hi(d) - J(0, d)});
        const bool needs_position = !(depth > 2.0 * len);
        const int r1 = needs_position ? 1 : 0;  // the row of the first derivative
        double spike = 0.0;
        for (int j = 0; j <= samples; ++j) {
            const double u = a + (b - a) * j / samples;
            if (needs_position)
                c.jet_into(u, 3, J);
            else
                c.derivatives_into(u, 3, J);
            const FrenetJet f = frenet_jet(J.middleRows(r1, 3));
            if (!f.regular)
                fail_input(who, "zero speed (a cusp) at t = " + full_precision(u) + ": curvature is undefined there");
            const double kappa = f.curvature;  // signed in the plane, |κ| in space
            if (dim == 2) {
                m.max_abs_curvature_derivative = std::max(m.max_abs_curvature_derivative, std::abs(f.curvature_rate));
                signs.push_back(curvature_sign(kappa, extent));
            } else if (!is_straight(kappa, extent)) {
                m.max_abs_curvature_derivative = std::max(m.max_abs_curvature_derivative, std::abs(f.curvature_rate));
                m.max_abs_torsion = std::max(m.max_abs_torsion, std::abs(f.torsion));
            }
            m.max_abs_curvature = std::max(m.max_abs_curvature, std::abs(kappa));
            spike = std::max(spike, std::abs(kappa) * chord);
            if (!needs_position) continue;
            double outside = 0.0;  // distance from the data's bounding box
            for (int d = 0; d < dim; ++d) {
                const double e = std::max({lo(d) - J(0, d), J(0, d) - hi(d), 0.0});
                outside += e * e;
            }
            m.overshoot = std::max(m.overshoot, std::sqrt(outside) / diagonal);
        }
        m.max_spike = std::max(m.max_spike, spike);
        if (spike > kCornerThreshold) ++m.corners;
    }
    m.curvature_sign_changes = sign_changes(signs, false);
    return m;
}

std::vector<CurvatureSample> curvature_profile(const Curve& c, int samples) {
    if (samples < 1)
        fail_input("cagd::analysis::curvature_profile", "samples must be >= 1, got " + std::to_string(samples));
    std::vector<CurvatureSample> out;
    const std::vector<double> br = c.breakpoints();
    double s = 0.0;
    for (std::size_t k = 0; k + 1 < br.size(); ++k) {
        double prev = br[k];
        for (int j = 0; j < samples + (k + 2 == br.size() ? 1 : 0); ++j) {
            const double u = br[k] + (br[k + 1] - br[k]) * j / samples;
            if (u > prev) s += arc_length(c, prev, u, 1);
            prev = u;
            out.push_back({u, s, signed_curvature(c, u)});
        }
        if (prev < br[k + 1]) s += arc_length(c, prev, br[k + 1], 1);
    }
    return out;
}

int self_intersections(const Curve& c, int samples) {
    if (c.dimension() != 2) fail_input("cagd::analysis::self_intersections", "needs a planar curve");
    if (samples < 1)
        fail_input("cagd::analysis::self_intersections", "samples must be >= 1, got " + std::to_string(samples));
    std::vector<Eigen::Vector2d> p;
    const std::vector<double> br = c.breakpoints();
    for (std::size_t k = 0; k + 1 < br.size(); ++k)
        for (int j = 0; j < samples + (k + 2 == br.size() ? 1 : 0); ++j)
            p.push_back(c.point(br[k] + (br[k + 1] - br[k]) * j / samples));
    const auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); };
    const bool closed = (p.front() - p.back()).norm() == 0.0;
    int count = 0;
    for (std::size_t i = 0; i + 1 < p.size(); ++i)
        for (std::size_t j = i + 2; j + 1 < p.size(); ++j) {
            if (closed && i == 0 && j + 2 == p.size()) continue;  // the closing segments touch at p_0
            const Eigen::Vector2d r = p[i + 1] - p[i], s = p[j + 1] - p[j], q = p[j] - p[i];
            const double d = cross(r, s);
            if (d == 0.0) continue;
            const double t = cross(q, s) / d, u = cross(q, r) / d;
            if (t > 0.0 && t < 1.0 && u > 0.0 && u < 1.0) ++count;
        }
    return count;
}

}  // namespace cagd::analysis
