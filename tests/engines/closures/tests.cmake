# engines/closures: g0, the kinetic-theory models (lun1984, syamlal_algebraic and its MFIX form)
# against hand values, limits and identities between the models.
grainbridge_add_test(test_closures
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/closures/RadialDistributionTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/closures/MixturePackingTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/closures/Lun1984Test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/closures/SyamlalAlgebraicTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/closures/KineticModelTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/closures/TabulatedClosureTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/closures/GasSolidsDragTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/closures/DragLawsTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/closures/RadialDistributionVariantsTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/closures/EffectiveRestitutionTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/closures/SolidsSolidsDragTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/closures/PlasticRegimeTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/closures/InertialRheologyTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/closures/JohnsonJacksonTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/closures/GranularEnergyGasTermsTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/closures/ClosureModelTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/closures/MinimumFluidizationTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/closures/MixtureSimpleShearTest.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/closures/GhdTemperatureRatioTest.cpp
  LIBS engines_closures
  LABELS "unit;closures")
