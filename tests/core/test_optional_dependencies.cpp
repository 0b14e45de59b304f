#include <gtest/gtest.h>

#include "cagd/core/errors.hpp"
#include "cagd/core/optional_dependencies.hpp"
#include "cagd/fairness/pseudo_energy_minimum.hpp"

using cagd::OptionalDependency;

// The tests and the harness are built only with Ceres and NLopt (CMakeLists.txt): a build that
// lost them would skip every reference cross-check, so say so here.
TEST(OptionalDependencies, TheTestBuildHasCeresAndNlopt) {
    EXPECT_TRUE(cagd::built_with(OptionalDependency::ceres));
    EXPECT_TRUE(cagd::built_with(OptionalDependency::nlopt));
    EXPECT_NO_THROW(cagd::require_built_with(OptionalDependency::ceres, "test"));
    EXPECT_NO_THROW(cagd::require_built_with(OptionalDependency::nlopt, "test"));
    // The reference minimisers run (they would throw without their dependency).
    const auto m = cagd::fairness::minimize_pseudo_energy_nlopt(0.5, -0.3);
    EXPECT_TRUE(m.outcome.ok()) << m.outcome.message;
}

TEST(OptionalDependencies, NamesAndTheMissingCaseMessage) {
    EXPECT_STREQ(cagd::to_string(OptionalDependency::ceres), "Ceres");
    EXPECT_STREQ(cagd::to_string(OptionalDependency::nlopt), "NLopt");
    EXPECT_STREQ(cagd::to_string(OptionalDependency::opencascade), "OpenCASCADE");
    if (cagd::built_with(OptionalDependency::opencascade)) return;
    try {
        cagd::require_built_with(OptionalDependency::opencascade, "who");
        FAIL() << "no throw without OpenCASCADE";
    } catch (const cagd::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("CAGD_WITH_OPENCASCADE"), std::string::npos) << e.what();
    }
}
