#pragma once
// Quoting for commands the tests hand to std::system (paths may hold spaces or quotes).

#include <string>

namespace sculpt::test {

/// `text` single-quoted for sh.
inline std::string shellQuote(const std::string& text) {
  std::string quoted = "'";
  for (char ch : text) quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return quoted + "'";
}

}  // namespace sculpt::test
