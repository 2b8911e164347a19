// .sculpt project files (project/project_file.h): a binary header, a JSON manifest and
// checksummed blobs. Bad input must give a FileError; "never reads past the bytes" is what
// AddressSanitizer checks.

#include <cstdint>

#include "fuzz_support.h"
#include "io/file_error.h"
#include "project/project_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  constexpr std::string_view kSource = "fuzz.sculpt";
  try {
    (void)sculpt::parseProject(sculpt::fuzz::text(data, size), kSource);
  } catch (const sculpt::FileError& error) {
    sculpt::fuzz::expectClearMessage(error, kSource);
  }
  return 0;
}
