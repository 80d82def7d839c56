# Install.* (tests/CMakeLists.txt): `cmake --install` of this build into a fresh prefix, then the consumer
# project of examples/cpp configured with find_package(plyimpact) against that prefix alone, built, and
# run on a shipped deck. Checks that the installed package is complete (headers, libraries, the CMake
# package and its dependencies, the command, the Python package), not only that the build tree works.
# -DBUILD_DIR, -DSOURCE_DIR, -DWORK_DIR.
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix}
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
foreach(installed bin/plyimpact include/plyimpact/analysis/impact/impact_case.hpp lib/cmake/plyimpact/plyimpactConfig.cmake
                  share/doc/plyimpact/examples/thesis-3.6-v268.toml)
  if(NOT EXISTS ${prefix}/${installed})
    message(FATAL_ERROR "not installed: ${installed}")
  endif()
endforeach()
execute_process(COMMAND ${prefix}/bin/plyimpact --version OUTPUT_VARIABLE version RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT version MATCHES "^plyimpact [0-9]+\\.[0-9]+\\.[0-9]+")
  message(FATAL_ERROR "the installed command: --version gave ${rc}: ${version}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/cpp -B ${WORK_DIR}/build -G Ninja
                        -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the consumer does not configure against the installed package:\n${out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the consumer does not build:\n${out}")
endif()
execute_process(COMMAND ${WORK_DIR}/build/drop_weight ${prefix}/share/doc/plyimpact/examples/thesis-3.6-v268.toml
                WORKING_DIRECTORY ${prefix}/share/doc/plyimpact/examples
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the consumer failed (${rc})")
endif()
