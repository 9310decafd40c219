# extract/geometry: the minimum image of a frame's box and the cell-list pair search that the
# correlations (Eq. 6.12) and the MST candidates (Section 6.3.3) share, against all-pairs loops.
grainbridge_add_test(test_extract_geometry
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/geometry/PeriodicBoxTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/geometry/PairSearchTest.cpp
  LIBS extract
  LABELS "unit;extract")
