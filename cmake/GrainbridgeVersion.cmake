# The code version (git SHA + dirty flag) is provenance: it goes into every artifact and run
# record, never into a stage key. It is regenerated on every build so a rebuild after an edit
# records the dirty flag; the generated file only changes (and recompiles) when the value does.
set(GRAINBRIDGE_VERSION_CPP ${CMAKE_BINARY_DIR}/generated/core/BuildVersion.cpp)
add_custom_target(grainbridge_version_stamp
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${CMAKE_SOURCE_DIR} -DOUTPUT=${GRAINBRIDGE_VERSION_CPP}
          -DPROJECT_VERSION=${PROJECT_VERSION} -P ${CMAKE_SOURCE_DIR}/cmake/WriteBuildVersion.cmake
  BYPRODUCTS ${GRAINBRIDGE_VERSION_CPP}
  COMMENT "Stamping git version")
