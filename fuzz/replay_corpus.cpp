// Feeds every file of the fuzz corpus (fuzz/corpus/<reader>/*) to every reader, built with
// the ordinary compiler so that CI runs it (ctest "fuzz: ..."): each file must be read or
// refused with a cmp::InputError; another exception is a failure (a crash ends the test).
//   fuzz_corpus_replay <corpus folder>
#include "readers.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: fuzz_corpus_replay <corpus folder>\n";
    return 2;
  }
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(argv[1]))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    std::cerr << "no corpus files under " << argv[1] << "\n";
    return 1;
  }
  int failures = 0, read = 0, refused = 0;
  for (const auto& path : files) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    for (const auto& reader : cmp::fuzz::readers()) {
      try {
        reader.read(bytes);
        ++read;
      } catch (const cmp::InputError&) {
        ++refused;
      } catch (const std::exception& e) {
        std::cerr << "FAIL: " << path.string() << " through " << reader.name << ": " << e.what() << "\n";
        ++failures;
      }
    }
  }
  std::cout << files.size() << " corpus files x " << cmp::fuzz::readers().size() << " readers: " << read
            << " read, " << refused << " refused with an InputError, " << failures << " other failures\n";
  return failures ? 1 : 0;
}
