// The docs' runnable commands, run: every fenced block marked ```console in README.md and
// docs/*.md is a session, each `$ impetus ...` line a command run from the repository's root and
// the lines after it (up to the next `$` line) what it prints. Each shown line must be a line of
// the command's output (stdout and stderr together); one ending in "..." need only begin one. So
// the docs cannot go stale: a changed message or number fails here first.
#include "cli_process.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct DocCommand {
  std::string file;
  int line = 0;
  std::string command;             ///< after "$ impetus "
  std::vector<std::string> output; ///< the lines the doc shows
};

/// The console sessions of one Markdown file.
std::vector<DocCommand> consoleCommands(const fs::path& path) {
  std::vector<DocCommand> commands;
  std::ifstream in(path);
  bool inConsole = false;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.rfind("```", 0) == 0) {
      inConsole = !inConsole && line == "```console";
      continue;
    }
    if (!inConsole) {
      continue;
    }
    if (line.rfind("$ impetus ", 0) == 0) {
      commands.push_back({path.filename().string(), number, line.substr(10), {}});
    } else if (!commands.empty() && !line.empty()) {
      commands.back().output.push_back(line);
    }
  }
  return commands;
}

std::vector<DocCommand> allConsoleCommands() {
  const fs::path root = IMPETUS_SOURCE_DIR;
  std::vector<DocCommand> all = consoleCommands(root / "README.md");
  std::vector<fs::path> docs;
  for (const fs::directory_entry& e : fs::directory_iterator(root / "docs")) {
    if (e.path().extension() == ".md") {
      docs.push_back(e.path());
    }
  }
  std::sort(docs.begin(), docs.end());
  for (const fs::path& doc : docs) {
    const std::vector<DocCommand> more = consoleCommands(doc);
    all.insert(all.end(), more.begin(), more.end());
  }
  return all;
}

/// Runs `impetus <command>` through the shell from the repository root; stdout then stderr.
std::string run(const std::string& command, int& status) {
  const std::string errPath = ::testing::TempDir() + "impetus_docs_stderr.txt";
  const std::string line = "cd " + impetus::testing::shellQuote(IMPETUS_SOURCE_DIR) + " && " +
                           impetus::testing::shellQuote(IMPETUS_CLI_PATH) + " " + command + " 2>" +
                           impetus::testing::shellQuote(errPath);
  std::string out;
  FILE* pipe = popen(line.c_str(), "r");
  if (pipe == nullptr) {
    status = -1;
    return out;
  }
  char buffer[4096];
  for (std::size_t n = 0; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) {
    out.append(buffer, n);
  }
  const int raw = pclose(pipe);
  status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream err(errPath);
  std::stringstream ss;
  ss << err.rdbuf();
  return out + ss.str();
}

bool printsLine(const std::string& output, const std::string& shown) {
  std::istringstream lines(output);
  const bool prefix = shown.size() >= 3 && shown.compare(shown.size() - 3, 3, "...") == 0;
  const std::string wanted = prefix ? shown.substr(0, shown.size() - 3) : shown;
  for (std::string line; std::getline(lines, line);) {
    if (prefix ? line.rfind(wanted, 0) == 0 : line == wanted) {
      return true;
    }
  }
  return false;
}

TEST(DocsCommands, every_console_session_in_the_docs_prints_what_the_docs_show) {
  const std::vector<DocCommand> commands = allConsoleCommands();
  ASSERT_GE(commands.size(), 6U) << "the docs' console sessions were not found";
  for (const DocCommand& c : commands) {
    int status = 0;
    const std::string output = run(c.command, status);
    ASSERT_GE(status, 0) << c.file << ":" << c.line;
    for (const std::string& shown : c.output) {
      EXPECT_TRUE(printsLine(output, shown))
          << c.file << ":" << c.line << ": `impetus " << c.command << "` does not print\n  " << shown << "\nbut\n"
          << output;
    }
  }
}

} // namespace
