# cmake -DBINARY=<the rtvk executable> -DPROBES=<tests/gpu/probes> -P check_no_test_code.cmake
# Fails when rtvk carries the tests' probes: a probe shader's SPIR-V (its names: every probe's
# buffer is a `probe_block`, its struct a `*_probe_entry` or `probe_io`) or the arrays and
# functions that hold and run them. The probes are test code (tests/gpu/probes, built into
# rtvk_test_probes only). The strings are read out of the binary as `strings` would: SPIR-V keeps
# its names as plain bytes, and the check first finds a shader rtvk must carry (render.comp's
# `camera_block`), so that a binary whose SPIR-V it could not read fails rather than passes.
cmake_minimum_required(VERSION 3.25)

if(NOT EXISTS "${BINARY}")
  message(FATAL_ERROR "no binary at '${BINARY}'")
endif()
file(STRINGS "${BINARY}" production REGEX "camera_block")
if(NOT production)
  message(FATAL_ERROR "${BINARY}: render.comp's camera_block not found: are the shaders embedded?")
endif()

# Every probe shader's own name too (probe.comp, rng_probe.comp, ...: the arrays probe_spv,
# rng_probe_spv, ... where symbols are kept), from the probes' folder.
file(GLOB probe_shaders RELATIVE "${PROBES}" "${PROBES}/*.comp")
list(LENGTH probe_shaders count)
if(count LESS 6)
  message(FATAL_ERROR "only ${count} probe shaders under '${PROBES}': wrong PROBES?")
endif()
set(names "probe_block|probe_io|_probe_entry|run_[a-z]+_probe")
foreach(shader IN LISTS probe_shaders)
  string(REGEX REPLACE "\\.comp$" "_spv" array "${shader}")
  string(APPEND names "|${array}")
endforeach()

file(STRINGS "${BINARY}" found REGEX "(${names})")
if(found)
  list(REMOVE_DUPLICATES found)
  list(JOIN found "\n  " text)
  message(FATAL_ERROR "${BINARY} carries test probes (tests/gpu/probes):\n  ${text}")
endif()
message(STATUS "${BINARY}: none of the ${count} probe shaders, their structs or runners")
