# dtwin_library(<name> SOURCES ... HEADERS ... [PUBLIC ...] [PRIVATE ...] [HEADER_DIR dir])
# One library of the project: target dtwin_<name> with alias dtwin::<name>, the project root on
# its include path, the project's warnings, exported as dtwin::<name> by `install`, and the headers
# of its folder (when it lists HEADERS) installed under include/dtwin/<HEADER_DIR, default name>/.
function(dtwin_library name)
  cmake_parse_arguments(L "" "HEADER_DIR" "SOURCES;HEADERS;PUBLIC;PRIVATE" ${ARGN})
  if(L_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "dtwin_library(${name}): unknown arguments ${L_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT L_HEADER_DIR)
    set(L_HEADER_DIR ${name})
  endif()
  set(target dtwin_${name})
  add_library(${target} ${L_SOURCES})
  add_library(dtwin::${name} ALIAS ${target})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:include/dtwin>)
  target_link_libraries(${target} PUBLIC ${L_PUBLIC} PRIVATE ${L_PRIVATE})
  if(DTWIN_SIMBODY_NDEBUG)  # a program built on these libraries must share Simbody's NDEBUG (CMakeLists.txt)
    target_compile_definitions(${target} PUBLIC NDEBUG)
  endif()
  target_compile_options(${target} PRIVATE ${DTWIN_WARNINGS})
  dtwin_use_pch(${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME ${target})
  install(TARGETS ${target} EXPORT dtwinTargets ARCHIVE DESTINATION lib LIBRARY DESTINATION lib)
  # Every header of the library's folder and its subfolders (effects/, roads/), not only those
  # listed: a listed header includes others, and a program built on the installed package needs
  # them all (tests/install/).
  if(L_HEADERS)
    install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/ DESTINATION include/dtwin/${L_HEADER_DIR}
            FILES_MATCHING PATTERN "*.hpp")
  endif()
endfunction()

# Precompiled headers (DTWIN_PCH, on by default): nlohmann/json.hpp, Eigen/Dense and the standard
# headers that nearly every file includes (calibration/calibrate.hpp brings in Eigen) are parsed
# once, in dtwin_common, and every other library, the `twin` program and the tests reuse that
# result (docs/performance.md, "Build time").
function(dtwin_use_pch target)
  if(NOT DTWIN_PCH)
    return()
  endif()
  if(target STREQUAL "dtwin_common")
    target_link_libraries(dtwin_common PRIVATE Eigen3::Eigen)
    target_precompile_headers(dtwin_common PRIVATE <nlohmann/json.hpp> <Eigen/Dense> <string> <vector> <map> <memory> <functional>)
  else()
    target_precompile_headers(${target} REUSE_FROM dtwin_common)
  endif()
endfunction()
