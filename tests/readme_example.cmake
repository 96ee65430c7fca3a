# The README's C++ examples must be examples/hello_world.cpp and examples/minimal.cpp, word for
# word (those files are compiled and run by the test suite). Arguments: SOURCE_DIR.
file(READ "${SOURCE_DIR}/README.md" readme)
foreach(name hello_world minimal)
  file(READ "${SOURCE_DIR}/examples/${name}.cpp" example)
  string(FIND "${readme}" "```cpp\n${example}```" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "README.md does not contain examples/${name}.cpp verbatim in a ```cpp block")
  endif()
endforeach()
