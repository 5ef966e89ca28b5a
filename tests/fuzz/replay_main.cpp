// Replays fuzz inputs without libFuzzer: each argument is a file, or a folder whose files are
// replayed in name order, through the target's LLVMFuzzerTestOneInput. ctest runs every
// target on its folder of tests/fuzz/corpus (the regression inputs); a broken invariant
// aborts with the decoded input, after the line naming its file.
//
//   build/tests/fuzz/fuzz_polylines tests/fuzz/corpus/fuzz_polylines   (GEOCDT_FUZZ_PRINT=1
//   prints each decoded input)
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

namespace fs = std::filesystem;

// The files an argument names; an empty list when it names nothing readable.
std::vector<fs::path> inputsOf(const fs::path& path) {
  std::error_code error;
  if (!fs::is_directory(path, error)) {
    if (fs::is_regular_file(path, error)) return {path};
    return {};
  }
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(path, error))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s FILE_OR_FOLDER...\n", argv[0]);
    return 2;
  }
  std::size_t replayed = 0;
  for (int i = 1; i < argc; ++i) {
    const std::vector<fs::path> files = inputsOf(argv[i]);
    // A folder emptied or misnamed by mistake must not pass as "nothing failed".
    if (files.empty()) {
      std::fprintf(stderr, "replay: no input files in %s\n", argv[i]);
      return 1;
    }
    for (const fs::path& file : files) {
      std::ifstream in(file, std::ios::binary);
      const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                    std::istreambuf_iterator<char>());
      if (!in.good() && !in.eof()) {
        std::fprintf(stderr, "replay: cannot read %s\n", file.c_str());
        return 1;
      }
      std::fprintf(stderr, "replay: %s\n", file.c_str());
      LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
      ++replayed;
    }
  }
  std::printf("replayed %zu inputs without a finding\n", replayed);
  return 0;
}
