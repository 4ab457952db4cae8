# Installs the package from BUILD into PREFIX, then configures, builds and
# runs the consumer project against it, with the CGAL of the package's build
# (CGAL_DIR, CGAL_VERSION): the consumer checks that it got that one.
foreach(step
    "${CMAKE_COMMAND};--install;${BUILD};--prefix;${PREFIX}"
    "${CMAKE_COMMAND};-S;${SOURCE};-B;${WORK};-DCMAKE_BUILD_TYPE=Release;-DCMAKE_PREFIX_PATH=${PREFIX};-DCGAL_DIR=${CGAL_DIR};-DEXPECTED_CGAL_VERSION=${CGAL_VERSION}"
    "${CMAKE_COMMAND};--build;${WORK}"
    "${WORK}/consumer")
  execute_process(COMMAND ${step} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "failed: ${step}")
  endif()
endforeach()
