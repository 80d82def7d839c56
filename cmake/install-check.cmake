# Run first by `cmake --install` and `cpack` (install(CODE) in CMakeLists.txt): every file the install copies
# from the build must have been built. The README's first command (scripts/quickstart) builds the command
# alone, and an install after it stopped with rc 1 after copying 212 files, at the Python module it had not
# built (issue 82). Now nothing is copied and the message says what to run first.
# PLYIMPACT_INSTALL_NEEDS: the built files the install copies (a list).
set(missing)
foreach(f IN LISTS PLYIMPACT_INSTALL_NEEDS)
  if(NOT EXISTS "${f}")
    list(APPEND missing "${f}")
  endif()
endforeach()
if(missing)
  list(JOIN missing "\n  " shown)
  message(FATAL_ERROR
    "plyimpact: nothing installed: this build has not made\n  ${shown}\n"
    "(the README's first command, scripts/quickstart, builds the command alone). Build everything first,\n"
    "  cmake --build --preset release\n"
    "then run the install again (docs/install.md).")
endif()
