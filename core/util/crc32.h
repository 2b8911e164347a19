#pragma once
// CRC-32 checksums (the project file's manifest and blobs).

#include <cstdint>
#include <string_view>

namespace sculpt {

/// CRC-32 (IEEE 802.3, as zlib's crc32) of the bytes.
uint32_t crc32(std::string_view bytes);

}  // namespace sculpt
