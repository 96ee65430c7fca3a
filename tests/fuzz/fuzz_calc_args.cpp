// Fuzzes `impetus calc` (apps/cli/calc): the input is an argument list, one token per line (a
// NUL also ends a token), as the shell would pass it after the word "calc": leading --list and
// --json flags, the model name, then the model's own --param value (or --param=value) tokens.
// It goes through runCalc, the code the CLI runs, with its output captured.
//
// Checked, for every input:
//  - runCalc returns 0 (a result, the model's help or the list) or 2 (a usage error or an
//    impetus::Error, one line on stderr); no crash, no sanitizer report, no other exception (a
//    std::logic_error from a model reading an undeclared parameter would escape);
//  - a result (status 0, a model named, no --help) has every output finite: in JSON each output
//    number is a finite number (nlohmann writes NaN and infinities as null), in text no output
//    value reads nan or inf.
// Models with a file parameter (composite) are skipped: a fuzzer must not open arbitrary paths
// (/dev/zero never ends).
#include "fuzz_support.hpp"

#include "calc/calc.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <string>
#include <typeinfo>
#include <vector>

namespace {

namespace cli = impetus::cli;
using nlohmann::json;

/// What runCalc wrote to stdout and stderr. It prints through the C streams (fmt::print), so
/// the harness points stdout and stderr at memory streams for the call; sanitizer reports are
/// written to file descriptor 2 directly and still show.
struct Captured {
  int status = 0;
  std::string out;
  std::string err;
};

class MemoryStream {
public:
  MemoryStream() : file_(open_memstream(&buffer_, &size_)) {}
  ~MemoryStream() {
    if (file_ != nullptr) {
      std::fclose(file_);
    }
    std::free(buffer_);
  }
  MemoryStream(const MemoryStream&) = delete;
  MemoryStream& operator=(const MemoryStream&) = delete;
  [[nodiscard]] FILE* file() const { return file_; }
  std::string take() {
    std::fclose(file_);
    file_ = nullptr;
    return {buffer_, size_};
  }

private:
  char* buffer_ = nullptr;
  std::size_t size_ = 0;
  FILE* file_;
};

Captured run(bool list, bool asJson, const std::string& model, const std::vector<std::string>& extra) {
  MemoryStream out;
  MemoryStream err;
  FUZZ_CHECK(out.file() != nullptr && err.file() != nullptr, "open_memstream failed");
  std::fflush(stdout);
  FILE* const savedOut = stdout;
  FILE* const savedErr = stderr;
  stdout = out.file(); // glibc's stdout and stderr are assignable FILE* variables
  stderr = err.file();
  Captured c;
  try {
    c.status = cli::runCalc(list, asJson, model, extra);
  } catch (const std::exception& e) {
    stdout = savedOut;
    stderr = savedErr;
    FUZZ_CHECK(false, std::string("runCalc threw ") + typeid(e).name() + ": " + e.what());
  } catch (...) {
    stdout = savedOut;
    stderr = savedErr;
    FUZZ_CHECK(false, "runCalc threw something that is not a std::exception");
  }
  stdout = savedOut;
  stderr = savedErr;
  c.out = out.take();
  c.err = err.take();
  return c;
}

/// Every number in `v` is finite (null: NaN or an infinity written by nlohmann).
bool allFinite(const json& v) {
  if (v.is_null()) {
    return false;
  }
  if (v.is_array()) {
    return std::all_of(v.begin(), v.end(), [](const json& e) { return allFinite(e); });
  }
  return true;
}

/// A text result's value (between " = " and the unit) holds no nan or inf.
bool textValueFinite(const std::string& value) {
  std::string words = value;
  std::replace_if(
      words.begin(), words.end(), [](char c) { return c == '(' || c == ')' || c == '[' || c == ']' || c == ','; }, ' ');
  std::istringstream in(words);
  for (std::string w; in >> w;) {
    if (w == "nan" || w == "-nan" || w == "inf" || w == "-inf") {
      return false;
    }
  }
  return true;
}

void checkResult(const Captured& c, bool asJson, const std::string& command) {
  if (asJson) {
    json doc;
    try {
      doc = json::parse(c.out);
    } catch (const json::exception& e) {
      FUZZ_CHECK(false, command + ": the JSON result does not parse (" + e.what() + "):\n" + c.out);
    }
    FUZZ_CHECK(doc.is_object() && doc.contains("outputs") && doc["outputs"].is_object(),
               command + ": no outputs in\n" + c.out);
    for (const auto& item : doc["outputs"].items()) {
      FUZZ_CHECK(allFinite(item.value()["value"]),
                 command + ": output " + item.key() + " is not finite: " + item.value().dump());
    }
    return;
  }
  // Text: "results:" then one "  name = value unit" line per output, then "note: ..." lines.
  const std::size_t start = c.out.find("\nresults:\n");
  FUZZ_CHECK(start != std::string::npos, command + ": no results in\n" + c.out);
  std::istringstream lines(c.out.substr(start + 10));
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("note: ", 0) == 0) {
      break;
    }
    const std::size_t eq = line.find(" = ");
    FUZZ_CHECK(eq != std::string::npos, command + ": unexpected result line '" + line + "'");
    FUZZ_CHECK(textValueFinite(line.substr(eq + 3)), command + ": output not finite: '" + line + "'");
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Tokens: lines, a NUL also ending one (argv cannot hold a NUL). A command line has a few
  // dozen tokens at most.
  std::vector<std::string> tokens(1);
  for (std::size_t i = 0; i < size; ++i) {
    const char c = static_cast<char>(data[i]);
    if (c == '\n' || c == '\0') {
      tokens.emplace_back();
    } else {
      tokens.back().push_back(c);
    }
  }
  if (size == 0 || tokens.size() > 64) {
    return 0;
  }

  // As CLI11 hands them to runCalc: the flags before the model name, the model name, the rest.
  bool list = false;
  bool asJson = false;
  std::size_t k = 0;
  for (; k < tokens.size() && (tokens[k] == "--list" || tokens[k] == "--json"); ++k) {
    (tokens[k] == "--list" ? list : asJson) = true;
  }
  const std::string model = k < tokens.size() ? tokens[k++] : std::string();
  const std::vector<std::string> extra(tokens.begin() + static_cast<std::ptrdiff_t>(k), tokens.end());

  if (const cli::Model* m = cli::registry().find(model)) {
    const bool opensFiles = std::any_of(m->params.begin(), m->params.end(),
                                        [](const cli::Param& p) { return p.kind == cli::ParamKind::path; });
    if (opensFiles) {
      return 0;
    }
  }

  std::string command = "impetus calc";
  for (const std::string& t : tokens) {
    command += " '";
    command += t;
    command += "'";
  }
  const Captured c = run(list, asJson, model, extra);
  FUZZ_CHECK(c.status == 0 || c.status == 2, command + ": exit status " + std::to_string(c.status));
  if (c.status == 2) {
    // One line on stderr, "error: ...".
    FUZZ_CHECK(c.err.rfind("error: ", 0) == 0 && !c.err.empty() && c.err.back() == '\n',
               command + ": a refusal without its one-line error: '" + c.err + "'");
    return 0;
  }
  // Which of --json and --help runCalc saw: the same walk as its parser (a token after
  // "--name" is that parameter's value, whatever it reads).
  bool help = false;
  bool jsonOut = asJson;
  for (std::size_t i = 0; i < extra.size(); ++i) {
    if (extra[i] == "--json") {
      jsonOut = true;
    } else if (extra[i] == "--help" || extra[i] == "-h") {
      help = true;
    } else if (extra[i].find('=') == std::string::npos) {
      ++i;
    }
  }
  if (!list && !help) {
    checkResult(c, jsonOut, command);
  }
  return 0;
}
