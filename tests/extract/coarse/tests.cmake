# extract/coarse: Eq. 2.3 coarse graining against exact states (Maxwellian gas, compressed
# lattice) and the DEM engine's own whole-domain stress.
grainbridge_add_test(test_extract_coarse
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/coarse/MaxwellianKineticStressTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/coarse/LatticeContactStressTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/coarse/SolidFractionIntegralTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/coarse/DemFrameStressTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/coarse/LeesEdwardsTemperatureTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/coarse/StressWidthConvergenceTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/coarse/ContactStatisticsTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/coarse/DissipationRateTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/coarse/SpeciesStressTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/coarse/CoarseGrainerTest.cpp
  LIBS extract engines_dem
  LABELS "physics;extract"
  TIMEOUT 60)
