// libFuzzer target of one reader, chosen at compile time (CMP_FUZZ_READER="off", ...): the
// input is a whole file; a cmp::InputError is a correct answer, anything else escaping is a
// crash libFuzzer reports (make fuzz).
#include "readers.hpp"

#include "core/errors.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const auto& reader = cmp::fuzz::reader(CMP_FUZZ_READER);
  try {
    reader.read(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const cmp::InputError&) {
  }
  return 0;
}
