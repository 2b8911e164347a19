#pragma once
// The one way a reader gets at a file's bytes. Only a regular file of a size its format can
// sensibly have is read: a device (/dev/zero), a FIFO or a directory named as a mesh would
// otherwise be read until memory runs out or block the reader forever, so they are refused by
// their type before anything opens them, and an oversized file by its size before anything is
// allocated.

#include <cstdint>
#include <filesystem>
#include <string>

namespace sculpt {

/// What a reader reads, for messages, and the largest file it accepts.
struct InputFormat {
  const char* noun;  ///< "a control-mesh file"
  uint64_t maxBytes;
};

inline constexpr uint64_t kGiB = uint64_t{1} << 30;

// Control-mesh JSON becomes a JSON document several times the size of its text before it is a
// mesh; 1 GiB of text is tens of millions of cells, more than anything sculpts.
inline constexpr InputFormat kControlMeshInput{"a control-mesh file", kGiB};
// OBJ and glTF surfaces index their vertices with 32 bits, and a .glb states its length in 32.
inline constexpr InputFormat kSurfaceInput{"a surface file", 4 * kGiB - 1};
// A glTF buffer's byteLength and the readers' accessors stay below 4 GiB as the .glb does.
inline constexpr InputFormat kGltfResourceInput{"a glTF buffer or image", 4 * kGiB - 1};
// VTK, Gmsh and TetGen meshes are limited to 2^32 - 1 nodes; 4 GiB of text is ~100 M nodes.
inline constexpr InputFormat kVolumeMeshInput{"a volume-mesh file", 4 * kGiB};
// A project holds a control mesh, its material samples and perhaps an embedded OBJ surface.
inline constexpr InputFormat kProjectInput{"a project file", 4 * kGiB};

// Session scripts, device scripts and preferences are small JSON written by hand or by a take;
// 256 MiB is hours of recorded strokes, 16 MiB far more settings than the window has.
inline constexpr InputFormat kSessionScriptInput{"a session script", 256u << 20};
inline constexpr InputFormat kDeviceScriptInput{"a device script", 256u << 20};
inline constexpr InputFormat kPreferencesInput{"a preferences file", 16u << 20};

/// Checks, without opening it, that `path` names a regular file (symbolic links followed) of
/// at most format.maxBytes bytes, and returns its size. Throws FileError naming the file:
/// "<path>: cannot open (No such file or directory)", "<path>: is a FIFO (named pipe), not a
/// regular file", "<path>: 5 GiB (5368709120 bytes) is more than the 4 GiB (4294967295 bytes)
/// that a surface file may have".
uint64_t checkInputFile(const std::filesystem::path& path, const InputFormat& format);

/// checkInputFile, then the whole file. Throws FileError naming the file.
std::string readInputFile(const std::filesystem::path& path, const InputFormat& format);

}  // namespace sculpt
