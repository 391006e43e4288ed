# The longest suites and their run times in seconds (their cases' times in a clean clone's
# `.ci/run`: an empty PoCL cache, ctest -j2 on two cores), as ctest's COST: under -j ctest starts
# the costliest first, so that at the end the many short suites fill both cores instead of one
# long suite running alone. Suites missing here keep cost 0; after a run, ctest's own
# measurements (Testing/Temporary/CTestCostData.txt) take over.
set(gdr_test_costs
  "GbdptUnbiased" 196
  "GvcmStability" 194
  "MetropolisStability" 150
  "GptUnbiased" 118
  "Gvcm" 112
  "GbdptStability" 108
  "Gpm" 103
  "GpmStability" 92
  "Gbdpt" 87
  "Gmlt" 85
  "Mlt" 78
  "AllNonDelta/BsdfChi2" 64
  "Cli" 43
  "MpiRender" 42
  "Registry" 38
  "BadOutput" 38
  "ProjectScenesFinite" 35
  "MarkovChains" 34
  "FurnaceObjects" 32
  "ShadingLanes" 29
  "GptMaterialQueues" 27
  "BadInputFiles" 27
  "GptDirectSamples" 25
  "BidirStability" 23
)
list(LENGTH gdr_test_costs n)
math(EXPR last "${n} - 1")
foreach(i RANGE 0 ${last} 2)
  math(EXPR j "${i} + 1")
  list(GET gdr_test_costs ${i} name)
  list(GET gdr_test_costs ${j} cost)
  set_tests_properties("${name}" PROPERTIES COST ${cost})
endforeach()
