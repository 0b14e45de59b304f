#include "cagd/numeric/sparse_lu.hpp"

#include <Eigen/SparseLU>
#include <stdexcept>
#include <variant>

namespace cagd::numeric {

using SparseMatrixD = Eigen::SparseMatrix<double>;

struct SparseLu::Impl {
    explicit Impl(ColumnOrdering ordering) {
        if (ordering == ColumnOrdering::natural) lu.emplace<1>();
    }
    std::variant<Eigen::SparseLU<SparseMatrixD, Eigen::COLAMDOrdering<int>>,
                 Eigen::SparseLU<SparseMatrixD, Eigen::NaturalOrdering<int>>>
        lu;
    bool factored = false;

    template <class Rhs>
    Rhs solve(const Rhs& b) const {
        if (!factored) throw std::logic_error("cagd::numeric::SparseLu::solve before a successful factorisation");
        return std::visit([&](const auto& f) -> Rhs { return f.solve(b); }, lu);
    }
};

SparseLu::SparseLu(ColumnOrdering ordering) : impl_(std::make_unique<Impl>(ordering)) {}
SparseLu::~SparseLu() = default;
SparseLu::SparseLu(SparseLu&&) noexcept = default;
SparseLu& SparseLu::operator=(SparseLu&&) noexcept = default;

void SparseLu::analyze_pattern(const SparseMatrixD& a) {
    impl_->factored = false;
    std::visit([&](auto& f) { f.analyzePattern(a); }, impl_->lu);
}

bool SparseLu::factorize(const SparseMatrixD& a) {
    impl_->factored = std::visit(
        [&](auto& f) {
            f.factorize(a);
            return f.info() == Eigen::Success;
        },
        impl_->lu);
    return impl_->factored;
}

bool SparseLu::compute(const SparseMatrixD& a) {
    analyze_pattern(a);
    return factorize(a);
}

Eigen::VectorXd SparseLu::solve(const Eigen::VectorXd& b) const { return impl_->solve(b); }
Eigen::MatrixXd SparseLu::solve(const Eigen::MatrixXd& b) const { return impl_->solve(b); }

}  // namespace cagd::numeric
