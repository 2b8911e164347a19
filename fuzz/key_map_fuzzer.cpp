// The window's key map text (app/sculpt/navigation.h, KeyMap::fromText), stored in the
// preferences file. With an error string bad lines are skipped and described (never thrown);
// without one the first bad line throws std::invalid_argument. What is read must write back
// as text that reads to the same map.

#include <cstdint>
#include <stdexcept>
#include <string>

#include "fuzz_support.h"
#include "sculpt/navigation.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using sculpt::app::KeyMap;
  const std::string_view text = sculpt::fuzz::text(data, size);
  std::string error;
  const KeyMap lenient = KeyMap::fromText(text, &error);
  if (KeyMap::fromText(lenient.toText(), nullptr) != lenient) {
    sculpt::fuzz::fail("the key map does not read back from its own text");
  }
  try {
    const KeyMap strict = KeyMap::fromText(text, nullptr);
    if (!error.empty()) sculpt::fuzz::fail("a bad line was described but not thrown");
    if (strict != lenient) sculpt::fuzz::fail("strict and lenient reads differ");
  } catch (const std::invalid_argument& refusal) {
    if (error.empty()) sculpt::fuzz::fail("a line was refused but not described");
    if (std::string_view(refusal.what()).empty()) sculpt::fuzz::fail("empty error message");
  }
  return 0;
}
