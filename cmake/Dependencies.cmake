# find_package / pkg-config wrappers whose failure message names the Debian package to install.
function(gdr_require_package name debian)
  find_package(${name} QUIET)
  if(NOT ${name}_FOUND)
    message(FATAL_ERROR "gdrender needs ${name}: install it with `apt-get install ${debian}` "
                        "(or run scripts/setup.sh)")
  endif()
endfunction()

# OpenImageIO's CMake package on Debian bookworm lists a non-existent OpenCV include folder,
# so it is found through pkg-config instead.
function(gdr_require_pkgconfig target module debian)
  find_package(PkgConfig QUIET)
  if(NOT PkgConfig_FOUND)
    message(FATAL_ERROR "gdrender needs pkg-config: install it with `apt-get install pkg-config`")
  endif()
  pkg_check_modules(${target} QUIET IMPORTED_TARGET GLOBAL ${module})
  if(NOT ${target}_FOUND)
    message(FATAL_ERROR "gdrender needs ${module}: install it with `apt-get install ${debian}` "
                        "(or run scripts/setup.sh)")
  endif()
endfunction()
