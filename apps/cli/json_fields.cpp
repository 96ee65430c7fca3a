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

namespace {

/// Counts the elements of the top-level arrays named in the limits, stopping at the first over.
class ArrayCounter final : public nlohmann::json_sax<json> {
public:
  explicit ArrayCounter(std::initializer_list<ArrayLimit> limits) : limits_(limits) {}
  const ArrayLimit* exceeded = nullptr;

  bool null() override { return element(); }
  bool boolean(bool) override { return element(); }
  bool number_integer(number_integer_t) override { return element(); }
  bool number_unsigned(number_unsigned_t) override { return element(); }
  bool number_float(number_float_t, const string_t&) override { return element(); }
  bool string(string_t&) override { return element(); }
  bool binary(binary_t&) override { return element(); }
  bool start_object(std::size_t) override {
    const bool go = element();
    ++depth_;
    return go;
  }
  bool end_object() override { return leave(); }
  bool start_array(std::size_t) override {
    const bool go = element();
    ++depth_;
    if (depth_ == 2) {
      counting_ = lastKeyLimit_;
      count_ = 0;
    }
    return go;
  }
  bool end_array() override { return leave(); }
  bool key(string_t& k) override {
    if (depth_ == 1) {
      lastKeyLimit_ = nullptr;
      for (const ArrayLimit& l : limits_) {
        if (k == l.key) {
          lastKeyLimit_ = &l;
        }
      }
    }
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

private:
  /// A value begins at the current depth: an element of the counted array when at depth 2.
  bool element() {
    if (depth_ == 2 && counting_ != nullptr && ++count_ > counting_->limit) {
      exceeded = counting_;
      return false;
    }
    return true;
  }
  bool leave() {
    --depth_;
    if (depth_ < 2) {
      counting_ = nullptr;
    }
    return true;
  }

  std::initializer_list<ArrayLimit> limits_;
  const ArrayLimit* lastKeyLimit_ = nullptr;
  const ArrayLimit* counting_ = nullptr;
  std::size_t count_ = 0;
  int depth_ = 0;
};

} // namespace

void requireArrayLimits(const std::string& text, std::initializer_list<ArrayLimit> limits) {
  ArrayCounter counter(limits);
  (void)json::sax_parse(text, &counter, nlohmann::json::input_format_t::json, false);
  if (counter.exceeded != nullptr) {
    const std::string key = counter.exceeded->key;
    fail(index(key, counter.exceeded->limit),
         "more than " + std::to_string(counter.exceeded->limit) + " " + key + " in the scene");
  }
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
