#include "cagd/compare/truth_benchmark.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

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
// The observed order comes from the largest this many sizes: the smaller ones are before the
// asymptotic regime (cubic-b on the closed ellipse: a fit over n = 6..96 gave 3.2, the pair
// 192/384 gives 4.0; on the nonuniform closed trefoil the fit over 96..384 gave 4.4, the pairs
// 96/192, 192/384, 384/768 give 4.6, 4.1, 4.0).
constexpr int kFittedSizes = 2;

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

// The truth parameter nearest to q, from the guess t, within [lo, hi].
double project(const Curve& truth, const Eigen::VectorXd& q, double t, double lo, double hi) {
    for (int it = 0; it < kProjectionIterations; ++it) {
        const Eigen::MatrixXd j = truth.jet(t, 2);
        const Eigen::VectorXd d = j.row(0).transpose() - q, d1 = j.row(1).transpose(), d2 = j.row(2).transpose();
        const double g = d.dot(d1), dg = d1.dot(d1) + d.dot(d2);
        if (!(dg > 0)) break;
        const double next = std::clamp(t - g / dg, lo, hi);
        if (std::abs(next - t) <= 1e-15 * (hi - lo)) return next;
        t = next;
    }
    return t;
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
    for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
        const double u0 = nodes[k], u1 = nodes[k + 1];
        // κ's sign also at the span's ends (one-sided): a sign change between the last Gauss node and
        // the point (3 % of the span from it) is counted too.
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
    static const numeric::GaussLegendreRule rule(kNodesPerSpan);
    const Curve& c = *in.curve;
    const double L = sample.length;
    TruthErrors e;
    double l2 = 0.0, arc = 0.0;
    for (std::size_t k = 0; k + 1 < nodes; ++k) {
        const double u0 = in.node_parameters[k], u1 = in.node_parameters[k + 1];
        const double t0 = sample.params[k], t1 = sample.params[k + 1];
        for (int q = 0; q < rule.size(); ++q) {
            const double f = 0.5 * (rule.nodes()[static_cast<std::size_t>(q)] + 1.0),
                         w = 0.5 * rule.weights()[static_cast<std::size_t>(q)];
            const double u = u0 + f * (u1 - u0);
            const Eigen::MatrixXd jc = c.jet(u, 2);
            const Eigen::VectorXd point = jc.row(0).transpose();
            const double t = project(truth, point, t0 + f * (t1 - t0), sample.t_first, sample.t_last);
            const Eigen::MatrixXd jt = truth.jet(t, 2);
            e.distance = std::max(e.distance, (point - jt.row(0).transpose()).norm() / L);
            e.tangent_angle = std::max(e.tangent_angle, angle_between(jc.row(1).transpose(), jt.row(1).transpose()));
            const double dk = std::abs(kappa(jc) - kappa(jt)) * L;
            e.curvature_max = std::max(e.curvature_max, dk);
            const double ds = w * (u1 - u0) * jc.row(1).norm();
            l2 += dk * dk * ds;
            arc += ds;
        }
    }
    e.curvature_l2 = std::sqrt(l2 / arc);
    e.length = std::abs(analysis::arc_length(c, kLengthPieces) - L) / L;
    return e;
}

std::optional<double> extensionality(const methods::Configuration& configuration, const PointList& points, bool closed,
                                     const methods::Interpolant& in) {
    const char* who = "compare::extensionality";
    const std::vector<double>& u = in.node_parameters;
    if (u.size() < 2 || u.size() != static_cast<std::size_t>(points.rows()) + (closed ? 1 : 0))
        fail_input(who, "the interpolant has " + std::to_string(u.size()) + " nodes for " +
                            std::to_string(points.rows()) + (closed ? " closed" : " open") + " points");
    const std::size_t k = (u.size() - 1) / 2;  // the middle span
    const double middle = 0.5 * (u[k] + u[k + 1]);
    PointList more(points.rows() + 1, points.cols());
    const auto before = static_cast<Eigen::Index>(k + 1);
    more.topRows(before) = points.topRows(before);
    more.row(before) = in.curve->jet(middle, 0).row(0);
    more.bottomRows(points.rows() - before) = points.bottomRows(points.rows() - before);
    methods::InterpolationResult again;
    try {
        again = methods::interpolate(configuration, more, closed);
    } catch (const InvalidInput&) {
        return std::nullopt;
    }
    if (!again.outcome.ok() || !again.interpolant) return std::nullopt;
    // The old curve as the truth: its parameters at the n + 1 points, its whole stretch.
    TruthSample old{.points = more,
                    .params = u,
                    .t_first = in.curve->t_min(),
                    .t_last = in.curve->t_max(),
                    .length = analysis::arc_length(*in.curve, kLengthPieces),
                    .closed = closed};
    old.params.insert(old.params.begin() + static_cast<std::ptrdiff_t>(k + 1), middle);
    return truth_errors(*again.interpolant, old, *in.curve).distance;
}

std::vector<TruthRun> run_truth_benchmark(const TruthBenchmarkOptions& o) {
    const char* who = "compare::run_truth_benchmark";
    if (o.sizes.empty()) fail_input(who, "needs at least one size");
    for (int n : o.sizes)
        if (n < 3 || n > 100000) fail_input(who, "size " + std::to_string(n) + " outside 3..100000");
    std::vector<const TruthFamily*> families;
    for (const std::string& name : o.families) families.push_back(&find_truth_family(name));
    if (o.families.empty())
        for (const TruthFamily& f : truth_families()) families.push_back(&f);
    std::vector<methods::Configuration> configurations;
    for (const std::string& name : o.methods) configurations.push_back(methods::find_configuration(name));
    if (o.methods.empty()) configurations = methods::configurations();
    struct Case {
        const TruthFamily* family;
        TruthSpacing spacing;
        bool closed;
        int n;
    };
    std::vector<Case> cases;
    for (const TruthFamily* f : families)
        for (bool closed : {true, false}) {
            if (closed && !f->closed) continue;
            for (TruthSpacing s : {TruthSpacing::uniform, TruthSpacing::nonuniform})
                for (int n : o.sizes) cases.push_back({f, s, closed, n});
        }
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
        const Case& c = cases[static_cast<std::size_t>(k)];
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
        const Case& k = cases[static_cast<std::size_t>(index) / configurations.size()];
        const TruthSample& sample = samples[static_cast<std::size_t>(index) / configurations.size()];
        const methods::Configuration& m = configurations[static_cast<std::size_t>(index) % configurations.size()];
        TruthRun& r = runs[static_cast<std::size_t>(index)];
        r.family = k.family->name, r.spacing = k.spacing, r.closed = k.closed, r.n = k.n, r.method = m.name;
        r.truth_shape = truth_shapes[static_cast<std::size_t>(index) / configurations.size()];
        InterpolationAttempt attempt = attempt_interpolation(m, sample.points, k.closed);
        r.status = attempt.status;
        r.note = attempt.note;
        if (attempt.status != AttemptStatus::ok) return;
        const methods::InterpolationResult& result = attempt.result;
        r.errors = truth_errors(*result.interpolant, sample, *k.family->curve);
        r.shape = shape_measures(*result.interpolant->curve, result.interpolant->node_parameters, k.closed);
        r.extensionality = extensionality(m, sample.points, k.closed, *result.interpolant);
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
        const std::vector<const TruthRun*>& g = groups[k];
        if (std::any_of(g.begin(), g.end(), [](const TruthRun* r) { return r->status != AttemptStatus::ok; })) continue;
        for (int measure = 0; measure < static_cast<int>(truth_error_names().size()); ++measure) {
            ConvergenceOrder c;
            c.family = std::get<0>(k), c.spacing = static_cast<TruthSpacing>(std::get<1>(k)), c.closed = std::get<2>(k),
            c.method = std::get<3>(k);
            c.measure = truth_error_names()[static_cast<std::size_t>(measure)];
            // The largest kFittedSizes sizes above the exact level, in decreasing n.
            std::vector<const TruthRun*> by_size(g.begin(), g.end());
            std::stable_sort(by_size.begin(), by_size.end(),
                             [](const TruthRun* a, const TruthRun* b) { return a->n > b->n; });
            double sx = 0, sy = 0, sxx = 0, sxy = 0;
            int count = 0, above = 0;
            for (const TruthRun* r : by_size) {
                const double e = truth_error(r->errors, measure);
                if (e <= truth_exact_level(r->n)) continue;
                ++above;
                if (count == kFittedSizes) continue;
                const double x = std::log(static_cast<double>(r->n)), y = std::log(e);
                sx += x, sy += y, sxx += x * x, sxy += x * y, ++count;
            }
            c.sizes_fitted = count;
            c.exact = above == 0;
            if (count == kFittedSizes) c.order = -(count * sxy - sx * sy) / (count * sxx - sx * sx);
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
    return {"family", "spacing",      "closed",    "method",  "measure", "order",
            "exact",  "sizes_fitted", "predicted", "verdict", "source"};
}

namespace {

std::string verdict(const ConvergenceOrder& c) {
    if (!c.predicted) return "measured";
    if (c.exact) return "holds (exact)";
    if (!c.order) return "not measurable";
    return std::abs(*c.order - *c.predicted) <= kPredictedOrderTolerance ? "holds" : "fails";
}

std::string order_text(const ConvergenceOrder& c) {
    if (c.exact) return "exact";
    if (!c.order) return "-";
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(2);
    s << *c.order;
    return s.str();
}

}  // namespace

std::vector<std::vector<std::string>> convergence_orders_rows(const std::vector<ConvergenceOrder>& orders) {
    std::vector<std::vector<std::string>> rows;
    for (const ConvergenceOrder& c : orders)
        rows.push_back({c.family, to_string(c.spacing), c.closed ? "1" : "0", c.method, c.measure,
                        c.order ? format_number(*c.order, 4) : "", c.exact ? "1" : "0", std::to_string(c.sizes_fitted),
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
           << "; errors dimensionless (see the notes above); order = observed order of the distance over n = ";
        std::vector<int> sizes;
        for (const TruthRun& r : runs)
            if (r.family == f.name && std::find(sizes.begin(), sizes.end(), r.n) == sizes.end()) sizes.push_back(r.n);
        for (std::size_t i = 0; i < sizes.size(); ++i) md << (i ? ", " : "") << sizes[i];
        md << ".\n\n| rank | method | distance | order | tangent angle | curvature max | curvature L2 | length "
              "|\n|---:|---|---:|---:|---:|---:|---:|---:|\n";
        int rank = 0;
        for (const TruthRun* r : rows) {
            if (r->status != AttemptStatus::ok) {
                md << "| — | `" << r->method << "` | " << to_string(r->status) << " | | | | | |\n";
                continue;
            }
            const ConvergenceOrder* o = find_order(*r, "distance");
            md << "| " << ++rank << " | `" << r->method << "` | " << number(r->errors.distance) << " | "
               << (o ? order_text(*o) : "-") << " | " << number(r->errors.tangent_angle) << " | "
               << number(r->errors.curvature_max) << " | " << number(r->errors.curvature_l2) << " | "
               << number(r->errors.length) << " |\n";
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
    md << "\n#### Exact reproduction\n\nA method reproduces a curve when its distance is at most "
       << format_number(kTruthExactLevelPerPoint, 2) << " × n"
       << " at every size and spacing (closed where the curve is closed):\n\n| family | methods |\n|---|---|\n";
    for (const char* name : {"line", "circle", "clothoid"}) {
        std::vector<std::string> exact;
        std::map<std::string, bool> all;
        for (const ConvergenceOrder& c : orders)
            if (c.family == name && c.measure == "distance" && c.closed == find_truth_family(name).closed) {
                if (!all.count(c.method)) all[c.method] = true, exact.push_back(c.method);
                all[c.method] = all[c.method] && c.exact;
            }
        std::string list;
        for (const std::string& m : exact)
            if (all[m]) list += (list.empty() ? "`" : ", `") + m + "`";
        md << "| " << name << " | " << (list.empty() ? "none" : list) << " |\n";
    }
    md << "\n#### Predicted orders\n\nWhere a theorem predicts the order of convergence, the observed order must be "
          "within "
       << kPredictedOrderTolerance
       << " of it:\n\n| method | family | spacing | closed | measure | predicted | observed | verdict | source "
          "|\n|---|---|---|---|---|---:|---:|---|---|\n";
    for (const ConvergenceOrder& c : orders)
        if (c.predicted)
            md << "| `" << c.method << "` | " << c.family << " | " << to_string(c.spacing) << " | "
               << (c.closed ? "yes" : "no") << " | " << c.measure << " | " << format_number(*c.predicted, 3) << " | "
               << order_text(c) << " | " << verdict(c) << " | " << c.source << " |\n";
    return md.str();
}

}  // namespace cagd::compare
