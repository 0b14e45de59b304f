# Read by ctest after the GoogleTest tests are discovered (TEST_INCLUDE_FILES): the long tests of a
# fresh build, which has no timing history yet (Testing/Temporary/CTestCostData.txt), start first,
# so that none is left running alone at the end of a parallel run. Costs are seconds measured on
# the 2-core machine; ctest replaces them with its own measurements from the second run on. (Tests
# added in CMakeLists.txt get their COST there: this file is read before them.)
set_tests_properties("Compare/EveryMethod.MillionPointsAreInterpolated/curvature_profile  # GetParam() = \"curvature-profile\""
                     PROPERTIES COST 30)
