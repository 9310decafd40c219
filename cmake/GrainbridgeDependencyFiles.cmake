# Writes <build>/dependency-files.tsv: every file or folder outside the project that the configure
# step resolved for a dependency, one per line as "<scope>\t<origin>\t<path>":
#   - cache entries of type FILEPATH or PATH (libraries, headers' folders, programs, CMake package
#     folders), except CMake's own toolchain entries (CMAKE_*);
#   - the files the imported targets reference (IMPORTED_LOCATION per configuration, include
#     folders, libraries linked by path), which a CMake package checks when it is loaded.
# <scope> is `tests` for what only the test suite resolves (the targets tests/ imports and the
# cache entries it declares in the global property GRAINBRIDGE_TEST_CACHE_ENTRIES), else `base`. The
# dependency_packages test (tests/build) names each path's Debian package and checks it against
# scripts/install-deps.sh's lists (issue 54).

# Records the files of the imported targets visible in the calling folder (imported targets are
# local to the folder whose find_package made them): call it in each folder that finds packages.
function(grainbridge_record_imported_targets scope)
  get_property(targets DIRECTORY PROPERTY IMPORTED_TARGETS)
  foreach(t IN LISTS targets)
    set(paths)
    get_target_property(type ${t} TYPE)
    if(NOT type STREQUAL "INTERFACE_LIBRARY")
      get_target_property(loc ${t} IMPORTED_LOCATION)
      list(APPEND paths ${loc})
      get_target_property(configs ${t} IMPORTED_CONFIGURATIONS)
      foreach(c IN LISTS configs)
        get_target_property(loc ${t} IMPORTED_LOCATION_${c})
        list(APPEND paths ${loc})
      endforeach()
    endif()
    get_target_property(incs ${t} INTERFACE_INCLUDE_DIRECTORIES)
    get_target_property(libs ${t} INTERFACE_LINK_LIBRARIES)
    list(APPEND paths ${incs} ${libs})
    foreach(p IN LISTS paths)
      # Absolute paths only: target names, -l flags and generator expressions are not files.
      if(p MATCHES "^/" AND NOT p MATCHES "[$<>]")
        set_property(GLOBAL APPEND PROPERTY GRAINBRIDGE_DEPENDENCY_LINES "${scope}\ttarget ${t}\t${p}")
      endif()
    endforeach()
  endforeach()
endfunction()

function(grainbridge_write_dependency_files)
  get_property(test_entries GLOBAL PROPERTY GRAINBRIDGE_TEST_CACHE_ENTRIES)
  get_cmake_property(entries CACHE_VARIABLES)
  set(lines)
  foreach(e IN LISTS entries)
    get_property(type CACHE ${e} PROPERTY TYPE)
    if(NOT type MATCHES "^(FILEPATH|PATH)$" OR e MATCHES "^CMAKE_")
      continue()
    endif()
    set(v "${${e}}")
    if(NOT v MATCHES "^/" OR NOT EXISTS "${v}")
      continue()  # -NOTFOUND, relative or gone
    endif()
    if(v MATCHES "^${PROJECT_SOURCE_DIR}(/|$)" OR v MATCHES "^${PROJECT_BINARY_DIR}(/|$)")
      continue()
    endif()
    set(scope base)
    if(e IN_LIST test_entries)
      set(scope tests)
    endif()
    list(APPEND lines "${scope}\tcache ${e}\t${v}")
  endforeach()
  grainbridge_record_imported_targets(base)
  get_property(target_lines GLOBAL PROPERTY GRAINBRIDGE_DEPENDENCY_LINES)
  list(APPEND lines ${target_lines})
  list(REMOVE_DUPLICATES lines)
  list(JOIN lines "\n" text)
  file(WRITE ${PROJECT_BINARY_DIR}/dependency-files.tsv "${text}\n")
endfunction()
