# What `cmake --install` puts beside bin/rtvk (host/app installs the binary): the docs, a man
# page and a bash completion. The last two are made by running the built rtvk, so they cannot
# disagree with its --help.
include_guard(GLOBAL)

# README.md's links point into docs/, so the docs keep that layout.
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs DESTINATION ${CMAKE_INSTALL_DOCDIR})

# Everything `cmake --install` installs (rtvk, librtvk.so and the Python module with the files
# below), built without the rest of the project: a whole build of
# the release preset also compiles the test suite and the benchmarks, more than half of its
# compile time. scripts/render.sh builds this target, so the README's install works right after
# it.
add_custom_target(rtvk_install_files)
add_dependencies(rtvk_install_files rtvk rtvk_library)
if(TARGET rtvk_python)
  add_dependencies(rtvk_install_files rtvk_python)
endif()

set(_rtvk_doc ${PROJECT_SOURCE_DIR}/host/app/doc)
if(CMAKE_CROSSCOMPILING)
  message(STATUS "rtvk: cross-compiling, so no man page and no bash completion (both run rtvk)")
  return()
endif()

add_custom_command(
  OUTPUT rtvk.bash
  COMMAND bash ${_rtvk_doc}/gen-completion.sh $<TARGET_FILE:rtvk> rtvk.bash
  DEPENDS rtvk ${_rtvk_doc}/gen-completion.sh
  COMMENT "Generating the bash completion from rtvk --help")
add_custom_target(rtvk_completion ALL DEPENDS rtvk.bash)
add_dependencies(rtvk_install_files rtvk_completion)
install(FILES ${PROJECT_BINARY_DIR}/rtvk.bash DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
        RENAME rtvk)

find_program(HELP2MAN help2man)
if(NOT HELP2MAN)
  message(STATUS "rtvk: help2man not found (Debian: apt install help2man), so no man page")
  return()
endif()
# Gzipped without a timestamp (gzip -n), as Debian ships man pages.
add_custom_command(
  OUTPUT rtvk.1.gz
  COMMAND bash ${_rtvk_doc}/gen-man.sh $<TARGET_FILE:rtvk> ${_rtvk_doc}/rtvk.h2m rtvk.1.gz
  DEPENDS rtvk ${_rtvk_doc}/gen-man.sh ${_rtvk_doc}/rtvk.h2m
  COMMENT "Generating the man page from rtvk --help with help2man")
add_custom_target(rtvk_man ALL DEPENDS rtvk.1.gz)
add_dependencies(rtvk_install_files rtvk_man)
install(FILES ${PROJECT_BINARY_DIR}/rtvk.1.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
