#pragma once
// The one exception type of file input and output.

#include <stdexcept>

namespace sculpt {

/// A file that cannot be read or parsed. what() is one line naming the file, the element and
/// the problem, e.g. "block.json: cell 3, face 2: vertex index -1 is negative".
class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace sculpt
