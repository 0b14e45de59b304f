#include "cagd/locality/locality_spline.hpp"

#include <Eigen/SparseCore>
#include <cmath>
#include <functional>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "cagd/core/errors.hpp"
#include "cagd/numeric/sparse_lu.hpp"

namespace cagd::locality {

namespace {
const char* const kLocalityWho = "cagd::locality::interpolate";

void require_locality(SegmentLocality m, const std::string& who) {
    for (int v : {m.left, m.right})
        if (v < 0 || v > kMaxLocality)
            fail_input(who, "locality m = " + std::to_string(v) + " outside [0, " + std::to_string(kMaxLocality) + "]");
}

// Virtual points of section 3.3 as an index → point map over all integers.
// A point as a row of at most 3 coordinates, held inline (no allocation per point).
using PointRow = Eigen::Matrix<double, 1, Eigen::Dynamic, Eigen::RowMajor, 1, 3>;

class ExtendedPoints {
public:
    ExtendedPoints(const PointList& p, bool closed, Eigen::VectorXd start_normal, Eigen::VectorXd end_normal,
                   bool start_mirror, bool end_mirror)
        : p_(p),
          closed_(closed),
          start_normal_(std::move(start_normal)),
          end_normal_(std::move(end_normal)),
          start_mirror_(start_mirror),
          end_mirror_(end_mirror) {}

    PointRow operator()(long k) const {
        const long n = p_.rows();
        if (closed_) return p_.row(((k % n) + n) % n);
        if (k >= 0 && k <= n - 1) return p_.row(k);
        if (k < 0) return reflect((*this)(-k), p_.row(0), start_normal_, start_mirror_);
        return reflect((*this)(2 * (n - 1) - k), p_.row(n - 1), end_normal_, end_mirror_);
    }

private:
    static PointRow reflect(const PointRow& x, const PointRow& centre, const Eigen::VectorXd& unit_normal,
                            bool mirror) {
        if (!mirror) return 2.0 * centre - x;  // point symmetry (natural end)
        const double s = (x - centre).dot(unit_normal.transpose());
        return x - 2.0 * s * unit_normal.transpose();  // mirror ⟂ tangent
    }
    const PointList& p_;
    bool closed_;
    Eigen::VectorXd start_normal_, end_normal_;
    bool start_mirror_, end_mirror_;
};

Eigen::VectorXd unit_tangent(const EndCondition& end, const PointList& p, bool at_start, const std::string& which) {
    Eigen::VectorXd t;
    if (end.kind == EndKind::tangent) {
        t = end.tangent;
        if (t.size() != p.cols())
            fail_input(kLocalityWho, which + " tangent has " + std::to_string(t.size()) +
                                         " coordinates; the points have " + std::to_string(p.cols()));
        if (!t.allFinite() || t.norm() == 0.0) fail_input(kLocalityWho, which + " tangent must be finite and non-zero");
    } else {
        t = at_start ? bessel_tangent(p) : bessel_tangent(p.colwise().reverse().eval());
    }
    return t.normalized();
}

SegmentLocality swapped(SegmentLocality m) { return {m.right, m.left}; }

// The virtual points of section 3.3 for these options (points already validated).
ExtendedPoints make_extended_points(const PointList& points, const Options& o) {
    Eigen::VectorXd ts, te;
    bool ms = false, me = false;
    if (!o.closed) {
        if (o.start.kind != EndKind::natural) {
            ts = unit_tangent(o.start, points, true, "start");
            ms = true;
        }
        if (o.end.kind != EndKind::natural) {
            te = unit_tangent(o.end, points, false, "end");
            me = true;
        }
    }
    return ExtendedPoints(points, o.closed, ts, te, ms, me);
}
}  // namespace

double alpha() { return -2.0 + std::sqrt(3.0); }

SegmentWeights extra_point_weights(SegmentLocality m) {
    require_locality(m, "cagd::locality::extra_point_weights");
    const double a = alpha();
    SegmentWeights w{Eigen::VectorXd(m.left + 1), Eigen::VectorXd(m.right + 1)};
    double power = 1.0, total = 0.0;
    for (int j = 0; j <= std::max(m.left, m.right); ++j, power *= a) {
        if (j <= m.left) {
            w.left(j) = power;
            total += power;
        }
        if (j <= m.right) {
            w.right(j) = power;
            total += power;
        }
    }
    w.left /= total;
    w.right /= total;
    return w;
}

Eigen::Vector3d truncation_weights(int m) {
    if (m < 1 || m > kMaxLocality)
        fail_input("cagd::locality::truncation_weights",
                   "m = " + std::to_string(m) + " outside [1, " + std::to_string(kMaxLocality) + "]");
    const double a = alpha(), am = std::pow(a, m), am1 = am * a, k = 1.0 / (1.0 - am1);
    return {k, -k * (1.0 - a) * am1 / 6.0, k * (1.0 - a) * am / 6.0};
}

StencilWeights truncation_weights_by_stencil(int m) {
    if (m < 1 || m > kMaxLocality)
        fail_input("cagd::locality::truncation_weights_by_stencil",
                   "m = " + std::to_string(m) + " outside [1, " + std::to_string(kMaxLocality) + "]");
    const SegmentWeights w = extra_point_weights({m, m});
    // Coefficients on p_{i+o}, o = −(m+1) .. m+2, stored at index o + m + 1.
    const int size = 2 * m + 4, shift = m + 1;
    Eigen::VectorXd v = Eigen::VectorXd::Zero(size);
    const auto add_segment = [&](int s, double factor) {  // segment i+s
        for (int j = 0; j <= m; ++j) {
            v(s - j + shift) += factor * w.left(j);
            v(s + 1 + j + shift) += factor * w.right(j);
        }
    };
    add_segment(-1, 1.0 / 6.0);
    add_segment(0, 4.0 / 6.0);
    add_segment(1, 1.0 / 6.0);
    // Σ c_k q_{i,k} with q_{i,k} = (p_{i−k} + p_{i+1+k})/2  ⇒  c_k = 2·coef(p_{i−k}).
    StencilWeights out;
    for (int k = 0; k <= m + 1; ++k) {
        const double c = 2.0 * v(-k + shift), c_mirror = 2.0 * v(1 + k + shift);
        out.largest_other = std::max(out.largest_other, std::abs(c - c_mirror));
        if (k == 0)
            out.weights(0) = c;
        else if (k == m)
            out.weights(1) = c;
        else if (k == m + 1)
            out.weights(2) = c;
        else
            out.largest_other = std::max(out.largest_other, std::abs(c));
    }
    return out;
}

MVector parse_m_vector(const std::string& text) {
    const std::string who = "cagd::locality::parse_m_vector";
    MVector out;
    std::stringstream ss(text);
    std::string token;
    const auto parse_int = [&](const std::string& s) {
        std::size_t used = 0;
        int v = 0;
        try {
            v = std::stoi(s, &used);
        } catch (const std::exception&) {
            fail_input(who, "'" + s + "' in m-vector '" + text + "' is not an integer");
        }
        if (used != s.size()) fail_input(who, "'" + s + "' in m-vector '" + text + "' is not an integer");
        return v;
    };
    while (std::getline(ss, token, ',')) {
        const auto b = token.find_first_not_of(" {}()\t"), e = token.find_last_not_of(" {}()\t");
        if (b == std::string::npos) fail_input(who, "empty entry in m-vector '" + text + "'");
        token = token.substr(b, e - b + 1);
        const auto colon = token.find(':');
        SegmentLocality m;
        if (colon == std::string::npos) {
            m.left = m.right = parse_int(token);
        } else {
            m.left = parse_int(token.substr(0, colon));
            m.right = parse_int(token.substr(colon + 1));
        }
        require_locality(m, who);
        out.push_back(m);
    }
    if (out.empty()) fail_input(who, "m-vector '" + text + "' has no entries");
    return out;
}

std::string format_m_vector(const MVector& m) {
    std::string s;
    for (std::size_t i = 0; i < m.size(); ++i) {
        if (i) s += ",";
        s += m[i].left == m[i].right ? std::to_string(m[i].left)
                                     : std::to_string(m[i].left) + ":" + std::to_string(m[i].right);
    }
    return s;
}

double basis_e(double u, int k) { return bspline_basis(3, {-1.0, -0.5, 0.0, 0.5, 1.0}, u, k); }
double basis_e_hat(double u, int k) { return bspline_basis(4, {-1.0, -1.0, 0.0, 0.0, 1.0, 1.0}, u, k); }
double basis_f_hat(double u, int k) { return bspline_basis(4, {-1.0, 0.0, 0.0, 1.0, 1.0, 2.0}, u, k); }

KnotRelation knot_relation(SplineForm form) {
    // r(i) = Σ_j N_j(i) d_j : the three controls whose basis is non-zero at u = i.
    if (form == SplineForm::b2_spline) return {basis_e(0.5), basis_e(0.0)};
    return {basis_f_hat(0.0), basis_e_hat(0.0)};
}

double blending_g(SplineForm form, double u, int k) {
    const KnotRelation r = knot_relation(form);
    return (form == SplineForm::b2_spline ? basis_e(u, k) : basis_e_hat(u, k)) / r.centre;
}

double blending_h(SplineForm form, double u, int k) {
    const KnotRelation r = knot_relation(form);
    const double ratio = r.side / r.centre;
    if (form == SplineForm::b2_spline) return basis_e(u - 0.5, k) - ratio * (basis_e(u, k) + basis_e(u - 1.0, k));
    return basis_f_hat(u, k) - ratio * (basis_e_hat(u, k) + basis_e_hat(u - 1.0, k));
}

Eigen::VectorXd bessel_tangent(const PointList& p) {
    if (p.rows() < 2) fail_input("cagd::locality::bessel_tangent", "needs at least 2 points");
    if (p.rows() == 2) return (p.row(1) - p.row(0)).transpose();
    // Parabola through p_0, p_1, p_2 at u = 0, 1, 2: r'(0) = (−3p_0 + 4p_1 − p_2)/2.
    Eigen::VectorXd t = (-1.5 * p.row(0) + 2.0 * p.row(1) - 0.5 * p.row(2)).transpose();
    if (t.norm() == 0.0) t = (p.row(1) - p.row(0)).transpose();
    return t;
}

namespace {

// interpolate() of points that passed require_valid_points(points, o.closed ? 3 : 2, …).
LocalitySpline interpolate_valid_points(const PointList& points, const Options& o) {
    const long n = points.rows();
    const long segments = o.closed ? n : n - 1;
    if (o.m.size() != 1 && static_cast<long>(o.m.size()) != segments)
        fail_input(kLocalityWho, "m-vector has " + std::to_string(o.m.size()) + " entries; this " +
                                     (o.closed ? "closed" : "open") + " curve through " + std::to_string(n) +
                                     " points has " + std::to_string(segments) + " segments (give 1 or " +
                                     std::to_string(segments) + ")");
    for (const auto& m : o.m) require_locality(m, kLocalityWho);

    const ExtendedPoints P = make_extended_points(points, o);
    const auto m_of = [&](long seg) -> SegmentLocality {
        if (o.m.size() == 1) return o.m[0];
        if (o.closed) return o.m[static_cast<std::size_t>(((seg % n) + n) % n)];
        if (seg < 0) return swapped(o.m.front());
        if (seg >= segments) return swapped(o.m.back());
        return o.m[static_cast<std::size_t>(seg)];
    };
    // One set of weights when every segment has the same locality (the usual case).
    const std::optional<SegmentWeights> uniform_weights =
        o.m.size() == 1 ? std::optional<SegmentWeights>(extra_point_weights(o.m[0])) : std::nullopt;
    const auto extra_point = [&](long i) -> PointRow {
        const PointRow q0 = 0.5 * (P(i) + P(i + 1));
        switch (o.rule) {
            case ExtraPointRule::method_I: return q0;  // eq (15)
            case ExtraPointRule::method_IIa:           // eq (16)
                return 1.25 * q0 - 0.25 * (0.5 * (P(i - 1) + P(i + 2)));
            case ExtraPointRule::fmill: {  // eq (17)
                const auto tangent = [&](long k) {
                    const PointRow c = P(k + 1) - P(k - 1);
                    if (c.norm() == 0.0)
                        fail_input(kLocalityWho, "FMILL tangent at point " + std::to_string(k) +
                                                     " undefined: its neighbours coincide");
                    return PointRow(c.normalized());
                };
                return q0 + (tangent(i) - tangent(i + 1)) * (P(i + 1) - P(i)).norm() / 6.0;
            }
            case ExtraPointRule::locality: break;
        }
        SegmentWeights own;
        const SegmentWeights& w = uniform_weights ? *uniform_weights : (own = extra_point_weights(m_of(i)));  // eq (12)
        PointRow d = PointRow::Zero(points.cols());
        for (long j = 0; j < w.left.size(); ++j) d += w.left(j) * P(i - j);
        for (long j = 0; j < w.right.size(); ++j) d += w.right(j) * P(i + 1 + j);
        return d;
    };

    // Controls d_j, j = −1 .. 2N−1 where N = number of interpolated nodes on the domain
    // (n open; n+1 closed: p_n = p_0). Odd j: extra points of segments −1 .. N−1.
    const long N = o.closed ? n + 1 : n;
    Eigen::MatrixXd extra(N + 1, points.cols());
    // Eq (12) with one set of weights, at the segments whose weights reach no point beyond the
    // data: coordinate by coordinate over contiguous memory, the same products summed in the same
    // order as extra_point (which serves the segments near the ends, and every other rule).
    long first = N, last = N - 1;  // the segments i ∈ [first, last] taken here
    if (o.rule == ExtraPointRule::locality && uniform_weights) {
        const Eigen::VectorXd &wl = uniform_weights->left, &wr = uniform_weights->right;
        first = std::max<long>(-1, static_cast<long>(wl.size()) - 1);
        last = std::min<long>(N - 1, n - 2 - static_cast<long>(wr.size()) + 1);
        for (Eigen::Index c = 0; c < points.cols(); ++c) {
            const double* x = points.col(c).data();
            for (long i = first; i <= last; ++i) {
                double d = 0.0;
                for (Eigen::Index j = 0; j < wl.size(); ++j) d += wl(j) * x[i - j];
                for (Eigen::Index j = 0; j < wr.size(); ++j) d += wr(j) * x[i + 1 + j];
                extra(i + 1, c) = d;
            }
        }
    }
    for (long i = -1; i <= N - 1; ++i)
        if (i < first || i > last) extra.row(i + 1) = extra_point(i);
    const KnotRelation rel = knot_relation(o.form);
    Eigen::MatrixXd control(2 * N + 1, points.cols());
    for (Eigen::Index c = 0; c < points.cols(); ++c) {
        for (long i = 0; i <= N; ++i) control(2 * i, c) = extra(i, c);  // d_{2i−1}
        for (long i = 0; i < N; ++i) {                                  // eq (3) / (7)
            const double p = i < n ? points(i, c) : points(0, c);       // closed: p_N = p_0
            control(2 * i + 1, c) = (p - rel.side * (extra(i, c) + extra(i + 1, c))) / rel.centre;
        }
    }
    std::vector<double> knots;
    knots.reserve(static_cast<std::size_t>(2 * N + 5));
    if (o.form == SplineForm::b2_spline) {  // u_j = j/2: cubic, knots spaced 1/2
        for (long k = 0; k < 2 * N + 5; ++k) knots.push_back(-1.5 + 0.5 * static_cast<double>(k));
    } else {  // quartic, every integer knot double
        knots.push_back(-2.0);
        for (long k = -1; k <= N; ++k) {
            knots.push_back(double(k));
            knots.push_back(double(k));
        }
        knots.push_back(double(N + 1));
    }
    const int degree = o.form == SplineForm::b2_spline ? 3 : 4;
    return {BSplineCurve(degree, std::move(knots), std::move(control)), std::move(extra), -1};
}

}  // namespace

LocalitySpline interpolate(const PointList& points, const Options& o) {
    require_valid_points(points, o.closed ? 3 : 2, true, o.closed, kLocalityWho);
    return interpolate_valid_points(points, o);
}

LocalitySpline interpolate(const ValidPoints& points, const Options& o) {
    if (!points.cover(o.closed ? 3 : 2, o.closed)) return interpolate(points.points(), o);  // checked as a PointList
    return interpolate_valid_points(points.points(), o);
}

Eigen::RowVectorXd extended_point(const PointList& points, const Options& o, long k) {
    require_valid_points(points, o.closed ? 3 : 2, true, o.closed, "cagd::locality::extended_point");
    return make_extended_points(points, o)(k);
}

BSplineCurve interpolating_blending_function(SplineForm form, int m) {
    if (m < 0 || m > kMaxLocality)
        fail_input("cagd::locality::interpolating_blending_function",
                   "m = " + std::to_string(m) + " outside [0, " + std::to_string(kMaxLocality) + "]");
    const int half = m + 3;  // zeros beyond ±(m+1) keep the natural virtual points zero
    PointList p = PointList::Zero(2 * half + 1, 2);
    for (int k = 0; k <= 2 * half; ++k) p(k, 0) = k - half;
    p(half, 1) = 1.0;
    Options o;
    o.form = form;
    o.m = {{m, m}};
    const BSplineCurve c = interpolate(p, o).curve;
    std::vector<double> knots = c.knots();
    for (double& t : knots) t -= half;
    return BSplineCurve(c.degree(), knots, c.control_points().col(1));
}

BSplineCurve cubic_bspline_interpolant(const PointList& points, bool closed) {
    const std::string who = "cagd::locality::cubic_bspline_interpolant";
    require_valid_points(points, closed ? 3 : 2, true, closed, who);
    const long n = points.rows();
    // Unknowns c_0..c_{n−1}; eq (10) c_{i−1} + 4c_i + c_{i+1} = 6p_i.
    std::vector<Eigen::Triplet<double>> t;
    Eigen::MatrixXd rhs = 6.0 * points;
    for (long i = 0; i < n; ++i) {
        if (!closed && (i == 0 || i == n - 1)) {  // natural: c_{−1} = 2c_0 − c_1 ⇒ 6c_0 = 6p_0
            t.emplace_back(i, i, 6.0);
            continue;
        }
        t.emplace_back(i, (i + n - 1) % n, 1.0);
        t.emplace_back(i, i, 4.0);
        t.emplace_back(i, (i + 1) % n, 1.0);
    }
    Eigen::SparseMatrix<double> A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    numeric::SparseLu lu;
    if (!lu.compute(A))
        throw std::logic_error(
            "cagd::locality: the B-spline interpolation system (rows 1 4 1) is singular");  // diagonally dominant:
                                                                                            // cannot be
    const Eigen::MatrixXd c = lu.solve(rhs);
    // Control list with one extra at each end; knots at integers.
    const long N = closed ? n + 1 : n;
    Eigen::MatrixXd control(N + 2, points.cols());
    for (long i = 0; i < N; ++i) control.row(i + 1) = c.row(i % n);
    if (closed) {
        control.row(0) = c.row(n - 1);
        control.row(N + 1) = c.row(1 % n);
    } else {
        control.row(0) = 2.0 * c.row(0) - c.row(1);
        control.row(N + 1) = 2.0 * c.row(n - 1) - c.row(n - 2);
    }
    std::vector<double> knots;
    for (long k = -3; k <= N + 2; ++k) knots.push_back(double(k));
    return BSplineCurve(3, knots, control);
}

}  // namespace cagd::locality
