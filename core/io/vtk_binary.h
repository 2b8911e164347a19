#pragma once
// Legacy VTK binary data: big-endian numbers (the format's binary data is always big-endian) and
// the sizes of the data types a file may name.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace sculpt {

/// The `size` bytes as an unsigned big-endian number.
uint64_t bigEndianBits(const char* bytes, size_t size);
/// A big-endian integer of 4 (signed 32-bit) or 8 bytes.
int64_t bigEndianInteger(const char* bytes, size_t size);
/// A big-endian float (4 bytes) or double (8 bytes).
double bigEndianReal(const char* bytes, size_t size);
/// Appends the low `size` bytes of `bits`, most significant first.
void appendBigEndian(std::string& out, uint64_t bits, size_t size);
/// Bytes per value of the VTK data types of FIELD arrays that can be skipped; 0 when unknown.
size_t dataTypeSize(std::string_view type);
/// Bytes per value of the integer types accepted for OFFSETS and CONNECTIVITY; 0 for others.
size_t integerTypeSize(std::string_view type);

}  // namespace sculpt
