# core/grid: particle-to-grid kernels shared by extract and TF-DEM (Eqs. 7.35-7.36, exact
# sphere-cell overlap, Gaussian and Lucy kernels, segment clipping).
grainbridge_add_test(test_core_grid
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/grid/CellGridTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/grid/SphereBoxOverlapTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/grid/SphereCellOverlapTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/grid/SolidsCellAveragesTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/grid/SmoothingKernelTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/grid/KernelCellSharesTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/grid/SegmentCellSharesTest.cpp
  LIBS core
  LABELS "unit;core")
