#pragma once
// Wavefront OBJ record formatting shared by the OBJ writers (boundary surfaces and embedded
// surfaces): one keyword, then numbers, then a newline.

#include <Eigen/Core>
#include <charconv>
#include <string>
#include <string_view>

#include "io/number_text.h"

namespace sculpt {

/// How many digits a writer spends on a coordinate. kDouble reads back bit for bit as a double;
/// kFloat writes the shortest text that reads back as the same float (about half the file size)
/// and is enough for data that ends up in 32-bit GPU buffers anyway.
enum class NumberPrecision { kDouble, kFloat };

inline void appendNumber(std::string& out, double value, NumberPrecision precision) {
  if (precision == NumberPrecision::kDouble) {
    appendNumber(out, value);
    return;
  }
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, static_cast<float>(value));
  out.append(buffer, result.ptr);
}

/// Appends "<keyword> a b c\n" for a row of numbers (e.g. "v x y z", "vt u v", "vn x y z").
template <typename Row>
void appendObjRecord(std::string& out, std::string_view keyword, const Row& values,
                     NumberPrecision precision = NumberPrecision::kDouble) {
  out += keyword;
  for (Eigen::Index k = 0; k < values.size(); ++k) {
    out += ' ';
    appendNumber(out, static_cast<double>(values(k)), precision);
  }
  out += '\n';
}

}  // namespace sculpt
