// main() for a harness built without libFuzzer: feeds inputs to LLVMFuzzerTestOneInput, so that
// the regular build replays the seed corpus and the saved regression inputs as ordinary tests
// (under ASan/UBSan in the asan build).
//
//   replay PATH...                 every file named, and every file under every directory named
//                                  (recursively, sorted), once; files named open-* inside a
//                                  directory are left out (see below). A missing path is skipped
//                                  (a harness may have no regression input yet).
//   replay --expect-failure FILE   an open finding: a library bug the fuzzer found that is not
//                                  fixed yet. Succeeds while the input still fails its harness
//                                  (in a child process: a failed check aborts), and fails once
//                                  it passes, so that whoever fixes the bug renames the file
//                                  (drops "open-") and it joins the ordinary replay.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

namespace fs = std::filesystem;

bool replay(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "cannot read %s\n", file.c_str());
    return false;
  }
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // Named before it runs, so that a crash says which input it was.
  std::fprintf(stderr, "replaying %s (%zu bytes)\n", file.c_str(), bytes.size());
  (void)LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  return true;
}

int expectFailure(const fs::path& file) {
  std::fflush(nullptr);
  const pid_t child = fork();
  if (child < 0) {
    std::perror("fork");
    return 1;
  }
  if (child == 0) {
    _exit(replay(file) ? 0 : 2);
  }
  int status = 0;
  if (waitpid(child, &status, 0) != child) {
    std::perror("waitpid");
    return 1;
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    std::fprintf(stderr,
                 "%s passes its harness now: the bug it shows is fixed. Rename the file without \"open-\" (it then "
                 "runs with the other regression inputs) and take its exemption out of the harness.\n",
                 file.c_str());
    return 1;
  }
  std::printf("%s still fails its harness (an open finding)\n", file.c_str());
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::strcmp(argv[1], "--expect-failure") == 0) {
    return expectFailure(argv[2]);
  }
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    const fs::path path(argv[i]);
    if (fs::is_directory(path)) {
      for (const auto& entry : fs::recursive_directory_iterator(path)) {
        if (entry.is_regular_file() && entry.path().filename().string().rfind("open-", 0) != 0) {
          files.push_back(entry.path());
        }
      }
    } else if (fs::is_regular_file(path)) {
      files.push_back(path);
    } else {
      std::printf("(no %s)\n", path.c_str());
    }
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    if (!replay(file)) {
      return 1;
    }
  }
  std::printf("replayed %zu inputs\n", files.size());
  return files.empty() ? 1 : 0;
}
