# Install.DebianPackage (tests/CMakeLists.txt): `cpack -G DEB` of this build, its files and dependencies,
# apt's resolution of it on this machine (simulated: nothing is installed here), then the package
# installed by dpkg into a fresh root, its command run on the example it ships and its Python module
# imported. -DBUILD_DIR, -DWORK_DIR.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND cpack -G DEB -B ${WORK_DIR} WORKING_DIRECTORY ${BUILD_DIR}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
file(GLOB deb ${WORK_DIR}/plyimpact_*.deb)
if(NOT rc EQUAL 0 OR NOT deb)
  message(FATAL_ERROR "cpack failed (${rc}):\n${out}")
endif()
execute_process(COMMAND dpkg-deb --contents ${deb} OUTPUT_VARIABLE contents)
foreach(path ./usr/bin/plyimpact ./usr/include/plyimpact/analysis/impact/impact_case.hpp
             ./usr/lib/cmake/plyimpact/plyimpactConfig.cmake ./usr/lib/python3/dist-packages/plyimpact/__init__.py
             ./usr/share/doc/plyimpact/examples/thesis-3.6-v268.toml ./usr/share/doc/plyimpact/copyright
             ./usr/share/doc/plyimpact/LICENSE)
  string(FIND "${contents}" " ${path}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the package lacks ${path}")
  endif()
endforeach()
# The licence the package carries (docs/install.md, "Licence"): Debian's copyright file names it.
execute_process(COMMAND dpkg-deb --fsys-tarfile ${deb} COMMAND tar -xO ./usr/share/doc/plyimpact/copyright
                OUTPUT_VARIABLE copyright)
if(NOT copyright MATCHES "Files: \\*\nCopyright: [^\n]+\nLicense: GPL-3\\+")
  message(FATAL_ERROR "the package's copyright file does not name the licence:\n${copyright}")
endif()
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
# Installed by dpkg into a fresh root with its own, empty package database: the package's files land
# where a system install puts them, and dpkg registers it. Its dependencies are this machine's libraries
# (checked above by apt), hence --force-depends; its maintainer scripts (none) would run outside the root.
set(root ${WORK_DIR}/root)
file(MAKE_DIRECTORY ${root}/var/lib/dpkg/info ${root}/var/lib/dpkg/updates)
file(TOUCH ${root}/var/lib/dpkg/status)
execute_process(COMMAND dpkg --root=${root} --force-depends --force-script-chrootless --force-not-root -i ${deb}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
execute_process(COMMAND dpkg-query --admindir=${root}/var/lib/dpkg -W "-f=\${Status}" plyimpact
                OUTPUT_VARIABLE status)
if(NOT rc EQUAL 0 OR NOT status STREQUAL "install ok installed")
  message(FATAL_ERROR "dpkg did not install the package into ${root} (${rc}, ${status}):\n${out}")
endif()
set(examples ${root}/usr/share/doc/plyimpact/examples)
execute_process(COMMAND ${root}/usr/bin/plyimpact impact ${examples}/thesis-3.6-v268.toml
                        -o ${WORK_DIR}/run --quiet
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT EXISTS ${WORK_DIR}/run/summary.json)
  message(FATAL_ERROR "the packaged command failed (${rc}):\n${out}")
endif()
file(READ ${WORK_DIR}/run/summary.json summary)
string(JSON peak GET "${summary}" peak_force)
message("packaged command: peak force ${peak} N")
# The Python package it ships, where Debian's interpreter looks (/usr/lib/python3/dist-packages).
execute_process(COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${root}/usr/lib/python3/dist-packages
                        /usr/bin/python3 -c "import plyimpact; print('packaged module:', plyimpact.__file__)"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "${root}/usr/lib/python3/dist-packages/plyimpact/__init__.py")
  message(FATAL_ERROR "the packaged Python module does not import")
endif()
