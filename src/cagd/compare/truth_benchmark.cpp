#include "cagd/compare/truth_benchmark.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>

#include <boost/math/tools/minima.hpp>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/frenet_jet.hpp"
#include "cagd/compare/interpolation_attempt.hpp"
#include "cagd/compare/method_comparison.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/parallel.hpp"
#include "cagd/numeric/gauss_legendre.hpp"

namespace cagd::compare {

namespace {

constexpr int kNodesPerSpan = 16;
// The leaderboard's shape table is for this many points.
constexpr int kShapeTableSize = 24;
// The interpolant's length: 20-point Gauss–Legendre on this many sub-pieces of every piece (the
// tests hold it to adaptive Gauss–Kronrod, which is too slow to run on every case).
constexpr int kLengthPieces = 4;
constexpr int kProjectionIterations = 30;
// κ of a jet (signed for planar curves, |κ| in space); NaN at a point of zero speed.
double kappa(const Eigen::MatrixXd& jet) { return analysis::frenet_jet(jet.bottomRows(jet.rows() - 1)).curvature; }

double angle_between(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    const double dot = a.dot(b);
    double cross = 0.0;
    if (a.size() == 2)
        cross = std::abs(a(0) * b(1) - a(1) * b(0));
    else
        cross = Eigen::Vector3d(a).cross(Eigen::Vector3d(b)).norm();
    return std::atan2(cross, dot);
}

// The projection's bracket: the truth sampled at this many equal parameter steps per data span.
constexpr int kBracketSamples = 8;
// The curvature's L2 per piece: 16-point Gauss–Legendre, accepted where the 8-point rule on the same
// piece agrees with it to kL2Tolerance of it or to an absolute ρ² × the piece's chord (ρ the
// curvature's rounding level, truth_rounding_level: below that the integrand is rounding), and
// otherwise the piece halved, at most kL2MaxDepth times (where the projection onto the truth jumps,
// |Δκ| does too). The 8-point estimate is the cruder, so the accepted 16-point value is more
// accurate than the agreement. (Boost's adaptive Gauss–Kronrod misjudges its error on the short,
// nearly constant pieces a B-spline peer's knots cut beside the nodes: 10^6 evaluations each.)
constexpr double kL2Tolerance = 1e-6;
constexpr int kL2MaxDepth = 10;
// The maxima: the pieces with the largest sampled maxima, this many, are refined.
constexpr std::size_t kRefinedPieces = 4;
// Brent locates the maximiser to 2^-kRefineBits of its bracket (two sample steps of one piece): the
// value, quadratic in that error near a smooth maximum, to about 2^-40 of it.
constexpr int kRefineBits = 20;

// The nearest point of the truth to points of an interpolant on data span k (TruthErrors): the
// truth sampled at kBracketSamples steps per span over the spans k − 1 … k + 1 (wrapping round a
// closed sample), the nearest sample bracketing Newton on (T(t) − q)·T'(t) = 0 between its
// neighbours. Global over those three spans; Newton stops at a step of 1e−15 of the stretch.
class TruthProjector {
public:
    TruthProjector(const Curve& truth, const TruthSample& sample) : truth_(truth), sample_(sample) {
        const std::size_t spans = sample.params.size() - 1;
        grid_.resize(static_cast<Eigen::Index>(spans * kBracketSamples + 1), truth.dimension());
        for (std::size_t k = 0; k < spans; ++k)
            for (int i = 0; i < kBracketSamples; ++i)
                grid_.row(static_cast<Eigen::Index>(k * kBracketSamples + static_cast<std::size_t>(i))) =
                    truth.jet(grid_parameter(k * kBracketSamples + static_cast<std::size_t>(i)), 0).row(0);
        grid_.row(grid_.rows() - 1) = truth.jet(sample.params.back(), 0).row(0);
    }
    // The truth parameter nearest to q, for a point of data span k.
    double nearest(const Eigen::VectorXd& q, std::size_t k) const {
        const long spans = static_cast<long>(sample_.params.size()) - 1, S = kBracketSamples;
        const long first = sample_.closed ? static_cast<long>(k) - 1 : std::max(0L, static_cast<long>(k) - 1),
                   last = sample_.closed ? static_cast<long>(k) + 1 : std::min(spans - 1, static_cast<long>(k) + 1);
        long best = 0;
        double best_distance = std::numeric_limits<double>::infinity();
        const long rows = static_cast<long>(grid_.rows()) - 1, dim = static_cast<long>(grid_.cols());
        long w = wrap_index(first * S);  // the grid row of unwrapped index g, stepped along without a division
        for (long g = first * S; g <= (last + 1) * S; ++g, w = sample_.closed && w + 1 == rows ? 0 : w + 1) {
            const double* row = grid_.data() + w * dim;
            double d = 0.0;
            for (long i = 0; i < dim; ++i) d += (row[i] - q(i)) * (row[i] - q(i));
            if (d < best_distance) best_distance = d, best = g;
        }
        const double lo = unwrapped_parameter(sample_.closed ? best - 1 : std::max(best - 1, 0L)),
                     hi = unwrapped_parameter(sample_.closed ? best + 1 : std::min(best + 1, spans * S));
        double t = unwrapped_parameter(best);
        for (int it = 0; it < kProjectionIterations; ++it) {
            const Eigen::MatrixXd j = jet(t, 2);
            const Eigen::VectorXd d = j.row(0).transpose() - q, d1 = j.row(1).transpose(), d2 = j.row(2).transpose();
            const double g = d.dot(d1), dg = d1.dot(d1) + d.dot(d2);
            if (!(dg > 0)) break;
            const double next = std::clamp(t - g / dg, lo, hi);
            if (std::abs(next - t) <= 1e-15 * (sample_.t_last - sample_.t_first)) return wrap(next);
            t = next;
        }
        return wrap(t);
    }
    // The truth's jet at a parameter of its sample's stretch (a closed sample's taken modulo its period).
    Eigen::MatrixXd jet(double t, int order) const { return truth_.jet(wrap(t), order); }

private:
    double grid_parameter(std::size_t g) const {
        const std::size_t k = g / kBracketSamples, i = g % kBracketSamples;
        const double t0 = sample_.params[k], t1 = sample_.params[k + 1];
        return i == 0 ? t0 : t0 + static_cast<double>(i) / kBracketSamples * (t1 - t0);
    }
    long wrap_index(long g) const {
        const long n = static_cast<long>(grid_.rows()) - 1;
        return sample_.closed ? ((g % n) + n) % n : g;
    }
    double unwrapped_parameter(long g) const {
        const long n = static_cast<long>(grid_.rows()) - 1;
        const double period = sample_.t_last - sample_.t_first;
        const long w = wrap_index(g);
        return grid_parameter(static_cast<std::size_t>(w)) +
               (sample_.closed ? static_cast<double>((g - w) / n) * period : 0.0);
    }
    double wrap(double t) const {
        if (!sample_.closed) return std::clamp(t, sample_.t_first, sample_.t_last);
        const double period = sample_.t_last - sample_.t_first;
        double r = std::fmod(t - sample_.t_first, period);
        if (r < 0) r += period;
        return sample_.t_first + r;
    }
    const Curve& truth_;
    const TruthSample& sample_;
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> grid_;  // a row per sample
};

// The pieces of [u0, u1] between the curve's breakpoints `br` (ascending) strictly inside it.
std::vector<double> piece_ends(const std::vector<double>& br, double u0, double u1) {
    std::vector<double> ends{u0};
    for (auto it = std::upper_bound(br.begin(), br.end(), u0); it != br.end() && *it < u1; ++it) ends.push_back(*it);
    ends.push_back(u1);
    return ends;
}

// The largest of f over [lo, hi] by Brent's method, and never below `sampled`, the largest sample's value.
double refined_maximum(const std::function<double(double)>& f, double lo, double hi, double sampled) {
    if (!(hi > lo)) return sampled;
    const auto [x, minus] = boost::math::tools::brent_find_minima([&](double v) { return -f(v); }, lo, hi, kRefineBits);
    (void)x;
    return std::max(sampled, -minus);
}

// A turn of the polygon (the sine of its angle) counts as none below this: collinear points.
constexpr double kStraightTurn = 1e-12;

}  // namespace

const std::vector<std::string>& shape_measure_names() {
    static const std::vector<std::string> names{"bending",   "variation",   "max_curvature",        "curvature_extrema",
                                                "g2_defect", "inflections", "unimplied_inflections"};
    return names;
}

ShapeMeasures shape_measures(const Curve& c, const std::vector<double>& nodes, bool closed) {
    if (nodes.size() < 2)
        fail_input("compare::shape_measures", "needs at least two nodes, got " + std::to_string(nodes.size()));
    static const numeric::GaussLegendreRule rule(kNodesPerSpan);
    double length = 0.0, bending = 0.0, variation = 0.0, max_kappa = 0.0;
    std::vector<double> rates, kappas;
    const std::vector<double> breakpoints = c.breakpoints();
    for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
        // Per piece between the curve's breakpoints (κ' may jump there), with κ also at the piece's
        // ends (one-sided): for its largest value (a natural end's), and a sign change between the
        // last Gauss node and the end (3 % of the piece from it) is counted too.
        const std::vector<double> ends = piece_ends(breakpoints, nodes[k], nodes[k + 1]);
        for (std::size_t p = 0; p + 1 < ends.size(); ++p) {
            const double u0 = ends[p], u1 = ends[p + 1];
            kappas.push_back(kappa(c.jet(u0, 2)));
            for (int q = 0; q < rule.size(); ++q) {
                const double u = u0 + 0.5 * (rule.nodes()[static_cast<std::size_t>(q)] + 1.0) * (u1 - u0);
                const Eigen::MatrixXd j = c.jet(u, 3);
                const analysis::FrenetJet f = analysis::frenet_jet(j.bottomRows(3));
                const double kappa = f.curvature, rate = f.curvature_rate;
                const double ds = 0.5 * rule.weights()[static_cast<std::size_t>(q)] * (u1 - u0) * j.row(1).norm();
                length += ds, bending += kappa * kappa * ds, variation += rate * rate * ds;
                max_kappa = std::max(max_kappa, std::abs(kappa));
                rates.push_back(rate);
                kappas.push_back(kappa);
            }
            kappas.push_back(kappa(c.jet_from_left(u1, 2)));
            max_kappa =
                std::max({max_kappa, std::abs(kappas.back()), std::abs(kappas[kappas.size() - 2 - rule.size()])});
        }
    }
    ShapeMeasures m;
    m.bending = length * bending;
    m.variation = length * length * length * variation;
    m.max_curvature = max_kappa * length;
    std::vector<int> rate_signs;
    for (double r : rates) rate_signs.push_back(analysis::curvature_rate_sign(r, length));
    m.curvature_extrema = analysis::sign_changes(rate_signs, closed);
    if (c.dimension() == 2) {
        std::vector<int> curve_signs, turn_signs;
        // (A point of zero speed at a span's end has no κ: no sign.)
        for (double k : kappas) curve_signs.push_back(analysis::curvature_sign(k, length));
        // The polygon through the curve's points at the nodes (closed: the last node is the first point).
        const std::size_t points = closed ? nodes.size() - 1 : nodes.size();
        std::vector<Eigen::Vector2d> p;
        for (std::size_t i = 0; i < points; ++i) p.emplace_back(c.jet(nodes[i], 0).row(0).transpose());
        for (std::size_t i = closed ? 0 : 1; i < (closed ? points : points - 1); ++i) {
            const Eigen::Vector2d a = p[i] - p[(i + points - 1) % points], b = p[(i + 1) % points] - p[i];
            const double turn = (a(0) * b(1) - a(1) * b(0)) / (a.norm() * b.norm());
            turn_signs.push_back(std::abs(turn) <= kStraightTurn ? 0 : (turn > 0 ? 1 : -1));
        }
        m.inflections = analysis::sign_changes(curve_signs, closed);
        m.unimplied_inflections = std::max(0, m.inflections - analysis::sign_changes(turn_signs, closed));
    }
    const std::size_t count = nodes.size();
    for (std::size_t i = closed ? 0 : 1; i + 1 < count; ++i) {
        const double left = kappa(i == 0 ? c.jet_from_left(nodes.back(), 2) : c.jet_from_left(nodes[i], 2)),
                     right = kappa(c.jet(nodes[i], 2));
        m.g2_defect = std::max(m.g2_defect, std::abs(left - right) * length);
    }
    return m;
}

std::string inflections_text(const ShapeMeasures& s, bool space) {
    if (space) return "—";
    return std::to_string(s.inflections) +
           (s.unimplied_inflections > 0 ? " (+" + std::to_string(s.unimplied_inflections) + ")" : "");
}

const std::vector<std::string>& truth_error_names() {
    static const std::vector<std::string> names{"distance", "tangent_angle", "curvature_max", "curvature_l2", "length"};
    return names;
}

double truth_error(const TruthErrors& e, int index) {
    switch (index) {
        case 0: return e.distance;
        case 1: return e.tangent_angle;
        case 2: return e.curvature_max;
        case 3: return e.curvature_l2;
        case 4: return e.length;
        default: fail_input("compare::truth_error", "measure index " + std::to_string(index) + " outside 0..4");
    }
}

TruthErrors truth_errors(const methods::Interpolant& in, const TruthSample& sample, const Curve& truth) {
    const char* who = "compare::truth_errors";
    const std::size_t nodes = in.node_parameters.size();
    if (nodes != sample.params.size())
        fail_input(who, "the interpolant has " + std::to_string(nodes) + " nodes, the sample " +
                            std::to_string(sample.params.size()));
    static const numeric::GaussLegendreRule fine_rule(kNodesPerSpan), coarse_rule(kNodesPerSpan / 2);
    const Curve& c = *in.curve;
    const double L = sample.length;
    const TruthProjector projector(truth, sample);
    const std::vector<double> breakpoints = c.breakpoints();
    // The distance (÷ L) and |Δκ|·L at u on span k, from the piece that starts (right) or ends there.
    struct Local {
        double distance, angle, curvature, speed;
    };
    const auto local = [&](double u, std::size_t k, JetSide side) {
        const Eigen::MatrixXd jc = side == JetSide::left ? c.jet_from_left(u, 2) : c.jet(u, 2);
        const Eigen::VectorXd point = jc.row(0).transpose();
        const Eigen::MatrixXd jt = projector.jet(projector.nearest(point, k), 2);
        return Local{(point - jt.row(0).transpose()).norm() / L,
                     angle_between(jc.row(1).transpose(), jt.row(1).transpose()), std::abs(kappa(jc) - kappa(jt)) * L,
                     jc.row(1).norm()};
    };
    // Per piece, the sampled maxima of the distance and the curvature error, and the brackets
    // (the neighbouring samples) for their refinement.
    struct Candidate {
        std::size_t span;
        double lo, hi, sampled;
    };
    std::vector<Candidate> distance_candidates, curvature_candidates;
    TruthErrors e;
    double l2 = 0.0;
    std::vector<std::pair<double, Local>> samples;
    for (std::size_t k = 0; k + 1 < nodes; ++k) {
        const std::vector<double> ends = piece_ends(breakpoints, in.node_parameters[k], in.node_parameters[k + 1]);
        for (std::size_t p = 0; p + 1 < ends.size(); ++p) {
            const double a = ends[p], b = ends[p + 1];
            // The piece's ends (one-sided), and every node the adaptive Gauss–Legendre rules of the
            // curvature's L2 evaluate: the samples of the maxima, in increasing u.
            samples.assign({{a, local(a, k, JetSide::right)}, {b, local(b, k, JetSide::left)}});
            const double rounding = truth_rounding_level(2, static_cast<int>(nodes));
            const auto integrand = [&](double u) {
                const Local v = local(u, k, JetSide::right);
                samples.emplace_back(u, v);
                return v.curvature * v.curvature * v.speed;
            };
            const std::function<double(double, double, int)> adaptive = [&](double lo, double hi, int depth) {
                const double fine = fine_rule.integrate(integrand, lo, hi),
                             coarse = coarse_rule.integrate(integrand, lo, hi);
                const double chord = (c.jet(hi, 0).row(0) - c.jet(lo, 0).row(0)).norm();
                if (depth == kL2MaxDepth ||
                    std::abs(fine - coarse) <= std::max(kL2Tolerance * std::abs(fine), rounding * rounding * chord))
                    return fine;
                const double mid = 0.5 * (lo + hi);
                return adaptive(lo, mid, depth + 1) + adaptive(mid, hi, depth + 1);
            };
            l2 += adaptive(a, b, 0);
            std::sort(samples.begin(), samples.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
            std::vector<double> at(samples.size());
            std::vector<Local> values(samples.size());
            for (std::size_t i = 0; i < samples.size(); ++i) at[i] = samples[i].first, values[i] = samples[i].second;
            std::size_t best_distance = 0, best_curvature = 0;
            for (std::size_t i = 0; i < at.size(); ++i) {
                e.tangent_angle = std::max(e.tangent_angle, values[i].angle);
                if (values[i].distance > values[best_distance].distance) best_distance = i;
                if (values[i].curvature > values[best_curvature].curvature) best_curvature = i;
            }
            const auto bracket = [&](std::size_t i, double sampled) {
                return Candidate{k, at[i == 0 ? 0 : i - 1], at[std::min(i + 1, at.size() - 1)], sampled};
            };
            distance_candidates.push_back(bracket(best_distance, values[best_distance].distance));
            curvature_candidates.push_back(bracket(best_curvature, values[best_curvature].curvature));
            e.distance = std::max(e.distance, values[best_distance].distance);
            e.curvature_max = std::max(e.curvature_max, values[best_curvature].curvature);
        }
    }
    // The suprema: the kRefinedPieces pieces of the largest sampled maxima, each refined by Brent's
    // method between the samples beside its largest (inside the piece: one-sided at its end).
    const auto refine = [&](std::vector<Candidate>& candidates, double& largest, double Local::*field) {
        const std::size_t count = std::min(kRefinedPieces, candidates.size());
        std::partial_sort(candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(count), candidates.end(),
                          [](const Candidate& x, const Candidate& y) { return x.sampled > y.sampled; });
        for (std::size_t i = 0; i < count; ++i) {
            const Candidate& cand = candidates[i];
            const double hi = cand.hi;
            const auto f = [&](double u) {
                return local(u, cand.span, u == hi ? JetSide::left : JetSide::right).*field;
            };
            largest = std::max(largest, refined_maximum(f, cand.lo, hi, cand.sampled));
        }
    };
    refine(distance_candidates, e.distance, &Local::distance);
    refine(curvature_candidates, e.curvature_max, &Local::curvature);
    e.curvature_l2 = std::sqrt(l2 / L);
    e.length = std::abs(analysis::arc_length(c, kLengthPieces) - L) / L;
    return e;
}

ExtendedPoints extended_points(const PointList& points, bool closed, const methods::Interpolant& in) {
    const char* who = "compare::extended_points";
    const std::vector<double>& u = in.node_parameters;
    if (u.size() < 2 || u.size() != static_cast<std::size_t>(points.rows()) + (closed ? 1 : 0))
        fail_input(who, "the interpolant has " + std::to_string(u.size()) + " nodes for " +
                            std::to_string(points.rows()) + (closed ? " closed" : " open") + " points");
    ExtendedPoints e;
    e.span = (u.size() - 1) / 2;  // the middle span
    e.parameter = 0.5 * (u[e.span] + u[e.span + 1]);
    e.points.resize(points.rows() + 1, points.cols());
    const auto before = static_cast<Eigen::Index>(e.span + 1);
    e.points.topRows(before) = points.topRows(before);
    e.points.row(before) = in.curve->jet(e.parameter, 0).row(0);
    e.points.bottomRows(points.rows() - before) = points.bottomRows(points.rows() - before);
    return e;
}

double extension_distance(const methods::Interpolant& in, const ExtendedPoints& extended, bool closed,
                          const methods::Interpolant& again) {
    // The old curve as the truth: its parameters at the n + 1 points, its whole stretch.
    TruthSample old{.points = extended.points,
                    .params = in.node_parameters,
                    .t_first = in.curve->t_min(),
                    .t_last = in.curve->t_max(),
                    .length = analysis::arc_length(*in.curve, kLengthPieces),
                    .closed = closed};
    old.params.insert(old.params.begin() + static_cast<std::ptrdiff_t>(extended.span + 1), extended.parameter);
    return truth_errors(again, old, *in.curve).distance;
}

std::optional<double> extensionality(const methods::Configuration& configuration, const PointList& points, bool closed,
                                     const methods::Interpolant& in) {
    const ExtendedPoints more = extended_points(points, closed, in);
    methods::InterpolationResult again;
    try {
        again = methods::interpolate(configuration, more.points, closed);
    } catch (const InvalidInput&) {
        return std::nullopt;
    }
    if (!again.outcome.ok() || !again.interpolant) return std::nullopt;
    return extension_distance(in, more, closed, *again.interpolant);
}

void measure_truth_run(TruthRun& r, const methods::Interpolant& in, const TruthSample& sample, const Curve& truth,
                       std::optional<double> extension) {
    r.errors = truth_errors(in, sample, truth);
    r.shape = shape_measures(*in.curve, in.node_parameters, r.closed);
    r.extensionality = extension;
    bool finite = std::isfinite(r.shape.bending) && std::isfinite(r.shape.variation) &&
                  std::isfinite(r.shape.max_curvature) && std::isfinite(r.shape.g2_defect);
    for (int e = 0; e < 5; ++e) finite = finite && std::isfinite(truth_error(r.errors, e));
    if (!finite) {  // a node of zero speed: κ undefined there
        r.status = AttemptStatus::cusp;
        r.note = "the curve has a point of zero speed, where its curvature is undefined";
        r.errors = {};
        r.shape = {};
        r.extensionality.reset();
    }
}

void check_truth_sizes(const std::vector<int>& sizes, const char* who) {
    if (sizes.empty()) fail_input(who, "needs at least one size");
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        const int n = sizes[i];
        if (n < 3 || n > 100000) fail_input(who, "size " + std::to_string(n) + " outside 3..100000");
        if (i > 0 && !(n > sizes[i - 1]))  // an order needs two different sizes, in the order given
            fail_input(who, "size " + std::to_string(n) + " after " + std::to_string(sizes[i - 1]) +
                                "; the sizes must increase");
    }
}

std::vector<TruthCase> truth_cases(const std::vector<const TruthFamily*>& families,
                                   const std::vector<TruthSpacing>& spacings, const std::vector<int>& sizes) {
    std::vector<TruthCase> cases;
    for (const TruthFamily* f : families)
        for (bool closed : {true, false}) {
            if (closed && !f->closed) continue;
            for (TruthSpacing s : spacings)
                for (int n : sizes) cases.push_back({.family = f, .spacing = s, .closed = closed, .n = n});
        }
    return cases;
}

std::vector<TruthRun> run_truth_benchmark(const TruthBenchmarkOptions& o) {
    const char* who = "compare::run_truth_benchmark";
    check_truth_sizes(o.sizes, who);
    std::vector<const TruthFamily*> families;
    for (const std::string& name : o.families) families.push_back(&find_truth_family(name));
    if (o.families.empty())
        for (const TruthFamily& f : truth_families()) families.push_back(&f);
    std::vector<methods::Configuration> configurations;
    for (const std::string& name : o.methods) configurations.push_back(methods::find_configuration(name));
    if (o.methods.empty()) configurations = methods::configurations();
    const std::vector<TruthCase> cases =
        truth_cases(families, {TruthSpacing::uniform, TruthSpacing::nonuniform}, o.sizes);
    const int threads = o.threads > 0 ? o.threads : hardware_threads();
    // The samples of each case once (t(s) by adaptive quadrature of the truth), shared by the methods.
    std::vector<TruthSample> samples(cases.size());
    std::vector<ShapeMeasures> truth_shapes(cases.size());
    check_work_share(o.share, who);
    const auto case_needed = [&](long k) {  // a case some run of the share needs
        for (std::size_t m = 0; m < configurations.size(); ++m)
            if (o.share.owns(k * static_cast<long>(configurations.size()) + static_cast<long>(m))) return true;
        return false;
    };
    parallel_for(static_cast<long>(cases.size()), threads, [&](long k) {
        if (!case_needed(k)) return;
        const TruthCase& c = cases[static_cast<std::size_t>(k)];
        samples[static_cast<std::size_t>(k)] = truth_samples(*c.family, c.n, c.spacing, c.closed);
        truth_shapes[static_cast<std::size_t>(k)] =
            shape_measures(*c.family->curve, samples[static_cast<std::size_t>(k)].params, c.closed);
    });
    std::vector<TruthRun> runs(cases.size() * configurations.size());
    // The shared tables (the pseudo-spline's) are loaded once, before the workers start.
    for (const methods::Configuration& m : configurations)
        for (int d : {2, 3})
            if (m.method->prepare && m.claims.max_dimension >= d) m.method->prepare(m.values, d);
    parallel_for(static_cast<long>(runs.size()), threads, [&](long index) {
        if (!o.share.owns(index)) return;
        const TruthCase& k = cases[static_cast<std::size_t>(index) / configurations.size()];
        const TruthSample& sample = samples[static_cast<std::size_t>(index) / configurations.size()];
        const methods::Configuration& m = configurations[static_cast<std::size_t>(index) % configurations.size()];
        TruthRun& r = runs[static_cast<std::size_t>(index)];
        r.family = k.family->name, r.spacing = k.spacing, r.closed = k.closed, r.n = k.n, r.method = m.name;
        r.truth_shape = truth_shapes[static_cast<std::size_t>(index) / configurations.size()];
        InterpolationAttempt attempt = attempt_interpolation(m, sample.points, k.closed);
        r.status = attempt.status;
        r.note = attempt.note;
        if (attempt.status != AttemptStatus::ok) return;
        const methods::Interpolant& in = *attempt.result.interpolant;
        measure_truth_run(r, in, sample, *k.family->curve, extensionality(m, sample.points, k.closed, in));
    });
    return runs;
}

const std::vector<PredictedOrder>& predicted_orders() {
    static const std::vector<PredictedOrder> p{
        {"cubic-b", "distance", true, 4.0,
         "M. S. Floater, Chordal cubic spline interpolation is fourth order accurate, IMA J. Numer. Anal. 26 (2006) "
         "25-33 (closed: no end conditions)"},
        {"cubic-b", "distance", false, 2.0,
         "C. de Boor, A Practical Guide to Splines (1978), ch. IV: natural end conditions force zero curvature at the "
         "ends, an O(h^2) error there"},
    };
    return p;
}

double truth_rounding_level(int measure, int n) {
    const double level = 64.0 * std::numeric_limits<double>::epsilon();
    return measure == 0 ? level : measure == 2 || measure == 3 ? level * n * n : level * n;
}

double truth_solver_level(int measure, int n) {
    const double per_span = 1e-13 * n;
    return measure == 2 || measure == 3 ? per_span * n : per_span;
}

bool iterative_configuration(const std::string& name) {
    for (const methods::Configuration& c : methods::configurations())
        if (c.name == name) return c.method->iterative;
    return false;
}

double truth_error_floor(const std::string& method, int measure, int n) {
    const double rounding = truth_rounding_level(measure, n);
    return iterative_configuration(method) ? std::max(rounding, truth_solver_level(measure, n)) : rounding;
}

const char* to_string(OrderRegime regime) {
    switch (regime) {
        case OrderRegime::asymptotic: return "asymptotic";
        case OrderRegime::pre_asymptotic: return "pre-asymptotic";
        case OrderRegime::exact: return "exact";
        case OrderRegime::solver_level: return "solver tolerance";
        case OrderRegime::none: return "none";
    }
    return "?";
}

std::vector<ConvergenceOrder> convergence_orders(const std::vector<TruthRun>& runs) {
    // Group the runs of one (family, spacing, closed, method) by size, in the runs' order.
    using Key = std::tuple<std::string, int, bool, std::string>;
    std::vector<Key> order_of_keys;
    std::map<Key, std::vector<const TruthRun*>> groups;
    for (const TruthRun& r : runs) {
        const Key k{r.family, static_cast<int>(r.spacing), r.closed, r.method};
        if (!groups.count(k)) order_of_keys.push_back(k);
        groups[k].push_back(&r);
    }
    std::vector<ConvergenceOrder> out;
    for (const Key& k : order_of_keys) {
        std::vector<const TruthRun*> by_size = groups[k];
        if (std::any_of(by_size.begin(), by_size.end(),
                        [](const TruthRun* r) { return r->status != AttemptStatus::ok; }))
            continue;
        std::stable_sort(by_size.begin(), by_size.end(),
                         [](const TruthRun* a, const TruthRun* b) { return a->n < b->n; });
        const bool iterative = iterative_configuration(std::get<3>(k));
        for (int measure = 0; measure < static_cast<int>(truth_error_names().size()); ++measure) {
            ConvergenceOrder c;
            c.family = std::get<0>(k), c.spacing = static_cast<TruthSpacing>(std::get<1>(k)), c.closed = std::get<2>(k),
            c.method = std::get<3>(k);
            c.measure = truth_error_names()[static_cast<std::size_t>(measure)];
            bool all_rounding = true, all_floor = true;
            for (std::size_t i = 0; i < by_size.size(); ++i) {
                const int n = by_size[i]->n;
                const double e = truth_error(by_size[i]->errors, measure), rounding = truth_rounding_level(measure, n);
                all_rounding = all_rounding && e <= rounding;
                all_floor = all_floor && e <= truth_error_floor(c.method, measure, n);
                if (i + 1 == by_size.size()) break;
                const int n1 = by_size[i + 1]->n;
                const double e1 = truth_error(by_size[i + 1]->errors, measure);
                if (e > rounding && e1 > truth_rounding_level(measure, n1) && n1 > n)
                    c.pairs.push_back({n, n1, -std::log(e1 / e) / std::log(static_cast<double>(n1) / n)});
            }
            if (!iterative && all_rounding)
                c.regime = OrderRegime::exact;
            else if (iterative && all_floor)
                c.regime = OrderRegime::solver_level;
            else if (!c.pairs.empty()) {
                c.order = c.pairs.back().order;
                c.regime = c.pairs.size() >= 2 &&
                                   std::abs(c.pairs.back().order - c.pairs[c.pairs.size() - 2].order) <= kAsymptoticBand
                               ? OrderRegime::asymptotic
                               : OrderRegime::pre_asymptotic;
            }
            for (const PredictedOrder& p : predicted_orders())
                if (p.method == c.method && p.measure == c.measure && p.closed == c.closed)
                    c.predicted = p.order, c.source = p.source;
            out.push_back(c);
        }
    }
    return out;
}

std::vector<std::string> truth_runs_header() {
    std::vector<std::string> h{"family", "spacing", "closed", "n", "method", "status"};
    for (const std::string& m : truth_error_names()) h.push_back(m);
    for (const std::string& m : shape_measure_names()) h.push_back(m);
    h.push_back("extensionality");
    for (const std::string& m : shape_measure_names()) h.push_back("truth_" + m);
    h.push_back("note");
    return h;
}

std::vector<std::vector<std::string>> truth_runs_rows(const std::vector<TruthRun>& runs, int digits) {
    std::vector<std::vector<std::string>> rows;
    for (const TruthRun& r : runs) {
        std::vector<std::string> row{r.family, to_string(r.spacing), r.closed ? "1" : "0", std::to_string(r.n),
                                     r.method, to_string(r.status)};
        for (int m = 0; m < 5; ++m)
            row.push_back(r.status == AttemptStatus::ok ? format_number(truth_error(r.errors, m), digits) : "");
        const auto shape = [&](const ShapeMeasures& s, bool shown) {
            for (const double v :
                 {s.bending, s.variation, s.max_curvature, static_cast<double>(s.curvature_extrema), s.g2_defect,
                  static_cast<double>(s.inflections), static_cast<double>(s.unimplied_inflections)})
                row.push_back(shown ? format_number(v, digits) : "");
        };
        shape(r.shape, r.status == AttemptStatus::ok);
        row.push_back(r.status == AttemptStatus::ok && r.extensionality ? format_number(*r.extensionality, digits)
                                                                        : "");
        shape(r.truth_shape, true);
        std::string note = r.note;
        std::replace(note.begin(), note.end(), '\n', ' ');
        row.push_back(note);
        rows.push_back(row);
    }
    return rows;
}

std::vector<std::string> convergence_orders_header() {
    return {"family", "spacing", "closed",    "method",  "measure", "order",
            "regime", "pairs",   "predicted", "verdict", "source"};
}

namespace {

std::string verdict(const ConvergenceOrder& c) {
    if (!c.predicted) return "measured";
    if (c.regime == OrderRegime::exact) return "holds (exact)";
    if (!c.order) return "not measurable";
    if (c.regime != OrderRegime::asymptotic) return "not asymptotic";
    return std::abs(*c.order - *c.predicted) <= kPredictedOrderTolerance ? "holds" : "fails";
}

std::string fixed2(double v) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(2);
    s << v;
    return s.str();
}

// The leaderboard's order: the value, "(p)" when pre-asymptotic, or the regime.
std::string order_text(const ConvergenceOrder& c) {
    switch (c.regime) {
        case OrderRegime::exact: return "exact";
        case OrderRegime::solver_level: return "solver tol.";
        case OrderRegime::asymptotic: return fixed2(*c.order);
        case OrderRegime::pre_asymptotic: return "(" + fixed2(*c.order) + ")";
        case OrderRegime::none: break;
    }
    return "-";
}

std::string pairs_text(const ConvergenceOrder& c) {
    std::string t;
    for (const PairOrder& p : c.pairs)
        (t += t.empty() ? "" : ";") +=
            std::to_string(p.n0) + "/" + std::to_string(p.n1) + ":" + format_number(p.order, 4);
    return t;
}

}  // namespace

std::vector<std::vector<std::string>> convergence_orders_rows(const std::vector<ConvergenceOrder>& orders) {
    std::vector<std::vector<std::string>> rows;
    for (const ConvergenceOrder& c : orders)
        rows.push_back({c.family, to_string(c.spacing), c.closed ? "1" : "0", c.method, c.measure,
                        c.order ? format_number(*c.order, 4) : "", to_string(c.regime), pairs_text(c),
                        c.predicted ? format_number(*c.predicted, 3) : "", verdict(c), c.source});
    return rows;
}

std::string truth_leaderboard_markdown(const std::vector<TruthRun>& runs, const std::vector<ConvergenceOrder>& orders) {
    std::ostringstream md;
    const auto number = [](double v) { return format_number(v, 3); };
    const auto find_order = [&](const TruthRun& r, const std::string& measure) -> const ConvergenceOrder* {
        for (const ConvergenceOrder& c : orders)
            if (c.family == r.family && c.spacing == r.spacing && c.closed == r.closed && c.method == r.method &&
                c.measure == measure)
                return &c;
        return nullptr;
    };
    for (const TruthFamily& f : truth_families()) {
        int largest = 0;
        for (const TruthRun& r : runs)
            if (r.family == f.name) largest = std::max(largest, r.n);
        if (largest == 0) continue;
        std::vector<const TruthRun*> rows;
        for (const TruthRun& r : runs)
            if (r.family == f.name && r.n == largest && r.spacing == TruthSpacing::uniform && r.closed == f.closed)
                rows.push_back(&r);
        std::stable_sort(rows.begin(), rows.end(), [](const TruthRun* a, const TruthRun* b) {
            if ((a->status == AttemptStatus::ok) != (b->status == AttemptStatus::ok))
                return a->status == AttemptStatus::ok;
            return a->status == AttemptStatus::ok && a->errors.distance < b->errors.distance;
        });
        md << "\n#### " << f.name << ": " << f.description << "\n\n"
           << largest << " points uniform in arc length" << (f.closed ? ", closed" : "")
           << "; errors dimensionless (see the notes above); distances within the rounding level (64 ε; "
              "an iterative method's: its solver level, 1e−13 n) of the row above share its rank; order = the "
              "distance's order from the last pair of successive sizes, in parentheses when the pair before "
              "disagrees by more than "
           << kAsymptoticBand << " (pre-asymptotic), over n = ";
        std::vector<int> sizes;
        for (const TruthRun& r : runs)
            if (r.family == f.name && std::find(sizes.begin(), sizes.end(), r.n) == sizes.end()) sizes.push_back(r.n);
        for (std::size_t i = 0; i < sizes.size(); ++i) md << (i ? ", " : "") << sizes[i];
        md << ".\n\n| rank | method | distance | order | tangent angle | curvature max | curvature L2 | length "
              "|\n|---:|---|---:|---:|---:|---:|---:|---:|\n";
        // Competition ranking with ties: a distance within the larger floor (truth_error_floor) of the
        // row above it shares that row's rank.
        int rank = 0, position = 0;
        double previous = 0.0, previous_floor = 0.0;
        for (const TruthRun* r : rows) {
            if (r->status != AttemptStatus::ok) {
                md << "| — | `" << r->method << "` | " << to_string(r->status) << " | | | | | |\n";
                continue;
            }
            const double floor = truth_error_floor(r->method, 0, r->n);
            ++position;
            if (position == 1 || r->errors.distance - previous > std::max(floor, previous_floor)) rank = position;
            previous = r->errors.distance, previous_floor = floor;
            const ConvergenceOrder* o = find_order(*r, "distance");
            md << "| " << rank << " | `" << r->method << "` | " << number(r->errors.distance) << " | "
               << (o ? order_text(*o) : "-") << " | " << number(r->errors.tangent_angle) << " | "
               << number(r->errors.curvature_max) << " | " << number(r->errors.curvature_l2) << " | "
               << number(r->errors.length) << " |\n";
        }
        // The behaviour that decides a peer's rank, beside its row, with what it does here.
        for (const TruthRun* r : rows)
            if (r->method == "boost-catmull-rom" && !r->closed && r->status == AttemptStatus::ok) {
                const ConvergenceOrder* o = find_order(*r, "distance");
                md << "\n`boost-catmull-rom`: Boost closes an open curve's end tangents round the other end (ghost "
                      "points P_{n−1} before P_0 and P_0, P_1 after P_{n−1}; docs/methods.md): here the distance's "
                      "order is "
                   << (o ? order_text(*o) : "-") << " and the tangent-angle error " << number(r->errors.tangent_angle)
                   << " rad.\n";
            }
        for (const TruthRun* r : rows)
            if (r->method == "occt-interpolate" && r->closed && r->status == AttemptStatus::ok) {
                const ConvergenceOrder* o = find_order(*r, "distance");
                md << "\n`occt-interpolate`: OpenCASCADE's periodic interpolation is C1 where the curve closes, at its "
                      "first point (C2 elsewhere; docs/methods.md): here the distance's order is "
                   << (o ? order_text(*o) : "-") << " and the curvature error " << number(r->errors.curvature_max);
                for (const TruthRun& s : runs)
                    if (s.family == f.name && s.n == kShapeTableSize && s.spacing == TruthSpacing::uniform &&
                        s.closed && s.method == r->method && s.status == AttemptStatus::ok)
                        md << "; at " << kShapeTableSize << " points its G2 defect (the largest curvature jump × L) is "
                           << number(s.shape.g2_defect);
                md << ".\n";
            }
        // The shape at a size where the methods still differ visibly, beside the truth's.
        std::vector<const TruthRun*> shaped;
        for (const TruthRun* r : rows)
            for (const TruthRun& s : runs)
                if (s.family == f.name && s.n == kShapeTableSize && s.spacing == TruthSpacing::uniform &&
                    s.closed == f.closed && s.method == r->method && s.status == AttemptStatus::ok)
                    shaped.push_back(&s);
        if (shaped.empty()) continue;
        const auto shape_row = [&](const std::string& name, const ShapeMeasures& s, const std::string& extension) {
            md << "| " << name << " | " << number(s.bending) << " | " << number(s.variation) << " | "
               << number(s.max_curvature) << " | " << s.curvature_extrema << " | " << number(s.g2_defect) << " | "
               << inflections_text(s, f.dimension == 3) << " | " << extension << " |\n";
        };
        md << "\nShape at " << kShapeTableSize
           << " points (scale-free: L∫κ² ds, L³∫κ'² ds, max |κ|·L, sign changes of κ', the largest curvature jump at a "
              "point × L; "
           << "inflections: sign changes of κ, (+u): u of them not implied by the polygon through the points; "
           << "extension: how far the curve moves, ÷ L, when a point taken on it is added):\n\n"
           << "| | bending | variation | max κ·L | κ extrema | G2 defect | inflections | extension "
              "|\n|---|---:|---:|---:|---:|---:|---:|---:|\n";
        shape_row("**truth**", shaped.front()->truth_shape, "—");
        for (const TruthRun* s : shaped)
            shape_row("`" + s->method + "`", s->shape, s->extensionality ? number(*s->extensionality) : "no curve");
    }
    // Exact reproduction: every size at rounding level, in both spacings.
    md << "\n#### Exact reproduction\n\nA direct method reproduces a curve when its distance is at its rounding "
          "level, 64 ε, at every size and spacing (closed where the curve is closed); an iterative method's "
          "distance at its solver level, 1e−13 n, is listed as such:\n\n| family | methods |\n|---|---|\n";
    for (const char* name : {"line", "circle", "clothoid"}) {
        std::vector<std::string> exact;
        std::map<std::string, bool> all, solver;
        for (const ConvergenceOrder& c : orders)
            if (c.family == name && c.measure == "distance" && c.closed == find_truth_family(name).closed) {
                if (!all.count(c.method)) all[c.method] = true, exact.push_back(c.method);
                all[c.method] =
                    all[c.method] && (c.regime == OrderRegime::exact || c.regime == OrderRegime::solver_level);
                if (c.regime == OrderRegime::solver_level) solver[c.method] = true;
            }
        std::string list;
        for (const std::string& m : exact)
            if (all[m]) list += (list.empty() ? "`" : ", `") + m + "`" + (solver[m] ? " (solver tolerance)" : "");
        md << "| " << name << " | " << (list.empty() ? "none" : list) << " |\n";
    }
    md << "\n#### Predicted orders\n\nWhere a theorem predicts the order of convergence, the observed order must be "
          "within "
       << kPredictedOrderTolerance << " of it, where it is asymptotic (its last two pairs within " << kAsymptoticBand
       << "):\n\n| method | family | spacing | closed | measure | predicted | observed | verdict | source "
          "|\n|---|---|---|---|---|---:|---:|---|---|\n";
    for (const ConvergenceOrder& c : orders)
        if (c.predicted)
            md << "| `" << c.method << "` | " << c.family << " | " << to_string(c.spacing) << " | "
               << (c.closed ? "yes" : "no") << " | " << c.measure << " | " << format_number(*c.predicted, 3) << " | "
               << order_text(c) << " | " << verdict(c) << " | " << c.source << " |\n";
    return md.str();
}

}  // namespace cagd::compare
