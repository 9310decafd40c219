# Warnings apply to our targets only; third-party headers are SYSTEM includes (imported
# targets), so -Werror never trips on Eigen, HDF5 or spdlog.
function(grainbridge_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wold-style-cast -Wcast-align -Woverloaded-virtual)
  if(GRAINBRIDGE_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
