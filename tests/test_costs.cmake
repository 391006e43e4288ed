# The longest suites and their run times in seconds (in a clean clone's
# `.ci/run`: an empty PoCL cache, ctest -j2 on two cores), as ctest's COST: under -j ctest starts
# the costliest first, so that at the end the many short suites fill both cores instead of one
# long suite running alone. Suites missing here keep cost 0; after a run, ctest's own
# measurements (Testing/Temporary/CTestCostData.txt) take over.
set(gdr_test_costs
  "GbdptUnbiased" 162
  "Gvcm" 84
  "Gpm" 77
  "GvcmStability" 73
  "GptUnbiased" 67
  "Mlt" 64
  "Gmlt" 63
  "MetropolisStability" 61
  "Gbdpt" 48
  "BadInputFiles" 38
  "Cli" 35
  "AllNonDelta/BsdfChi2" 28
  "Registry" 27
  "MarkovChains" 24
  "GptMaterialQueues" 24
  "MpiRender" 23
  "BadOutput" 22
  "MaterialQueues" 22
)
list(LENGTH gdr_test_costs n)
math(EXPR last "${n} - 1")
foreach(i RANGE 0 ${last} 2)
  math(EXPR j "${i} + 1")
  list(GET gdr_test_costs ${i} name)
  list(GET gdr_test_costs ${j} cost)
  set_tests_properties("${name}" PROPERTIES COST ${cost})
endforeach()
