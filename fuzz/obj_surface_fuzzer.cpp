// Wavefront OBJ surfaces (io/obj_surface.h). Bad input must give a FileError.

#include <cstdint>

#include "fuzz_support.h"
#include "io/file_error.h"
#include "io/obj_surface.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  constexpr std::string_view kSource = "fuzz.obj";
  try {
    (void)sculpt::parseObjSurface(sculpt::fuzz::text(data, size), kSource);
  } catch (const sculpt::FileError& error) {
    sculpt::fuzz::expectClearMessage(error, kSource);
  }
  return 0;
}
