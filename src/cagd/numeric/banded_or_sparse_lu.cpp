#include "cagd/numeric/banded_or_sparse_lu.hpp"

#include <utility>

namespace cagd::numeric {

void BandedOrSparseLu::analyze(const Eigen::SparseMatrix<double>& pattern, std::vector<int> row_position,
                               std::vector<int> column_position, int max_storage_rows) {
    band_.reset();
    if (max_storage_rows > 0 && BandedLu::available()) {
        band_.emplace(pattern, std::move(row_position), std::move(column_position));
        if (band_->storage_rows() > max_storage_rows) band_.reset();
    }
    if (!band_) sparse_.analyze_pattern(pattern);
}

}  // namespace cagd::numeric
