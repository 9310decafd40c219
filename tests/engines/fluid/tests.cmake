# engines/fluid: the multiphase staggered-grid finite-volume framework (Section 3.3).
grainbridge_add_test(test_fluid
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/fluid/StaggeredGridTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/fluid/SuperbeeTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/fluid/StencilSystemTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/fluid/ConvectionDiffusionTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/fluid/BoundariesTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/fluid/FlowStateIoTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/fluid/BedMeasuresTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/fluid/FluidSetupTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/fluid/InterphaseCouplingTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/fluid/FrameMapsTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/fluid/ContinuityTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/fluid/SimpleStepTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/fluid/MixturePlasticPressureTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/fluid/GivenPhaseTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/fluid/FieldSamplingTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/fluid/SuperficialVelocityTest.cpp
  LIBS engines_fluid
  LABELS "unit;fluid")

# The SIMPLE solver against analytic flows.
grainbridge_add_test(test_fluid_physics
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/fluid/ChannelFlowTest.cpp
  LIBS engines_fluid
  LABELS "physics;fluid")
