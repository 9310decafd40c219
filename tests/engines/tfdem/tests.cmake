# engines/tfdem: DEM particles in the averaged gas (Section 7.2.3).
grainbridge_add_test(test_tfdem
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/tfdem/ParticleDepositTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/tfdem/TfdemEngineTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/tfdem/ParticleBedMeasuresTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/tfdem/ParticleForcesTest.cpp
  LIBS engines_tfdem
  LABELS "unit;tfdem")

grainbridge_add_test(test_tfdem_physics
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/tfdem/TfdemPhysicsTest.cpp
  LIBS engines_tfdem
  LABELS "physics;tfdem"
  TIMEOUT 300)
