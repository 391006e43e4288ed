# The suite's longest tests and their run times in seconds (one core, `taskset -c 1 ctest -j1` in
# a build of the same tree), as ctest's COST: under -j ctest starts the costliest tests first, so
# that at the end the many short tests fill both cores instead of one long test running alone
# (the stability tests, the longest, come last in the listing order). Tests missing here keep
# cost 0; after a run, ctest's own measurements (Testing/Temporary/CTestCostData.txt) take over.
set(gdr_test_costs
  "GpmStability.ProjectScenesAreFinite" 47
  "MetropolisStability.ProjectScenesAreFinite" 44
  "GbdptUnbiased.MirrorAndGlassManifold" 38
  "BidirStability.ProjectScenesAreFinite" 28
  "GvcmStability.ProjectScenesAreFinite" 28
  "Gpm.SkyPhotonsGradientsBeatPmDifferences" 27
  "BsdfStability.EdgeCasesStayFinite" 25
  "GvcmStability.ProjectScenesAreFiniteWithManifoldShift" 20
  "GbdptUnbiased.GlassBoxManifold" 19
  "ProjectScenesFinite.NoNonFiniteSamples" 18
  "Gmlt.CausticsBoxGradientsConvergeThroughManifoldWalks" 18
  "GbdptUnbiased.GlassBoxHybrid" 16
  "GbdptStability.ZeroAreaLightAndPointLight" 16
  "FurnaceObjects.NearDeltaMirrorSphereIsInvisible" 15
  "Gpm.ManifoldPhotonShiftCorrelatesCaustics" 15
  "Mlt.GlossyPlatesAgreeWithPt" 13
  "Gvcm.PrimalAgreesWithVcmUnderManifoldShift" 12
  "GptUnbiased.GlassCausticManifold" 12
  "GbdptUnbiased.MirrorAndGlassHybrid" 12
  "Gvcm.MeanGradientsConverge" 10
  "GbdptStability.ProjectScenesAreFinite" 9
  "Mlt.CornellBoxAgreesWithPt" 9
  "MetropolisStability.ZeroAreaLightAndPointLight" 9
  "Merging.PmIsConsistent" 9
  "FurnaceObjects.IndexMatchedGlassSphereIsInvisible" 8
  "Gbdpt.PrimalAgreesWithBdpt" 8
  "Mlt.NormalizationIsTheImagesLuminanceSum" 8
  "Registry.EveryEntryRendersATinyScene" 8
  "BidirStability.ZeroAreaLightAndPointLight" 7
  "Gbdpt.PowerPrimalIsBdptsImage" 7
  "Gvcm.PrimalAgreesWithVcm" 7
  "MarkovChains.ReportedReachKeepsTheTarget" 7
  "GbdptStability.ProjectScenesAreFiniteWithManifoldShift" 7
  "Gmlt.CornellBoxGradientsConvergeToPtDifferences" 7
  "Gbdpt.GradientsBeatBdptDifferences" 7
  "MarkovChains.PathLengthsReadingFewerDimensionsKeepTheTarget" 7
  "Gvcm.ErrorFallsAsPassesGrow" 7
  "GvcmStability.ZeroAreaLightAndPointLight" 6
  "Gmlt.L2ReconstructionAgreesWithPt" 6
  "RoughPlasticAlbedo.BoundedAndFiniteAtTheEdges" 6
)
list(LENGTH gdr_test_costs n)
math(EXPR last "${n} - 1")
foreach(i RANGE 0 ${last} 2)
  math(EXPR j "${i} + 1")
  list(GET gdr_test_costs ${i} name)
  list(GET gdr_test_costs ${j} cost)
  set_tests_properties("${name}" PROPERTIES COST ${cost})
endforeach()
