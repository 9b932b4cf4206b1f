# Run at every build (cmake -P): writes version.cpp only when `git describe` changed, so a
# commit updates --version without rebuilding anything else.
execute_process(COMMAND git describe --always --dirty --tags
  WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE GIT_VERSION
  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(GIT_VERSION)
  set(CMP_VERSION "${PROJECT_VERSION}-${GIT_VERSION}")
else()
  set(CMP_VERSION "${PROJECT_VERSION}")
endif()
configure_file(${SOURCE_DIR}/cmake/version.cpp.in ${OUTPUT}.new @ONLY)
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different ${OUTPUT}.new ${OUTPUT})
