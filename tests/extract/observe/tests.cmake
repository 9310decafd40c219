# extract/observe: the per-frame analyses of the extract stage (surface verdict, the mean force ratio, the theta forms' errors).
grainbridge_add_test(test_extract_observe
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/observe/SurfaceObserverTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/observe/MeanForceRatioTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/observe/ThetaFormErrorsTest.cpp
  LIBS extract
  LABELS "unit;extract")
