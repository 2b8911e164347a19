// TetGen .node and .ele texts (io/tetgen_mesh.h). One input holds both files: the .node text up
// to the first NUL byte, the .ele text after it (no NUL: all .node, an empty .ele), so the
// fuzzer can change either. Bad input must give a FileError naming the file at fault.

#include <cstdint>

#include "fuzz_support.h"
#include "io/file_error.h"
#include "io/tetgen_mesh.h"
#include "volume_mesh_use.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  constexpr std::string_view kNodeSource = "fuzz.node";
  constexpr std::string_view kEleSource = "fuzz.ele";
  const std::string_view input = sculpt::fuzz::text(data, size);
  const size_t separator = input.find('\0');
  const std::string_view nodeText = input.substr(0, separator);
  const std::string_view eleText =
      separator == std::string_view::npos ? std::string_view() : input.substr(separator + 1);
  try {
    sculpt::fuzz::useVolumeMesh(sculpt::parseTetGenMesh(nodeText, eleText, kNodeSource, kEleSource,
                                                        sculpt::fuzz::kVolumeShapeCheck));
  } catch (const sculpt::FileError& error) {
    // Both names end in the same stem, so the shared prefix is what every message starts with.
    sculpt::fuzz::expectClearMessage(error, "fuzz.");
  }
  return 0;
}
