// Runs the `impetus` executable from a test and captures its exit status, stdout and stderr.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace impetus::testing {

struct CliRun {
  int status = -1;
  std::string out;
  std::string err;
};

/// A single-quoted shell word.
inline std::string shellQuote(const std::string& arg) {
  std::string q(1, '\'');
  for (char c : arg) {
    if (c == '\'') {
      q.append("'\\''");
    } else {
      q.push_back(c);
    }
  }
  q.push_back('\'');
  return q;
}

/// Runs the CLI (IMPETUS_CLI_PATH) with `args`, capturing stdout and stderr separately.
inline CliRun impetus(const std::vector<std::string>& args) {
  // ctest runs tests in parallel processes: one stderr file per test and call.
  static int calls = 0;
  const std::string errPath = ::testing::TempDir() + "impetus_stderr_" +
                              ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
                              std::to_string(++calls) + ".txt";
  std::string command = shellQuote(IMPETUS_CLI_PATH);
  for (const std::string& a : args) {
    command.push_back(' ');
    command.append(shellQuote(a));
  }
  command.append(" 2>").append(shellQuote(errPath));
  CliRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) {
    return run;
  }
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
    run.out.append(buffer.data(), n);
  }
  const int raw = pclose(pipe);
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream err(errPath);
  std::stringstream ss;
  ss << err.rdbuf();
  run.err = ss.str();
  return run;
}

/// Exit status 2 and exactly one line on stderr that contains `needle`.
inline void expectUsageError(const CliRun& run, const std::string& needle) {
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find(needle), std::string::npos) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
}

} // namespace impetus::testing
