# Run by ctest as it starts (a TEST_INCLUDE_FILES script): one ctest test per GoogleTest suite
# of GDR_TESTS_EXE, run as `gdr_tests --gtest_filter=Suite.*`. A test process spends about 0.45 s
# before main() in the dynamic loader alone (Debian's OpenImageIO brings some 260 libraries), so
# one process per suite instead of one per case saves that for all but the suites' first cases.
# A failing suite's output names the failing cases. A suite with some cases skipped (the
# shared-scene cases without ../shared/scenes) passes; `ctest -V` shows which were skipped.
# Each suite process gets one thread (GDR_TEST_THREADS, read by test_main.cpp): ctest runs as many
# suites side by side as scripts/test.sh gives it cores, and with two threads each the suites'
# small launches spent their time waking each other's threads (README "Tests and benchmarks").
# Then the suites' costs (test_costs.cmake), once there are suites to give them to.
execute_process(COMMAND "${GDR_TESTS_EXE}" --gtest_list_tests OUTPUT_VARIABLE listing RESULT_VARIABLE status
                ERROR_VARIABLE errors TIMEOUT 120)
if(NOT status EQUAL 0)
  add_test(gdr_tests_listing "${GDR_TESTS_EXE}" --gtest_list_tests)
  message(WARNING "${GDR_TESTS_EXE} --gtest_list_tests failed (${status}): ${errors}")
  return()
endif()
string(REPLACE "\n" ";" lines "${listing}")
foreach(line IN LISTS lines)
  # A suite line starts in the first column and ends in "." (a typed suite adds "  # TypeParam = ...").
  if(line MATCHES "^([^ #][^ ]*)\\.( .*)?$")
    set(suite "${CMAKE_MATCH_1}")
    add_test("${suite}" "${GDR_TESTS_EXE}" "--gtest_filter=${suite}.*")
    set_tests_properties("${suite}" PROPERTIES TIMEOUT 900 ENVIRONMENT "GDR_TEST_THREADS=1")
  endif()
endforeach()
include("${CMAKE_CURRENT_LIST_DIR}/test_costs.cmake")
