// hid-recorder recordings (haptics/hid/hid_recording.h). Bad input must give a FileError; an
// accepted recording's report descriptor then goes through topLevelUsage, as the device manager
// does with a replayed device.

#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "haptics/hid/hid_recording.h"
#include "io/file_error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string kSource = "fuzz-recording.txt";
  try {
    const sculpt::haptics::HidRecording recording =
        sculpt::haptics::parseHidRecording(sculpt::fuzz::text(data, size), kSource);
    (void)sculpt::haptics::topLevelUsage(recording.descriptor);
  } catch (const sculpt::FileError& error) {
    sculpt::fuzz::expectClearMessage(error, kSource);
  }
  return 0;
}
