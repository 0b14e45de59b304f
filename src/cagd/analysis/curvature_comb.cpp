#include "cagd/analysis/curvature_comb.hpp"

#include <algorithm>
#include <cmath>

namespace cagd::analysis {

double comb_scale(std::vector<double> kappa, double diagonal) {
    if (kappa.empty()) return 0.0;
    for (double& k : kappa) k = std::abs(k);
    const auto p95 = kappa.begin() + static_cast<std::ptrdiff_t>(0.95 * static_cast<double>(kappa.size() - 1));
    std::nth_element(kappa.begin(), p95, kappa.end());
    return *p95 > 0.0 ? kCombPercentileLength * diagonal / *p95 : 0.0;
}

}  // namespace cagd::analysis
