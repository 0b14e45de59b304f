#include "cagd/intrinsic/spiro.hpp"

#include <Eigen/SparseCore>
#include <cmath>
#include <numbers>
#include <optional>

#include "cagd/numeric/banded_or_sparse_lu.hpp"
#include "cagd/numeric/sparse_lu.hpp"
#include "cagd/spline/bezier.hpp"

namespace cagd::intrinsic {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// The chordwise Newton: converged at ‖f‖∞ ≤ kChordwiseTolerance (angles in radians, curvatures
// scaled by the chord); diverged when a coefficient exceeds kLargestCoefficient (a span turning by
// hundreds of radians) or a spiral's chord shrinks below kShortestChord of its arc length.
constexpr double kChordwiseTolerance = 1e-13;
// The arc-length polish's ‖f‖∞ tolerance, its rows dimensionless (see solve_spiro).
constexpr double kArcLengthTolerance = 1e-11;
// ... or when a step was below this (the residual then is rounding; the arc-length Newton polishes).
constexpr double kChordwiseSettledStep = 1e-11;
constexpr double kLargestCoefficient = 1e3;
constexpr double kShortestChord = 1e-9;

int span_count(const PointList& p, bool closed) { return static_cast<int>(p.rows()) - (closed ? 0 : 1); }

// k^m / m! at e, and its derivatives: a(d, m) = e^(m−d)/(m−d)! (m ≥ d), the coefficient of k_m in
// κ_n^(d)(e) (d = 0..2) and, for d = −1, in θ_n(e) = Σ k_m e^(m+1)/(m+1)!.
double coefficient(int d, int m, double e) {
    const int power = m - d;
    if (power < 0) return 0.0;
    double v = 1.0;
    for (int i = 1; i <= power; ++i) v *= e / i;
    return v;
}

// ∂(Bézier ordinates of θ_n(t − 1/2) on t ∈ [0, 1]) / ∂k_m: a constant 5 × 4 matrix (θ_n is linear in k).
const Eigen::Matrix<double, 5, 4>& ordinates_of_coefficients() {
    static const Eigen::Matrix<double, 5, 4> M = [] {
        Eigen::Matrix<double, 5, 4> out;
        for (int m = 0; m < 4; ++m) {
            // θ_n(t − 1/2) = (t − 1/2)^(m+1)/(m+1)! in powers of t.
            Eigen::MatrixXd monomial = Eigen::MatrixXd::Zero(5, 1);
            double factorial = 1.0;
            for (int i = 2; i <= m + 1; ++i) factorial *= i;
            double binomial = 1.0;  // C(m+1, j)
            for (int j = 0; j <= m + 1; ++j) {
                monomial(j, 0) = binomial * std::pow(-0.5, m + 1 - j) / factorial;
                binomial = binomial * (m + 1 - j) / (j + 1);
            }
            out.col(m) = bernstein_from_monomial(monomial).col(0);
        }
        return out;
    }();
    return M;
}

// One span's end quantities and their derivatives with respect to its k.
struct SpanEnds {
    double length = 0.0, turn = 0.0;     // ℓ and arg Z
    Eigen::Matrix<double, 5, 1> bezier;  // θ_n(t − 1/2) on [0, 1]
    // value[e][q]: e = 0 start (u = −1/2), 1 end (u = +1/2); q = 0 ψ − φ, 1..3 κ, κ', κ''.
    double value[2][4];
    double gradient[2][4][4];
};

bool span_ends(const std::array<double, 4>& k, double chord, SpanEnds& out) {
    const Eigen::Matrix<double, 5, 4>& M = ordinates_of_coefficients();
    const Eigen::Vector4d kv(k[0], k[1], k[2], k[3]);
    out.bezier = M * kv;
    DirectionWeights W;
    const Eigen::Vector2d Z = direction_integrals(out.bezier, 1.0, &W);
    const double rho = Z.norm();
    if (!(rho > kShortestChord)) return false;
    // ∂Z/∂k_m = Σ_r ∂Z/∂b_r M(r, m), ∂Z/∂b_r = (−∫ sin θ B_r, ∫ cos θ B_r).
    const Eigen::Matrix<double, 2, 4> dZ = (Eigen::Matrix<double, 2, 5>() << -W.row(1), W.row(0)).finished() * M;
    Eigen::Vector4d d_turn, d_length;
    for (int m = 0; m < 4; ++m) {
        d_turn(m) = (Z(0) * dZ(1, m) - Z(1) * dZ(0, m)) / (rho * rho);
        d_length(m) = -(chord / rho) * (Z(0) * dZ(0, m) + Z(1) * dZ(1, m)) / (rho * rho);
    }
    out.length = chord / rho;
    out.turn = std::atan2(Z(1), Z(0));
    for (int end = 0; end < 2; ++end) {
        const double e = end == 0 ? -0.5 : 0.5;
        double theta = 0.0;
        for (int m = 0; m < 4; ++m) theta += k[static_cast<std::size_t>(m)] * coefficient(-1, m, e);
        out.value[end][0] = theta - out.turn;
        for (int m = 0; m < 4; ++m) out.gradient[end][0][m] = coefficient(-1, m, e) - d_turn(m);
        for (int d = 0; d < 3; ++d) {
            double kn = 0.0;
            for (int m = 0; m < 4; ++m) kn += k[static_cast<std::size_t>(m)] * coefficient(d, m, e);
            const double scale = std::pow(out.length, d + 1), K = kn / scale;
            out.value[end][d + 1] = K;
            for (int m = 0; m < 4; ++m)
                out.gradient[end][d + 1][m] = coefficient(d, m, e) / scale - (d + 1) * K * d_length(m) / out.length;
        }
    }
    return true;
}

}  // namespace

CurvatureProfileProblem spiro_problem(const PointList& points, bool closed) {
    const std::string who = "intrinsic::spiro_problem";
    require_valid_points(points, closed ? 3 : 2, true, closed, who);
    const int spans = span_count(points, closed);
    std::vector<int> mult(static_cast<std::size_t>(spans) + 1, 1), index;
    mult.front() = mult.back() = 4;
    for (int i = 0; i < spans; ++i) index.push_back(i);
    const KnotLayout layout(4, std::vector<int>(static_cast<std::size_t>(spans), 1), mult, index);
    CurvatureProfileProblem problem{
        points, layout, std::vector<SegmentShape>(static_cast<std::size_t>(spans), SegmentShape::free), {}, closed, 0};
    if (closed) {
        problem.closing_continuity = 4;
    } else {
        using K = DesignCondition::Kind;
        for (int order : {1, 2}) {
            problem.conditions.push_back({K::curvature_derivative, 0, 0.0, false, order});
            problem.conditions.push_back({K::curvature_derivative, spans, 0.0, true, order});
        }
    }
    require_valid_problem(problem, who);
    return problem;
}

namespace {

// The chords of the spans and their angles, unwrapped along the polygon (bends in [−π, π]).
struct Chords {
    std::vector<double> length, angle;
    double closing_angle = 0.0;  // closed: the first chord's angle after the loop, φ_0 + 2π·turns
    int turns = 0;
};

Chords chords_of(const PointList& points, bool closed, const std::string& who) {
    require_valid_points(points, closed ? 3 : 2, true, closed, who);
    if (points.cols() != 2) fail_input(who, "points must be planar (2 columns), got " + std::to_string(points.cols()));
    const int S = span_count(points, closed), n = static_cast<int>(points.rows());
    Chords c;
    for (int i = 0; i < S; ++i) {
        const Eigen::RowVector2d d = points.row((i + 1) % n) - points.row(i);
        c.length.push_back(d.norm());
        const double a = std::atan2(d(1), d(0));
        c.angle.push_back(i == 0 ? a : c.angle.back() + std::remainder(a - c.angle.back(), kTwoPi));
    }
    if (closed) {
        c.closing_angle = c.angle.back() + std::remainder(c.angle.front() - c.angle.back(), kTwoPi);
        c.turns = static_cast<int>(std::lround((c.closing_angle - c.angle.front()) / kTwoPi));
    }
    return c;
}

// f and J at ks; false (with the span) when a spiral closes on itself.
bool chordwise_system(const Chords& C, bool closed, const std::vector<std::array<double, 4>>& ks,
                      std::vector<SpanEnds>& ends, SpiroChordwiseSystem& out, int& bad_span) {
    const int S = static_cast<int>(C.length.size());
    ends.resize(static_cast<std::size_t>(S));
    for (int i = 0; i < S; ++i)
        if (!span_ends(ks[static_cast<std::size_t>(i)], C.length[static_cast<std::size_t>(i)],
                       ends[static_cast<std::size_t>(i)])) {
            bad_span = i;
            return false;
        }
    out.f.resize(4 * S);
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(static_cast<std::size_t>(32 * S));
    int row = 0;
    // Open: κ_n' = κ_n'' = 0 at an end, linear in k (the start's rows first and the end's last, so
    // that J is banded in the order of the spans).
    const auto end_rows = [&](int end) {
        const int span = end == 0 ? 0 : S - 1;
        const double e = end == 0 ? -0.5 : 0.5;
        for (int d = 1; d <= 2; ++d) {
            double v = 0.0;
            for (int m = 0; m < 4; ++m) {
                v += ks[static_cast<std::size_t>(span)][static_cast<std::size_t>(m)] * coefficient(d, m, e);
                if (coefficient(d, m, e) != 0.0) t.emplace_back(row, 4 * span + m, coefficient(d, m, e));
            }
            out.f(row++) = v;
        }
    };
    if (!closed) end_rows(0);
    // G4 at each joint between span a and span b (closed: also the seam).
    const int joints = closed ? S : S - 1;
    for (int j = 0; j < joints; ++j) {
        const int a = j, b = (j + 1) % S;
        const SpanEnds &A = ends[static_cast<std::size_t>(a)], &B = ends[static_cast<std::size_t>(b)];
        const double phi_b = (closed && b == 0) ? C.closing_angle : C.angle[static_cast<std::size_t>(b)];
        const double scale = 0.5 * (C.length[static_cast<std::size_t>(a)] + C.length[static_cast<std::size_t>(b)]);
        for (int q = 0; q < 4; ++q) {
            const double s = q == 0 ? 1.0 : std::pow(scale, q);
            const double va = A.value[1][q] + (q == 0 ? C.angle[static_cast<std::size_t>(a)] : 0.0),
                         vb = B.value[0][q] + (q == 0 ? phi_b : 0.0);
            // The tangent angles agree modulo 2π, as in libspiro: a span may wind once more than
            // the polygon's bend says (the loops Spiro draws at sharp turns).
            out.f(row) = q == 0 ? std::remainder(va - vb, kTwoPi) : s * (va - vb);
            for (int m = 0; m < 4; ++m) {
                t.emplace_back(row, 4 * a + m, s * A.gradient[1][q][m]);
                t.emplace_back(row, 4 * b + m, -s * B.gradient[0][q][m]);
            }
            ++row;
        }
    }
    if (!closed) end_rows(1);
    out.jacobian.resize(4 * S, 4 * S);
    out.jacobian.setFromTriplets(t.begin(), t.end());
    return true;
}

}  // namespace

SpiroChordwiseSystem spiro_chordwise_system(const PointList& points, bool closed,
                                            const std::vector<std::array<double, 4>>& ks) {
    const std::string who = "intrinsic::spiro_chordwise_system";
    const Chords C = chords_of(points, closed, who);
    if (ks.size() != C.length.size())
        fail_input(who, "needs one row of ks per span (" + std::to_string(C.length.size()) + "), got " +
                            std::to_string(ks.size()));
    for (const auto& k : ks)
        for (double v : k)
            if (!std::isfinite(v)) fail_input(who, "curvature coefficient " + full_precision(v) + " is not finite");
    std::vector<SpanEnds> ends;
    SpiroChordwiseSystem out;
    int bad = -1;
    if (!chordwise_system(C, closed, ks, ends, out, bad))
        fail_input(who, "the spiral of span " + std::to_string(bad) + " closes on itself (its chord is 0)");
    return out;
}

SpiroChordwiseSolution solve_spiro_chordwise(const PointList& points, bool closed, int max_iterations) {
    const Chords C = chords_of(points, closed, "intrinsic::solve_spiro_chordwise");
    const int S = static_cast<int>(C.length.size());
    SpiroChordwiseSolution sol;
    sol.turns = C.turns;
    sol.ks.assign(static_cast<std::size_t>(S), {0.0, 0.0, 0.0, 0.0});
    std::vector<SpanEnds> ends;
    SpiroChordwiseSystem sys;
    // J is banded in span order (closed: with the seam's corner), so the natural column order
    // keeps LU's fill in the band; COLAMD cost three times as much at 2·10^5 points. An open
    // curve's band (5 sub- and 5 superdiagonals) goes to LAPACK's banded LU where the build has
    // it: 4·10^5 unknowns factorised in tens of milliseconds, not a second.
    numeric::BandedOrSparseLu lu(numeric::ColumnOrdering::natural);
    bool analysed = false;
    double last_step = 0.0;
    for (int it = 0;; ++it) {
        int bad = -1;
        if (!chordwise_system(C, closed, sol.ks, ends, sys, bad)) {
            sol.outcome = {Status::no_convergence, "chordwise spiro Newton: the spiral of span " + std::to_string(bad) +
                                                       " closes on itself at iteration " + std::to_string(it)};
            return sol;
        }
        sol.iterations = it;
        sol.residual = sys.f.lpNorm<Eigen::Infinity>();
        if (!std::isfinite(sol.residual)) {
            sol.outcome = {Status::no_convergence,
                           "chordwise spiro Newton: non-finite residual at iteration " + std::to_string(it)};
            return sol;
        }
        if (sol.residual <= kChordwiseTolerance || (it > 0 && last_step <= kChordwiseSettledStep)) break;
        if (it == max_iterations) {
            sol.outcome = {Status::no_convergence, "chordwise spiro Newton did not converge in " +
                                                       std::to_string(max_iterations) +
                                                       " iterations (‖f‖∞ = " + full_precision(sol.residual) + ")"};
            return sol;
        }
        if (!analysed) {  // the pattern depends on the span count alone
            analysed = true;
            std::vector<int> natural(static_cast<std::size_t>(4 * S));
            for (int i = 0; i < 4 * S; ++i) natural[static_cast<std::size_t>(i)] = i;
            lu.analyze(sys.jacobian, natural, natural, kMaxBandStorageRows);
        }
        if (!lu.factorize(sys.jacobian)) {
            sol.outcome = {Status::no_convergence,
                           "chordwise spiro Newton: singular Jacobian at iteration " + std::to_string(it)};
            return sol;
        }
        const Eigen::VectorXd delta = lu.solve(sys.f);
        last_step = delta.lpNorm<Eigen::Infinity>();
        double largest = 0.0;
        for (int i = 0; i < S; ++i) {
            auto& k = sol.ks[static_cast<std::size_t>(i)];
            for (int m = 0; m < 4; ++m) {
                k[static_cast<std::size_t>(m)] -= delta(4 * i + m);
                largest = std::max(largest, std::abs(k[static_cast<std::size_t>(m)]));
            }
            // Levien's iteration keeps each span's mean turning k0 in [−2π, 2π]: the angles agree
            // modulo 2π, and a span that has wound a full turn further is the same curve.
            k[0] = 2.0 * std::remainder(0.5 * k[0], kTwoPi);
        }
        if (!(largest <= kLargestCoefficient)) {
            sol.outcome = {Status::no_convergence, "chordwise spiro Newton diverged at iteration " +
                                                       std::to_string(it) + " (a curvature coefficient reached " +
                                                       full_precision(largest) + ")"};
            return sol;
        }
    }
    // ψ made continuous: each span starts where the one before it ends (not at its chord's angle
    // modulo 2π), so a closed curve's turning number is that of the solution.
    double psi = C.angle.front() + ends.front().value[0][0];
    for (int i = 0; i < S; ++i) {
        const SpanEnds& E = ends[static_cast<std::size_t>(i)];
        sol.arc_lengths.push_back(E.length);
        sol.start_angles.push_back(psi);
        psi += E.value[1][0] - E.value[0][0];
    }
    if (closed) sol.turns = static_cast<int>(std::lround((psi - sol.start_angles.front()) / kTwoPi));
    return sol;
}

Eigen::VectorXd spiro_unknowns(const CurvatureProfileProblem& problem, const SpiroChordwiseSolution& chordwise) {
    const std::string who = "intrinsic::spiro_unknowns";
    const KnotLayout& L = problem.layout;
    const int S = L.segments(), p = L.degree();
    if (!chordwise.outcome.ok() || static_cast<int>(chordwise.arc_lengths.size()) != S || p != 4)
        fail_input(who, "needs a converged chordwise solution with one span per segment of a degree-4 layout");
    const TangentAngleSpline shape(L, chordwise.arc_lengths, Eigen::VectorXd::Zero(L.ordinates()));
    Eigen::VectorXd ordinates = Eigen::VectorXd::Zero(L.ordinates()), count = Eigen::VectorXd::Zero(L.ordinates());
    const Eigen::Matrix<double, 5, 4>& M = ordinates_of_coefficients();
    for (int j = 0; j < S; ++j) {
        const auto& k = chordwise.ks[static_cast<std::size_t>(j)];
        Eigen::Matrix<double, 5, 1> b = M * Eigen::Vector4d(k[0], k[1], k[2], k[3]);
        b.array() += chordwise.start_angles[static_cast<std::size_t>(j)] - b(0);  // ψ at the span's start
        double u[8];
        shape.local_farin_knots_into(j, u);
        const double l = chordwise.arc_lengths[static_cast<std::size_t>(j)];
        const int first = L.last_knot_of_breakpoint(j) - p + 1;
        for (int m = 0; m <= p; ++m) {
            // The de Boor ordinate c_m is the blossom of ψ_j at the knots u_m..u_{m+p−1}.
            Eigen::Matrix<double, 5, 1> d = b;
            for (int level = 1; level <= p; ++level) {
                const double x = u[m + level - 1] / l;
                for (int r = 0; r + level <= p; ++r) d(r) = (1.0 - x) * d(r) + x * d(r + 1);
            }
            ordinates(first + m) += d(0);
            count(first + m) += 1.0;
        }
    }
    Eigen::VectorXd out(L.independent_lengths() + L.ordinates());
    for (int j = 0; j < S; ++j) out(L.length_index(j)) = chordwise.arc_lengths[static_cast<std::size_t>(j)];
    out.tail(L.ordinates()) = ordinates.cwiseQuotient(count);
    return out;
}

SpiroSolution solve_spiro(const PointList& points, bool closed) {
    SpiroSolution out{spiro_problem(points, closed), {}, solve_spiro_chordwise(points, closed)};
    if (!out.chordwise.outcome.ok()) {
        out.solution.outcome = out.chordwise.outcome;
        return out;
    }
    // A closed solution that does not turn (a figure eight) has no arc-length form here: turns = 0
    // means "the polygon's orientation" to the design problem.
    if (closed && out.chordwise.turns == 0) {
        out.solution.outcome = {Status::no_convergence,
                                "the chordwise solution closes with turning number 0 (a figure eight), which the "
                                "arc-length form does not take"};
        return out;
    }
    if (closed) out.problem.turns = out.chordwise.turns;  // both formulations close alike
    NewtonOptions options;
    // Spiro's loops wind ψ through tens of radians over spans of many chord lengths, and the
    // interpolation rows' rounding floor grows with both: 1.5e−12 of the chord was measured on a
    // seeded polygon whose chordwise solution met its equations to 4e−15. A tenfold margin.
    options.tolerance = kArcLengthTolerance;
    out.solution = solve_curvature_profile_auto(out.problem, spiro_unknowns(out.problem, out.chordwise), options);
    return out;
}

SpiroSolution solve_spiro_from(const PointList& points, bool closed, const Eigen::VectorXd& start,
                               double required_contraction) {
    if (!closed) {
        SpiroSolution out{spiro_problem(points, closed), {}, {}};
        if (start.size() == design_unknowns(out.problem)) {
            NewtonOptions options;
            options.tolerance = kArcLengthTolerance;
            options.required_contraction = required_contraction;
            out.solution = solve_curvature_profile_auto(out.problem, start, options);
            if (out.solution.outcome.ok() && out.solution.curve) return out;
        }
    }
    return solve_spiro(points, closed);
}

}  // namespace cagd::intrinsic
