# The README's C++ example must be examples/minimal.cpp, word for word (that file is compiled
# and run by the test suite). Arguments: SOURCE_DIR.
file(READ "${SOURCE_DIR}/README.md" readme)
file(READ "${SOURCE_DIR}/examples/minimal.cpp" example)
string(FIND "${readme}" "```cpp\n${example}```" at)
if(at EQUAL -1)
  message(FATAL_ERROR "README.md does not contain examples/minimal.cpp verbatim in a ```cpp block")
endif()
