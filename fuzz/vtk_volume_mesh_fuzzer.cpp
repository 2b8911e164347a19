// Legacy VTK unstructured grids, ASCII and big-endian BINARY (io/vtk_volume_mesh.h, whose binary
// numbers io/vtk_binary.h decodes). Bad input must give a FileError.

#include <cstdint>

#include "fuzz_support.h"
#include "io/file_error.h"
#include "io/vtk_volume_mesh.h"
#include "volume_mesh_use.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  constexpr std::string_view kSource = "fuzz.vtk";
  try {
    sculpt::fuzz::useVolumeMesh(sculpt::parseVtkVolumeMesh(sculpt::fuzz::text(data, size), kSource,
                                                           sculpt::fuzz::kVolumeShapeCheck));
  } catch (const sculpt::FileError& error) {
    sculpt::fuzz::expectClearMessage(error, kSource);
  }
  return 0;
}
