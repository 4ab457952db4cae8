# Checks on the files the example programs write, run by ctest:
#   cmake -DCHECK=mesh -DFILE=out.off -DMIN_FACES=1000 -P check_outputs.cmake
#   cmake -DCHECK=ply -DFILE=out.ply -DPOINTS=20000 -P check_outputs.cmake
#   cmake -DCHECK=rejected -DTOOL=rrht_normals "-DARGUMENTS=a|b|c" -P check_outputs.cmake
#   cmake -DCHECK=failed_run_keeps_output -DTOOL=rrht_normals -DGOOD=good.xyz -DINPUT=bad.xyz -DWORK=dir -P check_outputs.cmake
if(CHECK STREQUAL "mesh")
  # An OFF mesh with at least MIN_FACES faces.
  file(STRINGS "${FILE}" lines LIMIT_COUNT 2)
  list(GET lines 0 header)
  list(GET lines 1 counts)
  if(NOT header STREQUAL "OFF" OR NOT counts MATCHES "^([0-9]+) ([0-9]+) 0$")
    message(FATAL_ERROR "${FILE} is not an OFF file")
  endif()
  if(CMAKE_MATCH_2 LESS MIN_FACES)
    message(FATAL_ERROR "${FILE} has ${CMAKE_MATCH_2} faces, fewer than ${MIN_FACES}")
  endif()
  message(STATUS "${FILE}: ${CMAKE_MATCH_1} vertices, ${CMAKE_MATCH_2} faces")
elseif(CHECK STREQUAL "ply")
  # A PLY file of POINTS vertices with normals.
  file(STRINGS "${FILE}" header LIMIT_COUNT 12)
  string(REPLACE ";" "\n" header "${header}")
  if(NOT header MATCHES "element vertex ${POINTS}\n" OR NOT header MATCHES "property [a-z]+ nx\n"
     OR NOT header MATCHES "property [a-z]+ nz\n")
    message(FATAL_ERROR "${FILE} is not a PLY file of ${POINTS} points with normals:\n${header}")
  endif()
elseif(CHECK STREQUAL "failed_run_keeps_output")
  # A run that fails must leave a previous output as it was, and no partial file.
  file(REMOVE_RECURSE "${WORK}")
  file(MAKE_DIRECTORY "${WORK}")
  configure_file("${GOOD}" "${WORK}/out.xyz" COPYONLY)
  execute_process(COMMAND "${TOOL}" "${INPUT}" "${WORK}/out.xyz" -q RESULT_VARIABLE result)
  if(result EQUAL 0)
    message(FATAL_ERROR "the run on ${INPUT} should have failed")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${GOOD}" "${WORK}/out.xyz" RESULT_VARIABLE differ)
  if(differ)
    message(FATAL_ERROR "the failed run changed ${WORK}/out.xyz")
  endif()
  file(GLOB left "${WORK}/*")
  if(NOT left STREQUAL "${WORK}/out.xyz")
    message(FATAL_ERROR "the failed run left files behind: ${left}")
  endif()
elseif(CHECK STREQUAL "rejected")
  # A bad command line or file: exit code 1 or 2 (not a crash) and a message.
  string(REPLACE "|" ";" arguments "${ARGUMENTS}")
  execute_process(COMMAND "${TOOL}" ${arguments} RESULT_VARIABLE result ERROR_VARIABLE errors OUTPUT_QUIET)
  message(STATUS "exit code ${result}, stderr: ${errors}")
  if(NOT result MATCHES "^[12]$" OR NOT errors MATCHES "rrht_normals: ")
    message(FATAL_ERROR "expected exit code 1 or 2 and a message from rrht_normals")
  endif()
else()
  message(FATAL_ERROR "unknown CHECK '${CHECK}'")
endif()
