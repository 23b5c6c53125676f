# Fails when README.md's example differs from the compiled one in tests/test_readme_example.cpp.
file(READ "${SOURCE_DIR}/tests/test_readme_example.cpp" src)
file(READ "${SOURCE_DIR}/README.md" readme)
string(REGEX MATCH "// README-EXAMPLE-BEGIN\n(.*)// README-EXAMPLE-END" _ "${src}")
set(example "${CMAKE_MATCH_1}")
string(FIND "${readme}" "${example}" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "README.md does not contain the example of tests/test_readme_example.cpp verbatim")
endif()
