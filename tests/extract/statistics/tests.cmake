# extract/statistics: force PDFs and their fits (Eqs. 6.11, 6.13), the mu(I) and phi(I) fits, correlations (Eq. 6.12) and
# their lengths, velocity moments.
grainbridge_add_test(test_extract_statistics
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/statistics/ForcePdfTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/statistics/InertialRheologyFitTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/statistics/PairCorrelationTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/statistics/VelocityMomentsTest.cpp
  LIBS extract
  LABELS "unit;extract")
