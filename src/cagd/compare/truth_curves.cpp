#include "cagd/compare/truth_curves.hpp"

#include <cmath>
#include <numbers>

#include "cagd/aesthetic/log_aesthetic_curve.hpp"
#include "cagd/analysis/arc_length_parameter.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/intrinsic/intrinsic_curve.hpp"

namespace cagd::compare {

namespace {

constexpr double kPi = std::numbers::pi;

// A curve given by its analytic jet r^(k)(t), k ≤ 3.
class AnalyticCurve : public Curve {
public:
    using JetFunction = Eigen::MatrixXd (*)(double t);
    AnalyticCurve(int dimension, double t_max, JetFunction jet_function)
        : dimension_(dimension), t_max_(t_max), jet_(jet_function) {}
    int dimension() const override { return dimension_; }
    double t_min() const override { return 0.0; }
    double t_max() const override { return t_max_; }
    // Smooth everywhere: the limit from the left is the jet.
    void evaluate_jet(double t, int first, JetSide, Eigen::Ref<Eigen::MatrixXd> out) const override {
        const int order = first + static_cast<int>(out.rows()) - 1;
        if (order > 3) fail_input("compare::truth curve", "jet order must be 0..3, got " + std::to_string(order));
        take_rows(jet_(t), first, out);
    }
    std::vector<double> breakpoints() const override {
        std::vector<double> b;
        for (int i = 0; i <= 8; ++i) b.push_back(t_max_ * i / 8);  // pieces for the quadratures of analysis/
        return b;
    }

private:
    int dimension_;
    double t_max_;
    JetFunction jet_;
};

Eigen::MatrixXd line_jet(double t) {
    Eigen::MatrixXd j = Eigen::MatrixXd::Zero(4, 2);
    j.row(0) << t, 0.5 * t;
    j.row(1) << 1.0, 0.5;
    return j;
}

Eigen::MatrixXd circle_jet(double t) {
    const double c = std::cos(t), s = std::sin(t);
    Eigen::MatrixXd j(4, 2);
    j << c, s, -s, c, -c, -s, s, -c;
    return j;
}

Eigen::MatrixXd ellipse_jet(double t) {
    const double c = std::cos(t), s = std::sin(t);
    Eigen::MatrixXd j(4, 2);
    j << 2 * c, s, -2 * s, c, -2 * c, -s, 2 * s, -c;
    return j;
}

// Epitrochoid R = 3, r = 1, d = 1/2: (4 cos t − d cos 4t, 4 sin t − d sin 4t).
Eigen::MatrixXd epitrochoid_jet(double t) {
    constexpr double d = 0.5;
    Eigen::MatrixXd j(4, 2);
    double f = 1.0;
    for (int k = 0; k < 4; ++k) {
        // d^k/dt^k of (cos at, sin at) = a^k (cos(at + kπ/2), sin(at + kπ/2))
        const double shift = k * kPi / 2;
        j(k, 0) = 4 * std::cos(t + shift) - d * f * std::cos(4 * t + shift);
        j(k, 1) = 4 * std::sin(t + shift) - d * f * std::sin(4 * t + shift);
        f *= 4;
    }
    return j;
}

Eigen::MatrixXd helix_jet(double t) {
    const double c = std::cos(t), s = std::sin(t);
    Eigen::MatrixXd j(4, 3);
    j << c, s, t / 4, -s, c, 0.25, -c, -s, 0, s, -c, 0;
    return j;
}

// Trefoil (sin t + 2 sin 2t, cos t − 2 cos 2t, −sin 3t).
Eigen::MatrixXd trefoil_jet(double t) {
    Eigen::MatrixXd j(4, 3);
    for (int k = 0; k < 4; ++k) {
        const double h = k * kPi / 2, p2 = std::pow(2.0, k), p3 = std::pow(3.0, k);
        j(k, 0) = std::sin(t + h) + 2 * p2 * std::sin(2 * t + h);
        j(k, 1) = std::cos(t + h) - 2 * p2 * std::cos(2 * t + h);
        j(k, 2) = -p3 * std::sin(3 * t + h);
    }
    return j;
}

// ψ(s) = s²/2 on [0, L]: one degree-2 segment with Bézier (= de Boor) ordinates 0, 0, L²/2.
std::shared_ptr<const Curve> clothoid(double length) {
    const intrinsic::KnotLayout layout(2, {1}, {2, 2}, {0});
    Eigen::VectorXd ordinates(3);
    ordinates << 0.0, 0.0, 0.5 * length * length;
    return std::make_shared<intrinsic::IntrinsicCurve>(Eigen::Vector2d::Zero(),
                                                       intrinsic::TangentAngleSpline(layout, {length}, ordinates));
}

std::shared_ptr<const Curve> log_aesthetic() {
    aesthetic::LogAestheticParameters p;
    p.alpha = 2.0;
    p.c0 = 1.0;
    p.c1 = 1.0;
    p.length = 4.0;
    return std::make_shared<aesthetic::LogAestheticCurve>(p);
}

}  // namespace

const std::vector<TruthFamily>& truth_families() {
    static const std::vector<TruthFamily> families = [] {
        std::vector<TruthFamily> f;
        f.push_back(
            {"line", "the segment (t, t/2), 0 ≤ t ≤ 4", 2, false, std::make_shared<AnalyticCurve>(2, 4.0, line_jet)});
        f.push_back({"circle", "the unit circle (cos t, sin t)", 2, true,
                     std::make_shared<AnalyticCurve>(2, 2 * kPi, circle_jet)});
        f.push_back({"ellipse", "the ellipse (2 cos t, sin t)", 2, true,
                     std::make_shared<AnalyticCurve>(2, 2 * kPi, ellipse_jet)});
        f.push_back({"epitrochoid",
                     "the epitrochoid R = 3, r = 1, d = 1/2: (4 cos t − cos 4t / 2, 4 sin t − sin 4t / 2)", 2, true,
                     std::make_shared<AnalyticCurve>(2, 2 * kPi, epitrochoid_jet)});
        f.push_back({"clothoid", "the clothoid κ(s) = s, 0 ≤ s ≤ 2.5", 2, false, clothoid(2.5)});
        f.push_back(
            {"log-aesthetic", "the log-aesthetic curve ρ² = s + 1 (α = 2), 0 ≤ s ≤ 4", 2, false, log_aesthetic()});
        f.push_back({"helix", "the helix (cos t, sin t, t/4), 0 ≤ t ≤ 3π", 3, false,
                     std::make_shared<AnalyticCurve>(3, 3 * kPi, helix_jet)});
        f.push_back({"trefoil", "the trefoil knot (sin t + 2 sin 2t, cos t − 2 cos 2t, −sin 3t)", 3, true,
                     std::make_shared<AnalyticCurve>(3, 2 * kPi, trefoil_jet)});
        return f;
    }();
    return families;
}

const TruthFamily& find_truth_family(const std::string& name) {
    std::string known;
    for (const TruthFamily& f : truth_families()) {
        if (f.name == name) return f;
        known += (known.empty() ? "" : ", ") + f.name;
    }
    fail_input("compare::find_truth_family", "no truth family \"" + name + "\" (known: " + known + ")");
}

const char* to_string(TruthSpacing spacing) { return spacing == TruthSpacing::uniform ? "uniform" : "nonuniform"; }

TruthSample truth_samples(const TruthFamily& family, int n, TruthSpacing spacing, bool closed) {
    const char* who = "compare::truth_samples";
    if (n < 3) fail_input(who, "needs n ≥ 3 points, got " + std::to_string(n));
    if (closed && !family.closed) fail_input(who, "the " + family.name + " is open: it has no closed samples");
    const Curve& c = *family.curve;
    // An open sample of a closed curve is the arc over the first 3/4 of its parameter.
    const double t_end = closed || !family.closed ? c.t_max() : c.t_min() + 0.75 * (c.t_max() - c.t_min());
    struct Arc : Curve {
        const Curve& base;
        double end;
        Arc(const Curve& b, double e) : base(b), end(e) {}
        int dimension() const override { return base.dimension(); }
        double t_min() const override { return base.t_min(); }
        double t_max() const override { return end; }
        void evaluate_jet(double t, int first, JetSide side, Eigen::Ref<Eigen::MatrixXd> out) const override {
            base.evaluate_jet(t, first, side, out);
        }
        std::vector<double> breakpoints() const override {
            std::vector<double> b;
            for (double x : base.breakpoints())
                if (x < end) b.push_back(x);
            b.push_back(end);
            return b;
        }
    };
    const auto arc = std::make_shared<Arc>(c, t_end);
    const analysis::ArcLengthParameter inverse(arc);
    TruthSample out;
    out.closed = closed;
    out.length = inverse.length();
    out.t_first = c.t_min();
    out.t_last = t_end;
    out.points.resize(n, c.dimension());
    const int N = closed ? n : n - 1;
    for (int i = 0; i < n; ++i) {
        const double u = static_cast<double>(i) / N;
        const double g = spacing == TruthSpacing::uniform ? u : u - 0.6 * std::sin(2 * kPi * u) / (2 * kPi);
        const double t = i == 0 ? c.t_min() : (!closed && i == n - 1) ? t_end : inverse.parameter_at(g * out.length);
        out.params.push_back(t);
        out.points.row(i) = c.jet(t, 0).row(0);
    }
    if (closed) out.params.push_back(c.t_max());
    return out;
}

}  // namespace cagd::compare
