# Install.DebianPackageWithoutShlibdepsIsRefused (tests/CMakeLists.txt): `cpack -G DEB` of this build with a
# PATH that holds no dpkg-shlibdeps exits non-zero, makes no .deb, and names the package to install.
# -DBUILD_DIR, -DWORK_DIR, -DCPACK.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/empty-path)
execute_process(COMMAND ${CMAKE_COMMAND} -E env PATH=${WORK_DIR}/empty-path ${CPACK} -G DEB -B ${WORK_DIR}
                WORKING_DIRECTORY ${BUILD_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
file(GLOB deb ${WORK_DIR}/*.deb)
if(rc EQUAL 0 OR deb)
  message(FATAL_ERROR "cpack made a package without dpkg-shlibdeps (rc ${rc}, ${deb}):\n${out}")
endif()
string(FIND "${out}" "dpkg-shlibdeps is not on PATH" said)
string(FIND "${out}" "dpkg-dev" advice)
if(said EQUAL -1 OR advice EQUAL -1)
  message(FATAL_ERROR "cpack failed without saying why (rc ${rc}):\n${out}")
endif()
message("refused: no .deb, rc ${rc}")
