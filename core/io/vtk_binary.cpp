#include "io/vtk_binary.h"

#include <bit>
#include <initializer_list>
#include <utility>

#include "io/text_scanner.h"

namespace sculpt {

uint64_t bigEndianBits(const char* bytes, size_t size) {
  uint64_t bits = 0;
  for (size_t i = 0; i < size; ++i) bits = (bits << 8) | static_cast<uint8_t>(bytes[i]);
  return bits;
}

int64_t bigEndianInteger(const char* bytes, size_t size) {
  const uint64_t bits = bigEndianBits(bytes, size);
  if (size == 4) return static_cast<int32_t>(static_cast<uint32_t>(bits));
  return static_cast<int64_t>(bits);
}

double bigEndianReal(const char* bytes, size_t size) {
  if (size == 4) return std::bit_cast<float>(static_cast<uint32_t>(bigEndianBits(bytes, 4)));
  return std::bit_cast<double>(bigEndianBits(bytes, 8));
}

void appendBigEndian(std::string& out, uint64_t bits, size_t size) {
  for (size_t i = size; i-- > 0;) out += static_cast<char>((bits >> (8 * i)) & 0xffu);
}

/// Bytes per value of the VTK data types of FIELD arrays that can be skipped; 0 when unknown.
size_t dataTypeSize(std::string_view type) {
  for (const auto& [name, size] :
       std::initializer_list<std::pair<std::string_view, size_t>>{{"char", 1},
                                                                  {"unsigned_char", 1},
                                                                  {"short", 2},
                                                                  {"unsigned_short", 2},
                                                                  {"int", 4},
                                                                  {"unsigned_int", 4},
                                                                  {"vtktypeint32", 4},
                                                                  {"vtktypeuint32", 4},
                                                                  {"float", 4},
                                                                  {"double", 8},
                                                                  {"vtktypeint64", 8},
                                                                  {"vtktypeuint64", 8}}) {
    if (equalsIgnoringCase(type, name)) return size;
  }
  return 0;
}

/// Bytes per value of the integer types accepted for OFFSETS and CONNECTIVITY; 0 for others.
size_t integerTypeSize(std::string_view type) {
  for (const std::string_view name : {"int", "vtktypeint32", "unsigned_int", "vtktypeuint32"}) {
    if (equalsIgnoringCase(type, name)) return 4;
  }
  for (const std::string_view name : {"vtktypeint64", "vtktypeuint64"}) {
    if (equalsIgnoringCase(type, name)) return 8;
  }
  return 0;
}

}  // namespace sculpt
