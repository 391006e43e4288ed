# The longest suites and their run times in seconds (in a clean clone's
# `.ci/run`: an empty PoCL cache, ctest -j2 on two cores), as ctest's COST: under -j ctest starts
# the costliest first, so that at the end the many short suites fill both cores instead of one
# long suite running alone. Suites missing here keep cost 0; after a run, ctest's own
# measurements (Testing/Temporary/CTestCostData.txt) take over.
set(gdr_test_costs
  "Gvcm" 148
  "GbdptUnbiased" 100
  "GptUnbiased" 89
  "Gpm" 87
  "Mlt" 58
  "Gmlt" 54
  "Gbdpt" 43
  "Cli" 38
  "AllNonDelta/BsdfChi2" 36
  "BadInputFiles" 32
  "BadOutput" 32
  "MpiRender" 31
  "MarkovChains" 30
  "GptMaterialQueues" 25
  "Registry" 25
)
list(LENGTH gdr_test_costs n)
math(EXPR last "${n} - 1")
foreach(i RANGE 0 ${last} 2)
  math(EXPR j "${i} + 1")
  list(GET gdr_test_costs ${i} name)
  list(GET gdr_test_costs ${j} cost)
  set_tests_properties("${name}" PROPERTIES COST ${cost})
endforeach()
