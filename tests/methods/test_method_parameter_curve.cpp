// methods/method_parameter_curve: every registered configuration's curve in its method's own
// parameter τ, as MethodClaims::parameter states it. The registry's claim is tested against what
// evaluation does: the τ-length of each span is its chord (chord length), √chord (centripetal), its
// arc length (arc length) or 1 (uniform), derivatives are d/dτ, and "C^k in τ" holds at the nodes.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/core/errors.hpp"
#include "cagd/methods/method_parameter_curve.hpp"
#include "cagd/methods/method_registry.hpp"

#include "../support/point_lists.hpp"

namespace {

using cagd::InvalidInput;
using cagd::PointList;
using cagd::methods::Configuration;
using cagd::methods::configurations;
using cagd::methods::Interpolant;
using cagd::methods::InterpolationResult;
using cagd::methods::MethodParameterCurve;
namespace analysis = cagd::analysis;

// The τ-length a span of chord `chord` and arc length `arc` has under the stated parameter.
double expected_span(const std::string& parameter, double chord, double arc) {
    if (parameter == "chord length") return chord;
    if (parameter.rfind("centripetal", 0) == 0) return std::sqrt(chord);
    if (parameter == "arc length") return arc;
    return 1.0;  // "uniform", "u (unit spans)"
}

}  // namespace

TEST(MethodParameterCurve, EveryMethodIsEvaluatedInTheParameterItStates) {
    const PointList p = cagd::test::kNewberyGarrett;
    int checked = 0;
    for (const Configuration& c : configurations())
        for (bool closed : {false, true}) {
            if (closed && !c.claims.supports_closed) continue;
            const InterpolationResult r = cagd::methods::interpolate(c, p, closed);
            if (!c.claims.always_solves &&
                !r.outcome.ok()) {  // closed Spiro through these points does not exist (libspiro agrees)
                EXPECT_EQ(r.outcome.status, cagd::Status::no_convergence) << c.name;
                continue;
            }
            ASSERT_TRUE(r.outcome.ok()) << c.name << ": " << r.outcome.message;
            const Interpolant& in = *r.interpolant;
            const MethodParameterCurve m(in);
            const std::vector<double>& tau = m.node_parameters();
            const Eigen::Index n = p.rows();
            ASSERT_EQ(tau.size(), in.node_parameters.size()) << c.name;
            for (std::size_t k = 0; k + 1 < tau.size(); ++k) {
                const double chord =
                    (p.row(static_cast<Eigen::Index>(k + 1) % n) - p.row(static_cast<Eigen::Index>(k))).norm();
                const double arc =
                    analysis::arc_length(*in.curve, in.node_parameters[k], in.node_parameters[k + 1], 64);
                EXPECT_NEAR(tau[k + 1] - tau[k], expected_span(c.claims.parameter, chord, arc), 1e-9 * (1 + chord))
                    << c.name << (closed ? " closed" : " open") << ", span " << k << ": the τ-length under '"
                    << c.claims.parameter << "'";
                // Positions are the curve's; d/dτ is the central difference in τ.
                const double t = tau[k] + 0.37 * (tau[k + 1] - tau[k]), h = 1e-6 * (tau[k + 1] - tau[k]);
                const Eigen::MatrixXd j = m.jet(t, 2);
                EXPECT_LT((j.row(0) - in.curve->jet(m.span_parameter(t), 0).row(0)).norm(),
                          1e-13 * (1 + j.row(0).norm()))
                    << c.name;
                const Eigen::RowVectorXd fd = (m.jet(t + h, 0).row(0) - m.jet(t - h, 0).row(0)) / (2 * h);
                EXPECT_LT((j.row(1) - fd).norm(), 1e-6 * (1 + j.row(1).norm())) << c.name << ": r' is d/dτ";
                const Eigen::RowVectorXd fd2 = (m.jet(t + h, 1).row(1) - m.jet(t - h, 1).row(1)) / (2 * h);
                EXPECT_LT((j.row(2) - fd2).norm(), 1e-5 * (1 + j.row(2).norm())) << c.name << ": r'' is d²/dτ²";
            }
            // "C^k in τ": derivatives up to k agree across every interior node.
            const int k_claimed = c.claims.parametric_continuity;
            for (std::size_t k = 1; k_claimed > 0 && k + 1 < tau.size(); ++k) {
                const Eigen::MatrixXd left = m.jet_from_left(tau[k], k_claimed), right = m.jet(tau[k], k_claimed);
                EXPECT_LT((left - right).norm(), 1e-8 * (1 + right.norm()))
                    << c.name << ": C^" << k_claimed << " in τ at node " << k;
            }
            ++checked;
        }
    EXPECT_GE(checked, 30);
}

TEST(MethodParameterCurve, RefusesWhatIsNotAnInterpolant) {
    const InterpolationResult r = cagd::methods::interpolate("cubic-b", cagd::test::kNewberyGarrett, false);
    Interpolant bad = *r.interpolant;
    bad.dtau_du[1] = 0.0;
    EXPECT_THROW(MethodParameterCurve{bad}, InvalidInput);
    const MethodParameterCurve m(*r.interpolant);
    EXPECT_THROW(m.jet(m.t_max() + 1.0, 0), InvalidInput);
    EXPECT_DOUBLE_EQ(m.method_parameter(m.span_parameter(0.3 * m.t_max())), 0.3 * m.t_max());
}
