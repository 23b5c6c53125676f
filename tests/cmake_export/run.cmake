# Installs the build tree into a temporary prefix, then configures, builds and runs the
# consumer project against it, builds and runs the same program with the flags of the installed
# gridcar.pc, checks a shared build's SONAME, and checks the installed gridcar finds its
# installed files.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK}/prefix"
  RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed: ${rc}")
endif()
# a sanitizer build's library needs a consumer built with the same sanitizers
set(flags "")
if(SANITIZE)
  set(flags "-DCMAKE_CXX_FLAGS=-fsanitize=${SANITIZE}" "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=${SANITIZE}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S "${SOURCE_DIR}/tests/cmake_export" -B "${WORK}/build"
  -DCMAKE_PREFIX_PATH=${WORK}/prefix -DCMAKE_BUILD_TYPE=Release ${flags} RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the consumer failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build "${WORK}/build" RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the consumer failed: ${rc}")
endif()
# every installed program and consumer runs with a clean environment (env -i: no
# LD_LIBRARY_PATH the caller may have set): the libraries find each other by their RUNPATH
execute_process(COMMAND env -i "${WORK}/build/consumer" RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the consumer failed: ${rc}")
endif()
# the installed gridcar runs the installed report script, not the source tree's
execute_process(COMMAND env -i "${WORK}/prefix/bin/gridcar" bench --help OUTPUT_VARIABLE out RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "installed gridcar bench --help failed: ${rc}")
endif()
string(FIND "${out}" "${WORK}/prefix/share/gridcar/bench_report.py" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "the installed gridcar does not default to the installed report script: ${out}")
endif()

# the installed program knows its version (gridcar/version.h)
execute_process(COMMAND env -i "${WORK}/prefix/bin/gridcar" --version OUTPUT_VARIABLE out RESULT_VARIABLE rc)
file(READ "${SOURCE_DIR}/CMakeLists.txt" top)
string(REGEX MATCH "project\\(gridcar VERSION ([0-9.]+)" _ "${top}")
set(version "${CMAKE_MATCH_1}")
if(rc OR NOT out MATCHES "^gridcar ${version} \\(OMPL [0-9]+\\.[0-9]+\\.[0-9]+\\)")
  message(FATAL_ERROR "installed gridcar --version: '${out}' (expected gridcar ${version} and OMPL's version)")
endif()

# pkg-config: the same consumer built with `pkg-config --cflags --libs gridcar` (--static for the
# static libraries, which then bring yaml-cpp), nothing else on the command line
file(GLOB_RECURSE pcfiles "${WORK}/prefix/*/gridcar.pc")
list(LENGTH pcfiles npc)
if(NOT npc EQUAL 1)
  message(FATAL_ERROR "expected one installed gridcar.pc, found: ${pcfiles}")
endif()
get_filename_component(pcdir "${pcfiles}" DIRECTORY)
get_filename_component(libdir "${pcdir}" DIRECTORY)
set(static "")
if(NOT SHARED)
  set(static --static)
endif()
set(ENV{PKG_CONFIG_PATH} "${pcdir}")
execute_process(COMMAND pkg-config --cflags --libs ${static} gridcar OUTPUT_VARIABLE pcflags RESULT_VARIABLE rc
  ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "pkg-config --cflags --libs gridcar failed: ${err}")
endif()
execute_process(COMMAND pkg-config --modversion gridcar OUTPUT_VARIABLE pcver OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT pcver STREQUAL version)
  message(FATAL_ERROR "gridcar.pc says version '${pcver}', the project ${version}")
endif()
separate_arguments(pcflags UNIX_COMMAND "${pcflags}")
set(sanflags "")
if(SANITIZE)
  set(sanflags "-fsanitize=${SANITIZE}")
endif()
# -std after the flags: OMPL's own .pc file asks for -std=c++14, gridcar's headers need C++17
execute_process(COMMAND ${CXX} "${SOURCE_DIR}/tests/cmake_export/main.cpp" -o "${WORK}/consumer-pc" ${pcflags} -std=c++17
  ${sanflags} -Wl,-rpath,${libdir} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "building the consumer with gridcar.pc's flags failed: ${err}")
endif()
execute_process(COMMAND env -i "${WORK}/consumer-pc" RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(rc)
  message(FATAL_ERROR "the consumer built with gridcar.pc failed: ${rc} ${out}")
endif()

# a shared build: each library has the SONAME lib<name>.so.MAJOR.MINOR and its symlinks
if(SHARED)
  string(REGEX MATCH "^([0-9]+)\\.([0-9]+)" _ "${version}")
  set(so "${CMAKE_MATCH_1}.${CMAKE_MATCH_2}")
  foreach(lib gridcar_core gridcar_spaces gridcar_planners)
    if(NOT EXISTS "${libdir}/lib${lib}.so" OR NOT EXISTS "${libdir}/lib${lib}.so.${so}")
      message(FATAL_ERROR "no lib${lib}.so / lib${lib}.so.${so} in ${libdir}")
    endif()
    execute_process(COMMAND objdump -p "${libdir}/lib${lib}.so" OUTPUT_VARIABLE dyn)
    if(NOT dyn MATCHES "SONAME +lib${lib}\\.so\\.${so}\n")
      message(FATAL_ERROR "lib${lib}.so has no SONAME lib${lib}.so.${so}")
    endif()
  endforeach()
endif()

# the installed Python package: imported from the prefix's site-packages alone (a clean
# environment: no LD_LIBRARY_PATH, no build tree on the path), and it plans
if(PYTHON)
  set(code "import gridcar, numpy as np
occ = np.zeros((40, 80), bool); occ[0, :] = occ[-1, :] = occ[:, 0] = occ[:, -1] = True
r = gridcar.plan(gridcar.Map.from_array(occ, 0.5), (5, 5, 0), (30, 12, 0))
assert r.exact and r.drivable, r
print(gridcar.__file__)")
  execute_process(COMMAND env -i "PYTHONPATH=${WORK}/prefix/${PYTHON_DIR}" "${PYTHON}" -c "${code}"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc)
    message(FATAL_ERROR "the installed Python package failed (${rc}): ${out} ${err}")
  endif()
  if(NOT out MATCHES "^${WORK}/prefix/")
    message(FATAL_ERROR "python imported gridcar from ${out}, not from the installed prefix ${WORK}/prefix")
  endif()
endif()
