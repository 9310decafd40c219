# engines/particle_engines: the list of particle engines the dem stage runs on.
grainbridge_add_test(test_particle_engines
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/particle_engines/ParticleEnginesTest.cpp
  LIBS engines_particle_engines
  LABELS "unit;dem")
