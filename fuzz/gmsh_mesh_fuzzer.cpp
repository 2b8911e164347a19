// Gmsh .msh text, versions 2.x and 4.1 (io/gmsh_mesh.h). Bad input must give a FileError.

#include <cstdint>

#include "fuzz_support.h"
#include "io/file_error.h"
#include "io/gmsh_mesh.h"
#include "volume_mesh_use.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  constexpr std::string_view kSource = "fuzz.msh";
  try {
    sculpt::fuzz::useVolumeMesh(sculpt::parseGmshMesh(sculpt::fuzz::text(data, size), kSource,
                                                      sculpt::fuzz::kVolumeShapeCheck));
  } catch (const sculpt::FileError& error) {
    sculpt::fuzz::expectClearMessage(error, kSource);
  }
  return 0;
}
