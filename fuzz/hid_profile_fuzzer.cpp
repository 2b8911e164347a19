// HID device profiles (haptics/hid/hid_profile.h), JSON written by users. Bad input must give a
// FileError.

#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "haptics/hid/hid_profile.h"
#include "io/file_error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string kSource = "fuzz-profile.json";
  try {
    (void)sculpt::haptics::parseHidProfile(sculpt::fuzz::text(data, size), kSource);
  } catch (const sculpt::FileError& error) {
    sculpt::fuzz::expectClearMessage(error, kSource);
  }
  return 0;
}
