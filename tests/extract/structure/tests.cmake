# extract/structure: force networks and the multi-pass MST (Sections 6.3.2-6.3.3), against
# brute-force Kruskal and the five-particle example of Fig. 6.13; the local free surface over a particle; bond-orientational order (fcc against a random gas).
grainbridge_add_test(test_extract_structure
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/structure/ForceNetworksTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/structure/MultiPassMstTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/structure/LocalFreeSurfaceTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/structure/MstTreeContactsTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/structure/BondOrderTest.cpp
  LIBS extract
  LABELS "unit;extract")
