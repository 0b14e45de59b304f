#pragma once
/// @file
/// Internals shared by the source files of the curvature-profile design
/// (intrinsic/curvature_profile_design.hpp): the problem's spans and scale, the Bézier ordinates of
/// one segment of ψ with their exact derivatives, and the arrays Newton keeps from one evaluation
/// of the system (eq 9–14) to the next. Not API.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "cagd/intrinsic/curvature_profile_design.hpp"

namespace cagd::intrinsic::detail {

/// Spans of the data: n − 1 open, n closed.
int span_count(const CurvatureProfileProblem& P);
/// The chord of span `span` (closed: the last one back to the first point).
Eigen::Vector2d chord(const CurvatureProfileProblem& P, int span);
/// The longest chord, at least 1: the length scale of the tolerances.
double data_scale(const CurvatureProfileProblem& P);
/// The rows a segment's shape condition adds (eq 12–14) at degree p.
int shape_rows(SegmentShape s, int p);

/// The largest degree of ψ a layout has (KnotLayout: 2..4).
inline constexpr int kMaxJetDegree = 4;
inline constexpr int kMaxOrdinates = kMaxJetDegree + 1;
using Ordinates = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxOrdinates, 1>;

/// The Bézier ordinates of segment j and their exact derivatives with respect to the local de Boor
/// ordinates (columns first_ordinate..+p) and the local segment lengths (first_segment.., at most
/// 2p − 1 of them). Sizes are dynamic within fixed storage: no allocation per segment.
struct SegmentJet {
    Ordinates b;
    int first_ordinate = 0, first_segment = 0;
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxOrdinates, kMaxOrdinates> db_dc;
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxOrdinates, 2 * kMaxJetDegree> db_dw;
};

/// The per-iteration arrays of design_system, kept by Newton from one iteration to the next.
struct DesignWorkspace {
    std::vector<double> lengths;  ///< Δw_j from u
    std::vector<SegmentJet> jets;
    std::vector<Eigen::Triplet<double>> triplets;  ///< J's entries while its pattern is not known (freed once it is)
    std::vector<int> slots;                        ///< entry i's place in the last Jacobian's value array
    Eigen::VectorXd row_scale;                     ///< each equation's factor to dimensionless form
};

/// design_system (f and, asked, J) into `out`, reusing `workspace` and out's J where its pattern
/// holds.
void design_system_into(const CurvatureProfileProblem& P, const Eigen::VectorXd& u, bool with_jacobian,
                        DesignWorkspace& workspace, DesignSystem& out);

/// The label of the equation with the largest |f_i|, with that value.
std::string worst_equation(const CurvatureProfileProblem& P, const Eigen::VectorXd& f);
/// An empty solution of P's size (unknowns, equations) for a solver started at `start`;
/// InvalidInput naming `who` when start has not one entry per unknown (eq 2).
CurvatureProfileSolution sized_solution(const CurvatureProfileProblem& P, const Eigen::VectorXd& start,
                                        const std::string& who);
/// Builds the solution's curve from its unknowns.
void finish_ok(const CurvatureProfileProblem& P, CurvatureProfileSolution& sol);

}  // namespace cagd::intrinsic::detail
