// Control-mesh JSON (io/control_mesh_json.h) as the program loads it: parse, then validate,
// which is where out-of-range vertex indices are reported. Bad input must give a FileError.

#include <cstdint>

#include "fuzz_support.h"
#include "io/control_mesh_json.h"
#include "mesh/validation.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  constexpr std::string_view kSource = "fuzz.json";
  try {
    const sculpt::CellComplex mesh =
        sculpt::parseControlMeshJson(sculpt::fuzz::text(data, size), kSource);
    (void)sculpt::validate(mesh);
  } catch (const sculpt::FileError& error) {
    sculpt::fuzz::expectClearMessage(error, kSource);
  }
  return 0;
}
