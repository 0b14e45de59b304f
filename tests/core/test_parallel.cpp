// core/parallel: parallel_for rethrows the lowest failing index whatever the thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <boost/math/interpolators/catmull_rom.hpp>
#include <boost/math/interpolators/makima.hpp>
#include <boost/math/interpolators/pchip.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>

#include "cagd/analysis/curve_measures.hpp"
#include "cagd/analysis/fairness_measures.hpp"
#include "cagd/analysis/log_curvature_graph.hpp"
#include "cagd/compare/method_comparison.hpp"
#include "cagd/core/parallel.hpp"
#include "cagd/core/point_csv.hpp"
#include "cagd/core/random_walk.hpp"
#include "cagd/methods/method_registry.hpp"

using std::isnan;
using namespace cagd;
using namespace cagd::compare;
using namespace cagd::methods;

TEST(Parallel, TheLowestFailingIndexIsRethrownWhateverTheThreadCount) {
    for (int threads : {1, 2, 5}) {
        std::vector<int> ran(40, 0);
        try {
            cagd::parallel_for(40, threads, [&](long k) {
                ran[static_cast<std::size_t>(k)] = 1;
                if (k == 7 || k == 23) throw std::runtime_error("index " + std::to_string(k));
            });
            ADD_FAILURE() << "no exception with " << threads << " threads";
        } catch (const std::runtime_error& e) {
            EXPECT_EQ(std::string(e.what()), "index 7") << threads << " threads";
        }
        for (int k = 0; k <= 7; ++k)
            EXPECT_EQ(ran[static_cast<std::size_t>(k)], 1) << "index " << k << " with " << threads << " threads";
    }
    std::vector<long> square(1000);
    cagd::parallel_for(1000, 3, [&](long k) { square[static_cast<std::size_t>(k)] = k * k; });
    for (long k = 0; k < 1000; ++k) ASSERT_EQ(square[static_cast<std::size_t>(k)], k * k);
}
