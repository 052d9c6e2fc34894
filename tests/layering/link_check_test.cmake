# cmake -P: builds tests/layering/link_fixture twice, once with lower declared to use upper
# (it must build) and once without (lower's link check must fail on upper's function).
# Variables: FIXTURE (its folder), WORK (a scratch folder), RIGDESIGN_CMAKE_DIR, CXX.
foreach(uses ON OFF)
  set(build ${WORK}/uses_${uses})
  file(REMOVE_RECURSE ${build})
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${FIXTURE} -B ${build} -DLOWER_USES_UPPER=${uses}
                          -DRIGDESIGN_CMAKE_DIR=${RIGDESIGN_CMAKE_DIR} -DCMAKE_CXX_COMPILER=${CXX}
                  RESULT_VARIABLE configured OUTPUT_VARIABLE log ERROR_VARIABLE log)
  if(NOT configured EQUAL 0)
    message(FATAL_ERROR "the fixture does not configure (uses ${uses}):\n${log}")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${build}
                  RESULT_VARIABLE built OUTPUT_VARIABLE log ERROR_VARIABLE log)
  if(uses AND NOT built EQUAL 0)
    message(FATAL_ERROR "lower uses upper and still fails to link:\n${log}")
  endif()
  if(NOT uses)
    if(built EQUAL 0)
      message(FATAL_ERROR "lower calls upper without using it, and its link check passed")
    endif()
    if(NOT log MATCHES "rigdesign_link_check_lower" OR NOT log MATCHES "upper_answer")
      message(FATAL_ERROR "the build failed, but not at lower's link check on upper_answer:\n${log}")
    endif()
  endif()
endforeach()
message(STATUS "link check: a module calling one it does not use fails to link")
