#include "cagd/export/svg_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "cagd/analysis/curvature_comb.hpp"
#include "cagd/analysis/frenet_jet.hpp"

namespace cagd::exports {

namespace {

// 17 significant digits: every double reads back to itself.
std::string svg_number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string xml_text(const std::string& s) {
    std::string out;
    for (const char ch : s) {
        switch (ch) {
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '&': out += "&amp;"; break;
            case '"': out += "&quot;"; break;
            default: out += ch;
        }
    }
    return out;
}

}  // namespace

void write_svg(std::ostream& out, const Curve& curve, const BezierForm& cubic, const SvgOptions& o) {
    const char* who = "cagd::exports::write_svg";
    const BezierPieces& b = cubic.pieces;
    if (curve.dimension() != 2 || b.dimension() != 2)
        fail_input(who, "SVG is planar; the curve has " + std::to_string(curve.dimension()) + " coordinates");
    if (b.degree != 3 || b.pieces() < 1) fail_input(who, "needs cubic pieces, got degree " + std::to_string(b.degree));
    if (o.comb && o.comb_teeth < 2)
        fail_input(who, "comb teeth must be at least 2, got " + std::to_string(o.comb_teeth));
    Eigen::Vector2d lo = b.control.colwise().minCoeff().transpose(), hi = b.control.colwise().maxCoeff().transpose();
    const double diagonal = (hi - lo).stableNorm();  // no underflow for a curve of size 1e-160
    // The comb: teeth spread over the curve's pieces, at equal parameter steps within each.
    std::vector<Eigen::Vector2d> base, tip;
    double scale = 0.0;
    if (o.comb) {
        const std::vector<double> br = curve.breakpoints();
        const int pieces = static_cast<int>(br.size()) - 1;
        const int per_piece = std::max(1, (o.comb_teeth - 1) / pieces);
        std::vector<double> kappa;
        std::vector<Eigen::Vector2d> normal;
        for (int k = 0; k < pieces && static_cast<int>(base.size()) < o.comb_teeth; ++k)
            for (int j = 0; j <= per_piece; ++j) {
                if (j == per_piece && k + 1 < pieces) continue;  // the next piece's first tooth
                const double t =
                    br[static_cast<std::size_t>(k)] +
                    (br[static_cast<std::size_t>(k) + 1] - br[static_cast<std::size_t>(k)]) * j / per_piece;
                const Eigen::MatrixXd J = j == per_piece ? curve.jet_from_left(t, 2) : curve.jet(t, 2);
                const analysis::FrenetJet f = analysis::frenet_jet(J.bottomRows(2));
                if (!f.regular) continue;  // no normal at a cusp
                const double v = f.speed;
                kappa.push_back(f.curvature);
                normal.emplace_back(-J(1, 1) / v, J(1, 0) / v);
                base.emplace_back(J(0, 0), J(0, 1));
            }
        scale = analysis::comb_scale(kappa, diagonal);
        for (std::size_t i = 0; i < base.size(); ++i) {
            tip.push_back(base[i] - scale * kappa[i] * normal[i]);
            lo = lo.cwiseMin(tip.back());
            hi = hi.cwiseMax(tip.back());
        }
    }
    for (Eigen::Index i = 0; i < o.points.rows() && o.points.cols() == 2; ++i) {
        lo = lo.cwiseMin(o.points.row(i).transpose());
        hi = hi.cwiseMax(o.points.row(i).transpose());
    }
    const double span = std::max((hi - lo).maxCoeff(), 1e-300);
    const double margin = 0.05 * span;
    const double w = hi.x() - lo.x() + 2 * margin, h = hi.y() - lo.y() + 2 * margin;
    const double pixels_high = std::clamp(800.0 * h / w, 50.0, 4000.0);
    // y flipped: the group maps (x, y) to (x, −y), so the viewBox spans −(hi.y + margin) … −(lo.y − margin).
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"" << svg_number(std::round(pixels_high))
        << "\" viewBox=\"" << svg_number(lo.x() - margin) << ' ' << svg_number(-(hi.y() + margin)) << ' '
        << svg_number(w) << ' ' << svg_number(h) << "\">\n";
    if (!o.title.empty()) out << "<title>" << xml_text(o.title) << "</title>\n";
    out << "<desc>cagd: "
        << (cubic.exact ? "the curve's exact cubic pieces"
                        : "cubic pieces within " + svg_number(cubic.max_distance) + " of the curve (tolerance " +
                              svg_number(cubic.tolerance) + ")")
        << (o.comb ? "; curvature comb tooth = -c kappa n, c = " + svg_number(scale) : "") << "</desc>\n";
    out << "<g transform=\"scale(1,-1)\" fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
    if (o.comb && !base.empty()) {
        out << "<g id=\"comb\" data-comb-scale=\"" << svg_number(scale)
            << "\" stroke=\"#4f81bd\" stroke-width=\"1\" vector-effect=\"non-scaling-stroke\">\n<path "
               "vector-effect=\"non-scaling-stroke\" d=\"";
        for (std::size_t i = 0; i < base.size(); ++i)
            out << "M" << svg_number(base[i].x()) << ' ' << svg_number(base[i].y()) << 'L' << svg_number(tip[i].x())
                << ' ' << svg_number(tip[i].y());
        out << "\"/>\n<path vector-effect=\"non-scaling-stroke\" d=\"";
        for (std::size_t i = 0; i < tip.size(); ++i)
            out << (i ? "L" : "M") << svg_number(tip[i].x()) << ' ' << svg_number(tip[i].y());
        out << "\"/>\n</g>\n";
    }
    out << "<path id=\"curve\" stroke=\"#000000\" stroke-width=\"2\" vector-effect=\"non-scaling-stroke\" d=\"M"
        << svg_number(b.control(0, 0)) << ' ' << svg_number(b.control(0, 1));
    for (int i = 0; i < b.pieces(); ++i) {
        out << "\nC";
        for (int k = 1; k <= 3; ++k)
            out << (k > 1 ? " " : "") << svg_number(b.control(4 * i + k, 0)) << ' '
                << svg_number(b.control(4 * i + k, 1));
    }
    out << "\"/>\n";
    if (o.points.rows() > 0 && o.points.cols() == 2) {
        out << "<g id=\"points\" fill=\"#c0504d\" stroke=\"none\">\n";
        for (Eigen::Index i = 0; i < o.points.rows(); ++i)
            out << "<circle cx=\"" << svg_number(o.points(i, 0)) << "\" cy=\"" << svg_number(o.points(i, 1))
                << "\" r=\"" << svg_number(0.006 * span) << "\"/>\n";
        out << "</g>\n";
    }
    out << "</g>\n</svg>\n";
}

}  // namespace cagd::exports
