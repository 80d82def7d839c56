# Install.DebianPackage (tests/CMakeLists.txt): `cpack -G DEB` of this build, its files and dependencies,
# apt's resolution of it on this machine (simulated: nothing is installed), and the command it ships,
# unpacked into a folder, run on the example it ships. -DBUILD_DIR, -DWORK_DIR.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND cpack -G DEB -B ${WORK_DIR} WORKING_DIRECTORY ${BUILD_DIR}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
file(GLOB deb ${WORK_DIR}/plyimpact_*.deb)
if(NOT rc EQUAL 0 OR NOT deb)
  message(FATAL_ERROR "cpack failed (${rc}):\n${out}")
endif()
execute_process(COMMAND dpkg-deb --contents ${deb} OUTPUT_VARIABLE contents)
foreach(path ./usr/bin/plyimpact ./usr/include/plyimpact/analysis/impact_case.hpp
             ./usr/lib/cmake/plyimpact/plyimpactConfig.cmake ./usr/lib/python3/dist-packages/plyimpact/__init__.py
             ./usr/share/doc/plyimpact/examples/thesis-3.6-v268.toml)
  string(FIND "${contents}" " ${path}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the package lacks ${path}")
  endif()
endforeach()
execute_process(COMMAND dpkg-deb --field ${deb} Depends OUTPUT_VARIABLE depends)
message("Depends: ${depends}")
foreach(package libgmsh libcholmod gnuplot-nox)
  string(FIND "${depends}" "${package}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the package does not depend on ${package}")
  endif()
endforeach()
execute_process(COMMAND apt-get install --simulate --no-install-recommends ${deb}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "apt cannot resolve the package's dependencies here:\n${out}")
endif()
execute_process(COMMAND dpkg-deb -x ${deb} ${WORK_DIR}/root RESULT_VARIABLE rc)
set(examples ${WORK_DIR}/root/usr/share/doc/plyimpact/examples)
execute_process(COMMAND ${WORK_DIR}/root/usr/bin/plyimpact impact ${examples}/thesis-3.6-v268.toml
                        -o ${WORK_DIR}/run --quiet
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT EXISTS ${WORK_DIR}/run/summary.json)
  message(FATAL_ERROR "the packaged command failed (${rc}):\n${out}")
endif()
file(READ ${WORK_DIR}/run/summary.json summary)
string(JSON peak GET "${summary}" peak_force)
message("packaged command: peak force ${peak} N")
