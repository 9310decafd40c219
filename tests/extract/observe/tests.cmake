# extract/observe: the per-frame analyses of the extract stage (surface verdict).
grainbridge_add_test(test_extract_observe
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/observe/SurfaceObserverTest.cpp
  LIBS extract
  LABELS "unit;extract")
