// glTF 2.0 surfaces, JSON and GLB (io/gltf_surface.h, io/gltf_document.h). The reader takes a
// path only, so each input is written to a scratch file first; it picks JSON or GLB by content.
// Bad input must give a FileError. tinygltf itself is Debian's prebuilt library: its code is
// exercised but not instrumented (no coverage feedback or sanitizer checks inside it).

#include <cstdint>

#include "fuzz_support.h"
#include "io/file_error.h"
#include "io/gltf_surface.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const sculpt::fuzz::ScratchFile file("fuzz.gltf");
  const std::filesystem::path& path = file.write(sculpt::fuzz::text(data, size));
  try {
    (void)sculpt::GltfSurfaceFile::read(path);
  } catch (const sculpt::FileError& error) {
    sculpt::fuzz::expectClearMessage(error, path.string());
  }
  return 0;
}
