// Session scripts (tools/session_script.h). Bad input must give a FileError.

#include <cstdint>

#include "fuzz_support.h"
#include "io/file_error.h"
#include "tools/session_script.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  constexpr std::string_view kSource = "fuzz.json";
  try {
    const sculpt::SessionScript script =
        sculpt::parseSessionScript(sculpt::fuzz::text(data, size), kSource);
    (void)script.duration();
  } catch (const sculpt::FileError& error) {
    sculpt::fuzz::expectClearMessage(error, kSource);
  }
  return 0;
}
