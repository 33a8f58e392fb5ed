# cmake -DLIBRARY=<dtwin_fmu.so> "-DFIRST=<lib>;..." -P bundle_libraries.cmake
# Copies every shared library LIBRARY needs, directly or not, but the C and C++ runtimes every
# Linux has, into LIBRARY's folder under the name it is asked for by (its soname). Each must be a
# direct need of LIBRARY (fmu/CMakeLists.txt says why): one that is not fails the build, naming it.
# FIRST: the libraries the build linked that the system's path may hold in another build (Simbody:
# the Release one of scripts/simbody.sh beside Debian's), copied first, so that LIBRARY's run path
# finds them before the system's path does.
cmake_minimum_required(VERSION 3.21)  # IN_LIST, file(COPY_FILE)
get_filename_component(dest "${LIBRARY}" DIRECTORY)
# Those of an earlier build removed first: the libraries are found where they come from.
file(GLOB old "${dest}/lib*.so*")
if(old)
  file(REMOVE ${old})
endif()
foreach(lib IN LISTS FIRST)
  get_filename_component(name "${lib}" NAME)
  get_filename_component(real "${lib}" REALPATH)
  if(NOT real STREQUAL "${dest}/${name}")
    file(COPY_FILE "${real}" "${dest}/${name}")
  endif()
endforeach()
file(GET_RUNTIME_DEPENDENCIES
  LIBRARIES "${LIBRARY}"
  RESOLVED_DEPENDENCIES_VAR deps
  UNRESOLVED_DEPENDENCIES_VAR missing
  CONFLICTING_DEPENDENCIES_PREFIX conflict
  PRE_EXCLUDE_REGEXES "^ld-linux" "^linux-vdso" "^libc\\.so" "^libm\\.so" "^libdl\\.so"
                      "^libpthread\\.so" "^librt\\.so" "^libstdc\\+\\+\\.so" "^libgcc_s\\.so")
if(missing)
  message(FATAL_ERROR "dtwin_fmu: libraries not found: ${missing}")
endif()
# A FIRST library is also found on the system's path by a library without a run path: the copy
# here is the one the loader takes (by name, already loaded), so that is no conflict.
foreach(name IN LISTS conflict_FILENAMES)
  if(NOT "${dest}/${name}" IN_LIST conflict_${name})
    message(FATAL_ERROR "dtwin_fmu: ${name} is found in several places: ${conflict_${name}}")
  endif()
endforeach()
execute_process(COMMAND readelf -d "${LIBRARY}" OUTPUT_VARIABLE dynamic RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "dtwin_fmu: readelf -d ${LIBRARY} failed")
endif()
foreach(dep IN LISTS deps)
  get_filename_component(name "${dep}" NAME)
  get_filename_component(real "${dep}" REALPATH)
  string(FIND "${dynamic}" "Shared library: [${name}]" direct)
  if(direct EQUAL -1)
    message(FATAL_ERROR "dtwin_fmu: ${name} is needed only indirectly: add it to the direct needs "
                        "of dtwin_fmu (fmu/CMakeLists.txt), or the FMU would look for it outside itself")
  endif()
  if(NOT real STREQUAL "${dest}/${name}")
    file(COPY_FILE "${real}" "${dest}/${name}")
  endif()
endforeach()
