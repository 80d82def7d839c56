# Install.PipInstall (tests/CMakeLists.txt): `pip install --no-build-isolation --no-index .` into a fresh
# virtual environment that sees Debian's packages (numpy, tomli-w, setuptools), then its `plyimpact`
# command and `import plyimpact` outside the source tree. The compiled parts come from this build
# (PLYIMPACT_CMAKE_BUILD_DIR, setup.py), so nothing is compiled twice. -DBUILD_DIR, -DSOURCE_DIR,
# -DWORK_DIR, -DPYTHON (Debian's interpreter).
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${PYTHON} -m venv --system-site-packages ${WORK_DIR}/venv RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "python3 -m venv failed (${rc}): scripts/install-deps installs python3-venv")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env PLYIMPACT_CMAKE_BUILD_DIR=${BUILD_DIR}
                        ${WORK_DIR}/venv/bin/pip install --no-build-isolation --no-index ${SOURCE_DIR}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pip install failed (${rc}):\n${out}")
endif()
# The licence travels with the wheel (docs/install.md, "Licence"): LICENSE in its metadata folder, and the
# licence named in its metadata.
file(GLOB license ${WORK_DIR}/venv/lib/python3*/site-packages/plyimpact-*.dist-info/LICENSE)
file(GLOB metadata ${WORK_DIR}/venv/lib/python3*/site-packages/plyimpact-*.dist-info/METADATA)
if(NOT license OR NOT metadata)
  message(FATAL_ERROR "the installed package carries no LICENSE or METADATA")
endif()
file(READ ${metadata} metadata_text)
if(NOT metadata_text MATCHES "License: GPL-3.0-or-later")
  message(FATAL_ERROR "the package's metadata does not name the licence:\n${metadata_text}")
endif()
execute_process(COMMAND ${WORK_DIR}/venv/bin/plyimpact --version OUTPUT_VARIABLE version RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT version MATCHES "^plyimpact [0-9]+\\.[0-9]+\\.[0-9]+")
  message(FATAL_ERROR "the installed command: --version gave ${rc}: ${version}")
endif()
# The wheel carries the example decks (issue 82), and the installed command runs one of them.
file(GLOB shipped ${WORK_DIR}/venv/lib/python3*/site-packages/plyimpact/examples/thesis-3.6-v268.toml)
file(GLOB shipped_meshes ${WORK_DIR}/venv/lib/python3*/site-packages/plyimpact/examples/meshes/*.geo)
if(NOT shipped OR NOT shipped_meshes)
  message(FATAL_ERROR "the installed package carries no example decks (plyimpact/examples)")
endif()
execute_process(COMMAND ${WORK_DIR}/venv/bin/plyimpact impact ${shipped} -o ${WORK_DIR}/shipped-run -q
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT EXISTS ${WORK_DIR}/shipped-run/summary.json)
  message(FATAL_ERROR "the installed command did not run the shipped example (${rc}):\n${out}")
endif()
execute_process(COMMAND ${WORK_DIR}/venv/bin/python -c
                        "import plyimpact; r = plyimpact.impact('${SOURCE_DIR}/examples/thesis-3.6-v268.toml'); print(plyimpact.__file__); print('pip-installed module: peak force %.2f N' % r['peak_force'])"
                WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "/venv/lib/python3[^/]*/site-packages/plyimpact/__init__.py")
  message(FATAL_ERROR "import plyimpact did not load the installed package (${rc})")
endif()
# An editable install (pip install -e .) gives the command too (issue 82: it gave none): the module, the
# command and the examples land in the package's sources (ignored by git), removed again afterwards.
execute_process(COMMAND ${PYTHON} -m venv --system-site-packages ${WORK_DIR}/editable-venv)
execute_process(COMMAND ${CMAKE_COMMAND} -E env PLYIMPACT_CMAKE_BUILD_DIR=${BUILD_DIR}
                        ${WORK_DIR}/editable-venv/bin/pip install --no-build-isolation --no-index -e ${SOURCE_DIR}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pip install -e failed (${rc}):\n${out}")
endif()
execute_process(COMMAND ${WORK_DIR}/editable-venv/bin/plyimpact --version WORKING_DIRECTORY ${WORK_DIR}
                OUTPUT_VARIABLE version ERROR_VARIABLE version RESULT_VARIABLE rc)
file(GLOB built_in_sources ${SOURCE_DIR}/python/plyimpact/_core*.so)
file(REMOVE_RECURSE ${built_in_sources} ${SOURCE_DIR}/python/plyimpact/_bin ${SOURCE_DIR}/python/plyimpact/examples)
if(NOT rc EQUAL 0 OR NOT version MATCHES "^plyimpact [0-9]+\\.[0-9]+\\.[0-9]+")
  message(FATAL_ERROR "the editable install's command: --version gave ${rc}: ${version}")
endif()
message("editable install: ${version}")
