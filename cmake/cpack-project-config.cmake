# Read by cpack before it packs anything (CPACK_PROJECT_CONFIG_FILE, CMakeLists.txt). A .deb takes its
# Depends line from dpkg-shlibdeps (Debian's dpkg-dev): without it CPack warns and still makes the package,
# naming only gmsh and gnuplot, and the installed command then fails with "libfmt.so.9: cannot open shared
# object file" (issue 82). Such a package is refused here, with what to install.
if(CPACK_GENERATOR STREQUAL "DEB")
  find_program(PLYIMPACT_DPKG_SHLIBDEPS dpkg-shlibdeps NO_CACHE NO_CMAKE_SYSTEM_PATH)
  if(NOT PLYIMPACT_DPKG_SHLIBDEPS)
    message(FATAL_ERROR
      "plyimpact: no .deb made: dpkg-shlibdeps is not on PATH, and without it the package could not name the "
      "libraries the command needs (CHOLMOD, fmt, toml++, VTK, ...), so it would install a command that does "
      "not start. Install Debian's dpkg-dev (sudo apt-get install dpkg-dev, or scripts/install-deps) and run "
      "cpack again (docs/install.md, \"A Debian package\").")
  endif()
endif()
