#pragma once
// A cursor over a whole mesh file, shared by the VTK, Gmsh and TetGen readers: whitespace-separated
// tokens, numbers parsed without locale or allocation, the line number for error messages, and
// raw byte access for the binary blocks of legacy VTK. Every read is bounds-checked, and a file
// that announces more data than it can hold is rejected before anything is reserved.
// Failures throw FileError "<source>: line <n>: <problem>".

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>

#include "io/file_error.h"

namespace sculpt {

inline char asciiLower(char c) {
  return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

/// ASCII case-insensitive comparison (VTK keywords may be written in either case).
inline bool equalsIgnoringCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return asciiLower(x) == asciiLower(y);
         });
}

class TextScanner {
 public:
  /// `commentChar` (e.g. '#' for TetGen) starts a comment that runs to the end of the line.
  TextScanner(std::string_view text, std::string_view sourceName, char commentChar = '\0')
      : text_(text), source_(sourceName), comment_(commentChar) {}

  /// A place to come back to (for looking ahead).
  struct Mark {
    size_t offset;
    size_t line;
  };
  Mark mark() const { return {pos_, line_}; }
  void restore(Mark m) {
    pos_ = m.offset;
    line_ = m.line;
  }

  size_t line() const { return line_; }
  size_t bytesLeft() const { return text_.size() - pos_; }

  // ---- Tokens -------------------------------------------------------------------------------

  /// Skips blanks, line ends and comments. False when nothing but those is left.
  bool skipSpace() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_;
        ++pos_;
      } else if (isBlank(c)) {
        ++pos_;
      } else if (comment_ != '\0' && c == comment_) {
        skipToLineEnd();
      } else {
        return true;
      }
    }
    return false;
  }

  /// The next token without consuming it (empty at the end of the file).
  std::string_view peekToken() {
    if (!skipSpace()) return {};
    return text_.substr(pos_, tokenLength());
  }

  /// The next token (empty at the end of the file).
  std::string_view token() {
    const std::string_view t = peekToken();
    pos_ += t.size();
    return t;
  }

  /// Whether only blanks and perhaps a comment remain before the next line end or the file end.
  bool atLineEnd() const {
    size_t p = pos_;
    while (p < text_.size() && isBlank(text_[p])) ++p;
    return p == text_.size() || text_[p] == '\n' || (comment_ != '\0' && text_[p] == comment_);
  }

  /// Moves past the next line end (or to the end of the file).
  void skipLine() {
    skipToLineEnd();
    if (pos_ < text_.size()) {
      ++pos_;
      ++line_;
    }
  }

  /// The rest of the current line without its line end ("\r\n" or "\n"), and moves past it.
  std::string_view restOfLine() {
    const size_t start = pos_;
    skipToLineEnd();
    std::string_view line = text_.substr(start, pos_ - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    skipLine();
    return line;
  }

  /// Ends a header line that binary data follows: only blanks may remain, then one '\n'.
  void finishLineBeforeBinary() {
    while (pos_ < text_.size() && isBlank(text_[pos_])) ++pos_;
    if (pos_ >= text_.size()) fail("the file ends where binary data should start");
    if (text_[pos_] != '\n') fail("unexpected " + describeNext() + " at the end of the line");
    ++pos_;
    ++line_;
  }

  /// "'token'" or "the end of the file", for messages.
  std::string describeNext() {
    const Mark m = mark();
    const std::string_view t = peekToken();
    restore(m);
    return t.empty() ? std::string("the end of the file") : quoted(t);
  }

  /// A token from the file made safe for a one-line message: at most 40 characters, anything
  /// unprintable shown as '?'.
  static std::string printable(std::string_view token) {
    constexpr size_t kMaxShown = 40;
    std::string out;
    for (const char c : token.substr(0, kMaxShown)) out += (c >= 32 && c < 127) ? c : '?';
    return token.size() > kMaxShown ? out + "..." : out;
  }
  /// printable(token) in single quotes.
  static std::string quoted(std::string_view token) {
    std::string out = printable(token);
    out.insert(out.begin(), '\'');
    out.push_back('\'');
    return out;
  }

  // ---- Numbers (nothing is consumed when the next token is not one) -------------------------

  bool readInteger(int64_t& value) { return readNumber(value); }
  bool readUnsigned(uint64_t& value) { return readNumber(value); }
  bool readReal(double& value) { return readNumber(value); }

  int64_t integer(std::string_view what) {
    int64_t value = 0;
    if (!readInteger(value)) failExpected(what);
    return value;
  }
  uint64_t count(std::string_view what) {
    uint64_t value = 0;
    if (!readUnsigned(value)) failExpected(what);
    return value;
  }
  double real(std::string_view what) {
    double value = 0.0;
    if (!readReal(value)) failExpected(what);
    return value;
  }

  /// Consumes `keyword` (compared ignoring case) or fails.
  void expectKeyword(std::string_view keyword) {
    skipSpace();
    const Mark m = mark();
    if (!equalsIgnoringCase(token(), keyword)) {
      restore(m);
      failExpected(keyword);
    }
  }

  [[noreturn]] void failExpected(std::string_view what) {
    fail("expected " + std::string(what) + ", found " + describeNext());
  }

  // ---- Binary blocks and sizes --------------------------------------------------------------

  /// The next `size` raw bytes; fails when the file ends sooner.
  std::string_view bytes(uint64_t size, std::string_view what) {
    if (size > bytesLeft()) {
      fail("the file ends inside " + std::string(what) + " (" + std::to_string(size) +
           " bytes needed, " + std::to_string(bytesLeft()) + " left)");
    }
    const std::string_view block = text_.substr(pos_, static_cast<size_t>(size));
    line_ += static_cast<size_t>(std::count(block.begin(), block.end(), '\n'));
    pos_ += block.size();
    return block;
  }

  /// Rejects a declared count that the rest of the file cannot hold at `minBytesEach` bytes per
  /// item (checked before anything is reserved, so absurd counts fail fast), or that exceeds
  /// `limit`. `what` names the items ("points").
  void checkCount(uint64_t count, uint64_t minBytesEach, std::string_view what,
                  uint64_t limit = std::numeric_limits<uint32_t>::max()) {
    const uint64_t available = bytesLeft() + 1;  // the last item needs no separator after it
    if (minBytesEach > 0 && count > available / minBytesEach) {
      fail("the file ends too soon for " + std::to_string(count) + " " + std::string(what) +
           " (at least " + bytesNeeded(count, minBytesEach) + " bytes needed, " +
           std::to_string(bytesLeft()) + " left)");
    }
    if (count > limit) {
      fail("too many " + std::string(what) + ": " + std::to_string(count) + " (at most " +
           std::to_string(limit) + ")");
    }
  }

  [[noreturn]] void fail(const std::string& problem) const { failAt(line_, problem); }
  [[noreturn]] void failAt(size_t line, const std::string& problem) const {
    throw FileError(source_ + ": line " + std::to_string(line) + ": " + problem);
  }

 private:
  static bool isBlank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
  }

  size_t tokenLength() const {
    size_t end = pos_;
    while (end < text_.size() && text_[end] != '\n' && !isBlank(text_[end]) &&
           !(comment_ != '\0' && text_[end] == comment_)) {
      ++end;
    }
    return end - pos_;
  }

  void skipToLineEnd() {
    const size_t end = text_.find('\n', pos_);
    pos_ = end == std::string_view::npos ? text_.size() : end;
  }

  static std::string bytesNeeded(uint64_t count, uint64_t each) {
    if (count > std::numeric_limits<uint64_t>::max() / each) return "2^64";
    return std::to_string(count * each);
  }

  template <typename T>
  bool readNumber(T& value) {
    skipSpace();  // so that a failure reports the line of the offending token
    const Mark m = mark();
    std::string_view t = token();
    if (t.size() > 1 && t[0] == '+' && t[1] != '-') t.remove_prefix(1);
    T parsed{};
    const auto [end, error] = std::from_chars(t.data(), t.data() + t.size(), parsed);
    if (t.empty() || error != std::errc() || end != t.data() + t.size()) {
      restore(m);
      return false;
    }
    value = parsed;
    return true;
  }

  std::string_view text_;
  std::string source_;
  char comment_;
  size_t pos_ = 0;
  size_t line_ = 1;
};

}  // namespace sculpt
