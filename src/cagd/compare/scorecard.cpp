#include "cagd/compare/scorecard.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>

#include "cagd/analysis/frenet_jet.hpp"
#include "cagd/compare/locality_footprint.hpp"
#include "cagd/compare/truth_benchmark.hpp"
#include "cagd/core/csv.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/core/parallel.hpp"

namespace cagd::compare {

namespace {

constexpr int kSamplesPerSpan = 32;  // 33 fractions per span, the ends included
constexpr double kDegree = std::numbers::pi / 180.0;
// The largest turning angles' bins of the existence rates: [30°, 50°), …, [150°, 170°].
constexpr double kFirstTurn = 30.0, kTurnBin = 20.0;
constexpr int kTurnBins = 7;

double uniform(std::mt19937& rng, double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }

// The seeded maps of one case: the similarity and the moved point's direction (see the header).
struct CaseMoves {
    double scale = 1.0;
    Eigen::MatrixXd rotation;
    Eigen::RowVectorXd shift, direction;
};

Eigen::RowVectorXd unit_vector(std::mt19937& rng, long dimension) {
    const double phi = uniform(rng, 0.0, 2.0 * std::numbers::pi);
    Eigen::RowVectorXd v(dimension);
    if (dimension == 2) {
        v << std::cos(phi), std::sin(phi);
    } else {
        const double z = uniform(rng, -1.0, 1.0), r = std::sqrt(1.0 - z * z);
        v << r * std::cos(phi), r * std::sin(phi), z;
    }
    return v;
}

CaseMoves case_moves(unsigned seed, long dimension) {
    std::mt19937 rng(seed ^ 0x9e3779b9u);  // apart from the polygon's own stream
    CaseMoves m;
    m.scale = std::pow(10.0, uniform(rng, -6.0, 6.0));
    const double angle = uniform(rng, 0.0, 2.0 * std::numbers::pi);
    if (dimension == 2) {
        m.rotation = Eigen::Rotation2Dd(angle).toRotationMatrix();
    } else {
        const Eigen::RowVectorXd axis = unit_vector(rng, 3);
        m.rotation = Eigen::AngleAxisd(angle, Eigen::Vector3d(axis(0), axis(1), axis(2))).toRotationMatrix();
    }
    m.shift.resize(dimension);
    for (long c = 0; c < dimension; ++c) m.shift(c) = m.scale * uniform(rng, -10.0, 10.0);
    m.direction = unit_vector(rng, dimension);
    return m;
}

// q = s R p + t, row by row.
PointList similar(const PointList& p, const CaseMoves& m) {
    return ((m.scale * p * m.rotation.transpose()).rowwise() + m.shift).eval();
}
// The inverse map of similar.
Eigen::MatrixXd similar_back(const Eigen::MatrixXd& q, const CaseMoves& m) {
    return ((q.rowwise() - m.shift) * m.rotation / m.scale).eval();
}

double largest_row_distance(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    return (a - b).rowwise().norm().maxCoeff();
}

// The spans of an interpolant.
long spans_of(const methods::Interpolant& in) { return static_cast<long>(in.node_parameters.size()) - 1; }

// Span distance of span k from point j (the two spans beside it 0), open or around a closed curve.
long span_distance(long k, long j, long spans, bool closed) {
    if (!closed) return k < j ? j - 1 - k : k - j;
    const long left = ((j - 1 - k) % spans + spans) % spans, right = ((k - j) % spans + spans) % spans;
    return std::min(left, right);
}

// Spans whose largest sampled |κ| lies strictly inside (see the header).
int inner_curvature_maxima(const methods::Interpolant& in, double extent) {
    int inner = 0;
    std::array<double, kSamplesPerSpan + 1> k{};
    for (long span = 0; span < spans_of(in); ++span) {
        for (int j = 0; j <= kSamplesPerSpan; ++j) {
            const double t =
                span_parameter(in, static_cast<std::size_t>(span), static_cast<double>(j) / kSamplesPerSpan);
            const Eigen::MatrixXd jet = j == kSamplesPerSpan ? in.curve->jet_from_left(t, 2) : in.curve->jet(t, 2);
            k[static_cast<std::size_t>(j)] = std::abs(analysis::frenet_jet(jet.bottomRows(2)).curvature) * extent;
        }
        const double ends = std::max(k.front(), k.back());
        const double inside = *std::max_element(k.begin() + 1, k.end() - 1);
        if (inside > ends + analysis::kFlatCurvature) ++inner;
    }
    return inner;
}

// The scores of one case from its curves (see the header); `again` the extended curve.
CaseScore measure_case(const PointList& points, bool closed, const CaseMoves& moves, const DrawnCurve& base,
                       const DrawnCurve& reversed, const DrawnCurve& moved, const DrawnCurve& transformed,
                       const ExtendedPoints* extended, const DrawnCurve* again) {
    CaseScore s{.status = base.status, .note = base.note};
    if (base.status != AttemptStatus::ok) return s;
    try {
        const methods::Interpolant& in = *base.interpolant;
        const double extent = bounding_box_diagonal(points);
        const long spans = spans_of(in);
        const Eigen::MatrixXd samples = span_samples(in, kSamplesPerSpan);
        const long per = kSamplesPerSpan + 1;
        if (reversed.interpolant && spans_of(*reversed.interpolant) == spans) {
            const Eigen::MatrixXd r = span_samples(*reversed.interpolant, kSamplesPerSpan);
            Eigen::MatrixXd mirrored(r.rows(), r.cols());
            for (long k = 0; k < spans; ++k) {
                const long m = !closed ? spans - 1 - k : (k == spans - 1 ? k : spans - 2 - k);
                for (long j = 0; j < per; ++j) mirrored.row(k * per + j) = r.row(m * per + (per - 1 - j));
            }
            s.symmetry = largest_row_distance(samples, mirrored) / extent;
        }
        if (transformed.interpolant && spans_of(*transformed.interpolant) == spans)
            s.similarity = largest_row_distance(
                               samples, similar_back(span_samples(*transformed.interpolant, kSamplesPerSpan), moves)) /
                           extent;
        if (moved.interpolant && spans_of(*moved.interpolant) == spans) {
            const double delta = kLocalityMove * extent;
            const std::vector<double> d =
                span_displacements(samples, span_samples(*moved.interpolant, kSamplesPerSpan), kSamplesPerSpan);
            const long j = points.rows() / 2;
            int zero = 0;
            for (long k = 0; k < spans; ++k) {
                const double moved_by = d[static_cast<std::size_t>(k)];
                if (moved_by <= kZeroInfluence * extent) ++zero;
                const auto r = static_cast<std::size_t>(span_distance(k, j, spans, closed));
                if (s.influence.size() <= r) s.influence.resize(r + 1, 0.0);
                s.influence[r] = std::max(s.influence[r], moved_by / delta);
            }
            s.zero_influence_spans = zero;
            s.spans_moved = static_cast<int>(spans) - zero;
        }
        s.inner_curvature_maxima = inner_curvature_maxima(in, extent);
        const ShapeMeasures shape = shape_measures(*in.curve, in.node_parameters, closed);
        if (std::isfinite(shape.bending) && std::isfinite(shape.variation)) {
            s.bending = shape.bending;
            s.variation = shape.variation;
            s.g2_defect = shape.g2_defect;
        }
        if (extended && again && again->interpolant)
            s.extensionality = extension_distance(in, *extended, closed, *again->interpolant);
    } catch (const std::exception& e) {
        s = CaseScore{.status = AttemptStatus::failed, .note = std::string("measuring the curve: ") + e.what()};
    }
    return s;
}

std::optional<double> radial_error(const DrawnCurve& d) {
    if (!d.interpolant) return std::nullopt;
    const Eigen::MatrixXd samples = span_samples(*d.interpolant, kSamplesPerSpan);
    return (samples.rowwise().norm().array() - 1.0).abs().maxCoeff();
}

}  // namespace

ScorecardPolygon scorecard_polygon(unsigned seed) {
    std::mt19937 rng(seed);
    ScorecardPolygon p;
    p.largest_turn = uniform(rng, 30.0, 170.0) * kDegree;
    std::vector<double> turn(kScorecardPoints - 2);
    for (double& t : turn) t = uniform(rng, -p.largest_turn, p.largest_turn);
    const auto sharp =
        std::min(static_cast<std::size_t>(uniform(rng, 0.0, static_cast<double>(turn.size()))), turn.size() - 1);
    turn[sharp] = uniform(rng, 0.0, 1.0) < 0.5 ? p.largest_turn : -p.largest_turn;
    p.points.resize(kScorecardPoints, 2);
    p.points.row(0) << 0.0, 0.0;
    double heading = 0.0;
    for (int i = 1; i < kScorecardPoints; ++i) {
        if (i >= 2) heading += turn[static_cast<std::size_t>(i - 2)];  // the turn at point i − 1
        const double chord = uniform(rng, 0.5, 1.5);
        p.points.row(i) << p.points(i - 1, 0) + chord * std::cos(heading),
            p.points(i - 1, 1) + chord * std::sin(heading);
    }
    return p;
}

PointList co_circular_points(unsigned seed, bool closed) {
    std::mt19937 rng(seed);
    const int n = 3 + static_cast<int>(seed % 62);
    const double start = uniform(rng, 0.0, 2.0 * std::numbers::pi);
    const double arc = closed ? 2.0 * std::numbers::pi : uniform(rng, 90.0, 300.0) * kDegree;
    const double step = closed ? arc / n : arc / (n - 1);
    PointList p(n, 2);
    for (int i = 0; i < n; ++i) {
        const double jitter = closed || (i > 0 && i < n - 1) ? uniform(rng, -0.3, 0.3) : 0.0;
        const double theta = start + step * (i + jitter);
        p.row(i) << std::cos(theta), std::sin(theta);
    }
    return p;
}

SubjectScores run_scorecard(const CurveSubject& subject, const ScorecardOptions& o) {
    const char* who = "cagd::compare::run_scorecard";
    if (o.polygons < 1) fail_input(who, "polygons " + std::to_string(o.polygons) + " must be at least 1");
    if (o.threads < 0) fail_input(who, "threads " + std::to_string(o.threads) + " must be at least 0");
    const int threads = o.threads > 0 ? o.threads : hardware_threads();
    SubjectScores out{.subject = subject.name, .kind = subject.kind};
    struct Case {
        PointList points;
        bool closed = false;
        CaseMoves moves;
    };
    std::vector<Case> cases;
    for (int s = 0; s < o.polygons; ++s) {
        ScorecardPolygon p = scorecard_polygon(static_cast<unsigned>(s));
        out.largest_turns.push_back(p.largest_turn);
        cases.push_back({std::move(p.points), false, case_moves(static_cast<unsigned>(s), 2)});
    }
    for (std::size_t c = 0; c < o.classic.size(); ++c)
        cases.push_back({o.classic[c].points, o.classic[c].closed,
                         case_moves(static_cast<unsigned>(c), o.classic[c].points.cols())});
    // Round 1: each case's curve, of its reversed points, with a point moved and of its similar
    // points; then the co-circular sets, closed and open.
    std::vector<CurveRequest> first;
    for (const Case& c : cases) {
        first.push_back({c.points, c.closed});
        first.push_back({c.points.colwise().reverse(), c.closed});
        PointList moved = c.points;
        moved.row(c.points.rows() / 2) += kLocalityMove * bounding_box_diagonal(c.points) * c.moves.direction;
        first.push_back({std::move(moved), c.closed});
        first.push_back({similar(c.points, c.moves), c.closed});
    }
    for (int s = 0; s < o.polygons; ++s) {
        first.push_back({co_circular_points(static_cast<unsigned>(s), true), true});
        first.push_back({co_circular_points(static_cast<unsigned>(s), false), false});
    }
    std::vector<DrawnCurve> one = subject.draw(first);
    // A subject answers every request (curve_subject.hpp); anything else is its defect, not bad input.
    if (one.size() != first.size())
        throw std::logic_error(std::string(who) + ": " + subject.name + " drew " + std::to_string(one.size()) +
                               " curves of " + std::to_string(first.size()));
    // Round 2: each drawn case's extension (extensionality).
    std::vector<ExtendedPoints> extended(cases.size());
    std::vector<long> second_of(cases.size(), -1);
    std::vector<CurveRequest> second;
    for (std::size_t c = 0; c < cases.size(); ++c) {
        const DrawnCurve& base = one[4 * c];
        if (!base.interpolant) continue;
        extended[c] = extended_points(cases[c].points, cases[c].closed, *base.interpolant);
        second_of[c] = static_cast<long>(second.size());
        second.push_back({extended[c].points, cases[c].closed});
    }
    const std::vector<DrawnCurve> two = second.empty() ? std::vector<DrawnCurve>{} : subject.draw(second);
    if (two.size() != second.size())
        throw std::logic_error(std::string(who) + ": " + subject.name + " drew " + std::to_string(two.size()) +
                               " curves of " + std::to_string(second.size()));
    std::vector<CaseScore> scores(cases.size());
    parallel_for(static_cast<long>(cases.size()), threads, [&](long k) {
        const auto c = static_cast<std::size_t>(k);
        const DrawnCurve* again = second_of[c] >= 0 ? &two[static_cast<std::size_t>(second_of[c])] : nullptr;
        scores[c] = measure_case(cases[c].points, cases[c].closed, cases[c].moves, one[4 * c], one[4 * c + 1],
                                 one[4 * c + 2], one[4 * c + 3], again ? &extended[c] : nullptr, again);
    });
    out.polygons.assign(scores.begin(), scores.begin() + o.polygons);
    out.classic.assign(scores.begin() + o.polygons, scores.end());
    const std::size_t round_first = 4 * cases.size();
    out.roundness_closed.resize(static_cast<std::size_t>(o.polygons));
    out.roundness_open.resize(static_cast<std::size_t>(o.polygons));
    parallel_for(o.polygons, threads, [&](long s) {
        const auto i = static_cast<std::size_t>(s);
        out.roundness_closed[i] = radial_error(one[round_first + 2 * i]);
        out.roundness_open[i] = radial_error(one[round_first + 2 * i + 1]);
    });
    for (int s = 0; s < o.polygons; ++s) {
        const auto i = static_cast<std::size_t>(s);
        for (auto [from, to] :
             {std::pair{round_first + 2 * i, &out.round_closed}, std::pair{round_first + 2 * i + 1, &out.round_open}})
            to->push_back({.status = one[from].status, .note = one[from].note, .interpolant = std::nullopt});
    }
    return out;
}

namespace {

// The values of an optional member over the cases that have it.
template <class Get>
std::vector<double> gathered(const std::vector<CaseScore>& scores, Get get) {
    std::vector<double> v;
    for (const CaseScore& s : scores)
        if (const auto x = get(s)) v.push_back(static_cast<double>(*x));
    return v;
}

std::vector<double> present(const std::vector<std::optional<double>>& values) {
    std::vector<double> v;
    for (const auto& x : values)
        if (x) v.push_back(*x);
    return v;
}

bool failed(AttemptStatus s) { return s != AttemptStatus::ok && s != AttemptStatus::not_applicable; }

}  // namespace

std::vector<ScorecardRow> scorecard_rows(const SubjectScores& sc) {
    std::vector<ScorecardRow> rows;
    const auto add = [&](const std::string& property, const std::string& quantity, long sets, numeric::Estimate e) {
        rows.push_back({sc.subject, sc.kind, property, quantity, sets, e});
    };
    // median, q95 and the largest of a measure's values.
    const auto spread = [&](const std::string& property, const std::vector<double>& v) {
        if (v.empty()) return;
        const long m = static_cast<long>(v.size());
        add(property, "median", m, numeric::quantile_estimate(v, 0.5));
        add(property, "q95", m, numeric::quantile_estimate(v, 0.95));
        const double largest = *std::max_element(v.begin(), v.end());
        add(property, "max", m, {largest, largest, largest});
    };
    const auto median_and_mean = [&](const std::string& property, const std::vector<double>& v) {
        if (v.empty()) return;
        const long m = static_cast<long>(v.size());
        add(property, "median", m, numeric::quantile_estimate(v, 0.5));
        double sum = 0.0;
        for (double x : v) sum += x;
        add(property, "mean", m,
            {sum / static_cast<double>(m), sum / static_cast<double>(m), sum / static_cast<double>(m)});
    };
    // Existence: the failure rate overall and per bin of the largest turning angle.
    long applicable = 0, failures = 0;
    std::array<long, kTurnBins> bin_sets{}, bin_failures{};
    for (std::size_t s = 0; s < sc.polygons.size(); ++s) {
        if (sc.polygons[s].status == AttemptStatus::not_applicable) continue;
        const bool f = failed(sc.polygons[s].status);
        ++applicable;
        failures += f;
        const auto bin = static_cast<std::size_t>(
            std::clamp(static_cast<int>((sc.largest_turns[s] / kDegree - kFirstTurn) / kTurnBin), 0, kTurnBins - 1));
        ++bin_sets[bin];
        bin_failures[bin] += f;
    }
    if (applicable > 0) {
        add("existence", "rate", applicable, numeric::rate_estimate(failures, applicable));
        for (int b = 0; b < kTurnBins; ++b)
            if (bin_sets[static_cast<std::size_t>(b)] > 0) {
                const int lo = static_cast<int>(kFirstTurn + b * kTurnBin);
                add("existence_" + std::to_string(lo) + "_" + std::to_string(lo + static_cast<int>(kTurnBin)), "rate",
                    bin_sets[static_cast<std::size_t>(b)],
                    numeric::rate_estimate(bin_failures[static_cast<std::size_t>(b)],
                                           bin_sets[static_cast<std::size_t>(b)]));
            }
    }
    spread("roundness_closed", present(sc.roundness_closed));
    spread("roundness_open", present(sc.roundness_open));
    spread("extensionality", gathered(sc.polygons, [](const CaseScore& s) { return s.extensionality; }));
    spread("symmetry", gathered(sc.polygons, [](const CaseScore& s) { return s.symmetry; }));
    spread("similarity", gathered(sc.polygons, [](const CaseScore& s) { return s.similarity; }));
    median_and_mean("spans_moved", gathered(sc.polygons, [](const CaseScore& s) { return s.spans_moved; }));
    median_and_mean("zero_influence_spans",
                    gathered(sc.polygons, [](const CaseScore& s) { return s.zero_influence_spans; }));
    for (std::size_t r = 1; r <= 3; ++r)
        spread("influence_r" + std::to_string(r), gathered(sc.polygons, [r](const CaseScore& s) {
                   return s.influence.size() > r ? std::optional<double>(s.influence[r]) : std::nullopt;
               }));
    const std::vector<double> inner =
        gathered(sc.polygons, [](const CaseScore& s) { return s.inner_curvature_maxima; });
    if (!inner.empty()) {
        const auto with = static_cast<long>(std::count_if(inner.begin(), inner.end(), [](double x) { return x > 0; }));
        add("curvature_maxima_inside", "rate", static_cast<long>(inner.size()),
            numeric::rate_estimate(with, static_cast<long>(inner.size())));
    }
    spread("bending", gathered(sc.polygons, [](const CaseScore& s) { return s.bending; }));
    spread("variation", gathered(sc.polygons, [](const CaseScore& s) { return s.variation; }));
    spread("g2_defect", gathered(sc.polygons, [](const CaseScore& s) { return s.g2_defect; }));
    return rows;
}

std::string scorecard_csv(const std::vector<ScorecardRow>& rows) {
    std::vector<std::vector<std::string>> table;
    for (const ScorecardRow& r : rows)
        table.push_back({r.subject, r.kind, r.property, r.quantity, std::to_string(r.sets),
                         format_number(r.estimate.value, 6), format_number(r.estimate.low, 6),
                         format_number(r.estimate.high, 6)});
    return csv_table({"subject", "kind", "property", "quantity", "sets", "value", "low", "high"}, table);
}

std::string scorecard_classic_csv(const std::vector<SubjectScores>& scores, const std::vector<ClassicDataSet>& sets) {
    const auto number = [](const std::optional<double>& x) { return x ? format_number(*x, 6) : std::string(); };
    const auto count = [](const std::optional<int>& x) { return x ? std::to_string(*x) : std::string(); };
    std::vector<std::vector<std::string>> table;
    for (const SubjectScores& sc : scores)
        for (std::size_t c = 0; c < sc.classic.size() && c < sets.size(); ++c) {
            const CaseScore& s = sc.classic[c];
            table.push_back({sc.subject, sc.kind, sets[c].name, sets[c].closed ? "closed" : "open", to_string(s.status),
                             number(s.extensionality), number(s.symmetry), number(s.similarity), count(s.spans_moved),
                             count(s.zero_influence_spans), count(s.inner_curvature_maxima), number(s.bending),
                             number(s.variation), number(s.g2_defect)});
        }
    return csv_table(
        {"subject", "kind", "data_set", "closed", "status", "extensionality", "symmetry", "similarity", "spans_moved",
         "zero_influence_spans", "inner_curvature_maxima", "bending", "variation", "g2_defect"},
        table);
}

namespace {

using RowKey = std::tuple<std::string, std::string, std::string>;  // subject, property, quantity

std::map<RowKey, const ScorecardRow*> index_rows(const std::vector<ScorecardRow>& rows) {
    std::map<RowKey, const ScorecardRow*> m;
    for (const ScorecardRow& r : rows) m[{r.subject, r.property, r.quantity}] = &r;
    return m;
}

// Three significant digits, without a needless exponent (100, not 1e+02).
std::string short_number(double x) {
    std::ostringstream o;
    o << std::setprecision(3) << x;
    return o.str();
}

// "value [low, high]" of a summary, "—" where there is none.
std::string cell(const std::map<RowKey, const ScorecardRow*>& m, const std::string& subject,
                 const std::string& property, const std::string& quantity, double factor = 1.0) {
    const auto it = m.find({subject, property, quantity});
    if (it == m.end()) return "—";
    const numeric::Estimate& e = it->second->estimate;
    return short_number(factor * e.value) + " [" + short_number(factor * e.low) + ", " + short_number(factor * e.high) +
           "]";
}

std::vector<std::string> subjects_in_order(const std::vector<ScorecardRow>& rows) {
    std::vector<std::string> s;
    for (const ScorecardRow& r : rows)
        if (std::find(s.begin(), s.end(), r.subject) == s.end()) s.push_back(r.subject);
    return s;
}

}  // namespace

std::string scorecard_markdown(const std::vector<ScorecardRow>& rows, int polygons,
                               const std::vector<std::string>& skipped) {
    const auto m = index_rows(rows);
    const std::vector<std::string> subjects = subjects_in_order(rows);
    std::ostringstream o;
    o << "# The scorecard: Levien's properties as numbers\n\n"
      << "Every configuration of the registry and every installed peer on " << polygons << " seeded random polygons of "
      << kScorecardPoints
      << " points (largest turning angle 30°…170°) and as many co-circular sets of 3…64 points of each kind "
         "(`cagd scorecard`, `src/cagd/compare/scorecard.hpp`; docs/benchmark.md defines each measure). "
         "Each cell is a median (a rate in %) and its 95 % interval; distances are ÷ the points' "
         "bounding-box diagonal D, sampled at 33 fractions per span (a lower bound of each supremum). "
         "Data: [`scorecard.csv`](scorecard.csv) (with 95th percentiles and the largest values), "
         "[`scorecard_classic.csv`](scorecard_classic.csv) (the classic data).\n\n";
    if (!skipped.empty()) {
        o << "Skipped (not installed):\n\n";
        for (const std::string& s : skipped) o << "- " << s << "\n";
        o << "\n";
    }
    o << "## Shape: roundness, extensionality, symmetry, similarity\n\n"
      << "| subject | roundness, closed | roundness, open arc | extensionality | symmetry | similarity |\n"
      << "|---|---|---|---|---|---|\n";
    for (const std::string& s : subjects)
        o << "| " << s << " | " << cell(m, s, "roundness_closed", "median") << " | "
          << cell(m, s, "roundness_open", "median") << " | " << cell(m, s, "extensionality", "median") << " | "
          << cell(m, s, "symmetry", "median") << " | " << cell(m, s, "similarity", "median") << " |\n";
    o << "\n## Locality, curvature and fairness\n\n"
      << "Spans moved: of the " << kScorecardPoints - 1 << " spans, those a move of point " << kScorecardPoints / 2
      << " by 10⁻³ D displaces by more than 10⁻¹² D; influence at r: the largest displacement ÷ the move "
         "r spans away. κ-max inside: the polygons with a span whose |κ| peaks inside it (%). Fairness: "
         "L∫κ² ds and L³∫κ′² ds. Failures: polygons without a curve (%).\n\n"
      << "| subject | spans moved | influence at r = 2 | influence at r = 3 | κ-max inside (%) | L∫κ² ds | L³∫κ′² ds | "
         "failures (%) |\n"
      << "|---|---|---|---|---|---|---|---|\n";
    for (const std::string& s : subjects)
        o << "| " << s << " | " << cell(m, s, "spans_moved", "median") << " | " << cell(m, s, "influence_r2", "median")
          << " | " << cell(m, s, "influence_r3", "median") << " | "
          << cell(m, s, "curvature_maxima_inside", "rate", 100.0) << " | " << cell(m, s, "bending", "median") << " | "
          << cell(m, s, "variation", "median") << " | " << cell(m, s, "existence", "rate", 100.0) << " |\n";
    o << "\n## Existence: failures (%) against the largest turning angle\n\n";
    std::vector<std::string> failing;
    for (const std::string& s : subjects)
        if (const auto it = m.find({s, "existence", "rate"}); it != m.end() && it->second->estimate.value > 0)
            failing.push_back(s);
    if (failing.empty()) {
        o << "Every subject drew a curve through every polygon.\n";
    } else {
        o << "Every subject not listed drew a curve through every polygon.\n\n| subject |";
        for (int b = 0; b < kTurnBins; ++b)
            o << ' ' << kFirstTurn + b * kTurnBin << "°–" << kFirstTurn + (b + 1) * kTurnBin << "° |";
        o << "\n|---|";
        for (int b = 0; b < kTurnBins; ++b) o << "---|";
        o << "\n";
        for (const std::string& s : failing) {
            o << "| " << s << " |";
            for (int b = 0; b < kTurnBins; ++b) {
                const int lo = static_cast<int>(kFirstTurn + b * kTurnBin);
                o << ' '
                  << cell(m, s,
                          "existence_" + std::to_string(lo) + "_" + std::to_string(lo + static_cast<int>(kTurnBin)),
                          "rate", 100.0)
                  << " |";
            }
            o << "\n";
        }
    }
    o << "\n## Locality against fairness\n\n![locality against fairness](scorecard_locality.png)\n";
    return o.str();
}

std::string scorecard_figure_data(const std::vector<ScorecardRow>& rows) {
    const auto m = index_rows(rows);
    std::ostringstream o;
    o << "# mean_spans_moved median_bending curvature_continuous subject\n";
    for (const std::string& s : subjects_in_order(rows)) {
        const auto moved = m.find({s, "spans_moved", "mean"});
        const auto bending = m.find({s, "bending", "median"});
        const auto g2 = m.find({s, "g2_defect", "median"});
        if (moved == m.end() || bending == m.end() || g2 == m.end()) continue;
        o << format_number(moved->second->estimate.value, 6) << ' ' << format_number(bending->second->estimate.value, 6)
          << ' ' << (g2->second->estimate.value <= analysis::kFlatCurvature ? 1 : 0) << ' ' << s << '\n';
    }
    return o.str();
}

}  // namespace cagd::compare
