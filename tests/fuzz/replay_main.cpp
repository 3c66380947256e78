// Runs a fuzz target's LLVMFuzzerTestOneInput on stored inputs, without libFuzzer: each argument
// is a file, or a directory whose files are all run. Used by ctest (fuzz_replay.*) so that every
// input that once crashed glass, and the seed corpus, is checked on every build, with any
// compiler. Prints how many inputs ran; a crash is the failure.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size);

namespace {

bool runFile(const std::filesystem::path &path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "cannot read %s\n", path.string().c_str());
    return false;
  }
  const std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t *>(bytes.data()), bytes.size());
  return true;
}

} // namespace

int main(int argc, char **argv) {
  int inputs = 0;
  bool ok = true;
  for (int i = 1; i < argc; ++i) {
    const std::filesystem::path argument(argv[i]);
    std::vector<std::filesystem::path> files;
    if (std::filesystem::is_directory(argument)) {
      for (const auto &entry : std::filesystem::directory_iterator(argument))
        if (entry.is_regular_file()) files.push_back(entry.path());
      std::sort(files.begin(), files.end());
    } else {
      files.push_back(argument);
    }
    for (const auto &file : files) {
      ok = runFile(file) && ok;
      ++inputs;
    }
  }
  std::printf("%d inputs ran without a crash\n", inputs);
  return ok && inputs > 0 ? 0 : 1;
}
