#include "cagd/intrinsic/curvature_profile_design.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "cagd/core/errors.hpp"
#include "cagd/intrinsic/detail/design_system.hpp"

namespace cagd::intrinsic {

namespace detail {

int span_count(const CurvatureProfileProblem& P) { return static_cast<int>(P.points.rows()) - (P.closed ? 0 : 1); }

Eigen::Vector2d chord(const CurvatureProfileProblem& P, int span) {
    const Eigen::Index n = P.points.rows();
    const Eigen::Index a = span, b = (span + 1) % n;
    return (P.points.row(b) - P.points.row(a)).transpose();
}

double data_scale(const CurvatureProfileProblem& P) {
    double s = 1.0;
    for (int i = 0; i < span_count(P); ++i) s = std::max(s, chord(P, i).norm());
    return s;
}

int shape_rows(SegmentShape s, int p) {
    switch (s) {
        case SegmentShape::free: return 0;
        case SegmentShape::line: return p;
        case SegmentShape::arc: return p - 1;
        case SegmentShape::linear_curvature: return 1;
    }
    return 0;
}

}  // namespace detail

using detail::shape_rows;
using detail::span_count;

int closing_turns(const CurvatureProfileProblem& P) {
    if (P.turns != 0) return P.turns;
    double area = 0.0;
    const Eigen::Index n = P.points.rows();
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Index j = (i + 1) % n;
        area += P.points(i, 0) * P.points(j, 1) - P.points(j, 0) * P.points(i, 1);
    }
    return area >= 0 ? 1 : -1;
}

const char* to_string(SegmentShape shape) {
    switch (shape) {
        case SegmentShape::free: return "free";
        case SegmentShape::line: return "line";
        case SegmentShape::arc: return "arc";
        case SegmentShape::linear_curvature: return "linear_curvature";
    }
    return "?";
}

std::vector<SegmentShape> parse_span_shapes(const std::string& text) {
    std::vector<SegmentShape> out;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        item.erase(0, item.find_first_not_of(" \t"));
        item.erase(item.find_last_not_of(" \t") + 1);
        if (item == "free")
            out.push_back(SegmentShape::free);
        else if (item == "line")
            out.push_back(SegmentShape::line);
        else if (item == "arc")
            out.push_back(SegmentShape::arc);
        else if (item == "clothoid" || item == "linear_curvature")
            out.push_back(SegmentShape::linear_curvature);
        else
            fail_input("intrinsic::parse_span_shapes", "span " + std::to_string(out.size()) + ": \"" + item +
                                                           "\" is not a shape (allowed: free, line, arc, clothoid)");
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return out;
}

std::vector<SegmentShape> segment_shapes(const KnotLayout& layout, const std::vector<SegmentShape>& span_shapes) {
    if (static_cast<int>(span_shapes.size()) != layout.spans())
        fail_input("intrinsic::segment_shapes", "needs one shape per span (" + std::to_string(layout.spans()) +
                                                    "), got " + std::to_string(span_shapes.size()));
    std::vector<SegmentShape> out;
    for (int j = 0; j < layout.segments(); ++j)
        out.push_back(span_shapes[static_cast<std::size_t>(layout.span_of_segment(j))]);
    return out;
}

KnotLayout span_layout(const std::vector<SegmentShape>& span_shapes) {
    if (span_shapes.empty()) fail_input("intrinsic::span_layout", "needs at least one span");
    const int n = static_cast<int>(span_shapes.size());
    std::vector<int> mult{2}, index;
    for (int i = 1; i < n; ++i) {
        const auto a = span_shapes[static_cast<std::size_t>(i) - 1], b = span_shapes[static_cast<std::size_t>(i)];
        const bool rigid =
            a == SegmentShape::line || a == SegmentShape::arc || b == SegmentShape::line || b == SegmentShape::arc;
        mult.push_back(rigid ? 2 : 1);
    }
    mult.push_back(2);
    for (int i = 0; i < n; ++i) index.push_back(i);
    return KnotLayout(2, std::vector<int>(static_cast<std::size_t>(n), 1), mult, index);
}

void require_valid_problem(const CurvatureProfileProblem& P, const std::string& who) {
    require_valid_points(P.points, P.closed ? 3 : 2, true, P.closed, who);
    if (P.points.cols() != 2)
        fail_input(who, "points must be planar (2 columns), got " + std::to_string(P.points.cols()));
    const int n = span_count(P);
    if (P.layout.spans() != n)
        fail_input(who, "the knot layout has " + std::to_string(P.layout.spans()) + " spans but the " +
                            std::to_string(P.points.rows()) +
                            (P.closed ? " points of a closed curve make " : " points make ") + std::to_string(n));
    if (static_cast<int>(P.shapes.size()) != P.layout.segments())
        fail_input(who, "needs one shape per segment (" + std::to_string(P.layout.segments()) + "), got " +
                            std::to_string(P.shapes.size()));
    for (std::size_t j = 0; j < P.shapes.size(); ++j)
        if (P.shapes[j] == SegmentShape::linear_curvature && P.layout.degree() != 3)
            fail_input(
                who, "segment " + std::to_string(j) +
                         ": linear_curvature needs a degree-3 ψ (a degree-2 ψ has linear curvature on every segment)");
    using K = DesignCondition::Kind;
    for (const auto& c : P.conditions) {
        const int top = P.layout.segments() - (c.kind == K::segment_length ? 1 : 0);
        if (c.index < 0 || c.index > top)
            fail_input(who, std::string(c.kind == K::segment_length ? "segment" : "breakpoint") + " index " +
                                std::to_string(c.index) + " of a condition is outside 0.." + std::to_string(top));
        if (!std::isfinite(c.value)) fail_input(who, "condition value " + full_precision(c.value) + " is not finite");
        if (c.kind == K::curvature_radius && c.value == 0.0)
            fail_input(who, "curvature radius 0 at breakpoint " + std::to_string(c.index));
        if (c.kind == K::segment_length && !(c.value > 0))
            fail_input(who, "segment length " + full_precision(c.value) + " for segment " + std::to_string(c.index) +
                                " must be > 0");
        const bool one_sided =
            c.kind == K::curvature || c.kind == K::curvature_radius || c.kind == K::curvature_derivative;
        if (one_sided && ((c.from_left && c.index == 0) || (!c.from_left && c.index == P.layout.segments())))
            fail_input(who,
                       "curvature at breakpoint " + std::to_string(c.index) + " needs the side that has a segment");
        if (c.kind == K::curvature_derivative && (c.order < 1 || c.order > P.layout.degree() - 2))
            fail_input(who, "curvature derivative of order " + std::to_string(c.order) + " at breakpoint " +
                                std::to_string(c.index) + ": a degree-" + std::to_string(P.layout.degree()) +
                                " ψ allows orders 1.." + std::to_string(P.layout.degree() - 2));
    }
    if (P.closed && std::abs(P.turns) > 100)
        fail_input(who, "turns = " + std::to_string(P.turns) + " is implausible (|turns| ≤ 100)");
    if (P.closed && (P.closing_continuity < 2 || P.closing_continuity > P.layout.degree()))
        fail_input(who, "closing continuity G" + std::to_string(P.closing_continuity) + " is outside G2..G" +
                            std::to_string(P.layout.degree()) + " for a degree-" + std::to_string(P.layout.degree()) +
                            " ψ");
}

int design_unknowns(const CurvatureProfileProblem& P) { return P.layout.independent_lengths() + P.layout.ordinates(); }

int design_equations(const CurvatureProfileProblem& P) {
    int m = 2 * P.layout.spans() + static_cast<int>(P.conditions.size()) + (P.closed ? P.closing_continuity : 0);
    for (auto s : P.shapes) m += shape_rows(s, P.layout.degree());
    return m;
}

std::vector<std::string> design_equation_labels(const CurvatureProfileProblem& P) {
    std::vector<std::string> out;
    const int p = P.layout.degree();
    for (int i = 0; i < P.layout.spans(); ++i) {
        out.push_back("interpolation x, span " + std::to_string(i));
        out.push_back("interpolation y, span " + std::to_string(i));
    }
    for (int j = 0; j < P.layout.segments(); ++j) {
        const std::string seg = ", segment " + std::to_string(j);
        switch (P.shapes[static_cast<std::size_t>(j)]) {
            case SegmentShape::free: break;
            case SegmentShape::line:
                for (int r = 1; r <= p; ++r) out.push_back("line" + seg + ", b" + std::to_string(r) + " − b0");
                break;
            case SegmentShape::arc:
                for (int r = 1; r < p; ++r) out.push_back("arc" + seg + ", second difference at b" + std::to_string(r));
                break;
            case SegmentShape::linear_curvature: out.push_back("linear curvature" + seg + ", third difference"); break;
        }
    }
    for (const auto& c : P.conditions) {
        using K = DesignCondition::Kind;
        if (c.kind == K::segment_length) {
            out.push_back("length of segment " + std::to_string(c.index));
            continue;
        }
        const std::string what = c.kind == K::tangent_angle      ? "tangent angle"
                                 : c.kind == K::curvature        ? "curvature"
                                 : c.kind == K::curvature_radius ? "curvature radius"
                                                                 : "curvature derivative " + std::to_string(c.order);
        out.push_back(what + " at breakpoint " + std::to_string(c.index));
    }
    if (P.closed) {
        out.push_back("closed: tangent angles differ by 2π·turns");
        out.push_back("closed: end curvatures equal");
        for (int d = 1; d + 2 <= P.closing_continuity; ++d)
            out.push_back("closed: end curvature derivatives " + std::to_string(d) + " equal");
    }
    return out;
}

}  // namespace cagd::intrinsic
