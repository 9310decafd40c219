# engines/mfm: the multi-fluid model on the SIMPLE solver (issue 17).
grainbridge_add_test(test_mfm
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/mfm/PackedBedTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/mfm/FluidizedBedTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/mfm/MfmEngineTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/mfm/BoundaryAccountTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/mfm/BinaryBedTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/mfm/MixtureModelTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/mfm/AlgebraicTemperatureTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/mfm/FluidizationCurveTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/mfm/GranularEnergyTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/mfm/TabulatedClosureRunTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/mfm/InitialBedTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/mfm/InitialRegionsTest.cpp
  LIBS engines_mfm
  LABELS "physics;mfm")
