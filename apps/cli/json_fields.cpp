#include "json_fields.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace impetus::cli::json_fields {

std::string readFile(const std::string& path) {
  // An ifstream opens a directory and reads nothing from it: say what it is.
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw Error("file", "file = " + path + ": is a directory, not a file");
  }
  std::ifstream in(path);
  if (!in) {
    throw Error("file", "file = " + path + (std::filesystem::exists(path, ec) ? ": cannot be read" : ": no such file"));
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

json parseObject(const std::string& text, const std::string& expectation) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    fail("json", std::string("malformed JSON: ") + e.what());
  } catch (const json::out_of_range& e) {
    // A number beyond a double (1e999) is reported as out_of_range, not as a parse error: left
    // uncaught it would abort the tool instead of naming the input.
    fail("json", std::string("number out of range: ") + e.what());
  }
  if (!doc.is_object()) {
    fail("document", "expected " + expectation);
  }
  return doc;
}

} // namespace impetus::cli::json_fields
