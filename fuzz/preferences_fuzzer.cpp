// The preferences file (project/preferences.h). It takes a path only, so each input is written
// to a scratch file first. Its contract is stronger than the other readers': a damaged file
// gives defaults and a warning and never throws, so nothing is caught here.

#include <cstdint>

#include "fuzz_support.h"
#include "project/preferences.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const sculpt::fuzz::ScratchFile file("preferences.json");
  const sculpt::LoadedPreferences loaded =
      sculpt::loadPreferences(file.write(sculpt::fuzz::text(data, size)));
  if (loaded.preferences.recentFiles.size() > sculpt::Preferences::kMaxRecentFiles) {
    sculpt::fuzz::fail("more recent files than the documented maximum");
  }
  return 0;
}
