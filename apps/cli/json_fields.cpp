#include "json_fields.hpp"

#include <fstream>
#include <sstream>

namespace impetus::cli::json_fields {

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    throw Error("file", "file = " + path + ": cannot be read");
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
  }
  if (!doc.is_object()) {
    fail("document", "expected " + expectation);
  }
  return doc;
}

} // namespace impetus::cli::json_fields
