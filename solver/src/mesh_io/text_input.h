#pragma once
// What every mesh reader reads text with: lines, whitespace-separated tokens and numbers, and the
// two pieces of a message that point into the input (`where` it is, and a token `shown` safely).
// Private to solver/src/mesh_io/.

#include <cstddef>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>

namespace geodex::detail {

// ===  Messages  =================================================================================

/// The start of a message: "FILE:LINE: ", "line LINE: " (no file name), "FILE: " (line unknown,
/// e.g. binary PLY) or "".
std::string where(const std::string& file, int line);

/// A token of the input for a message: quoted, cut after a few bytes, unprintable bytes escaped
/// (fuzzed input must not put control characters into a terminal).
std::string shown(std::string_view token);

// ===  Lines and tokens  =========================================================================

inline bool isBlank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/// Splits bytes into lines ('\n' or "\r\n"), counting them from 1.
class LineReader {
 public:
  explicit LineReader(std::string_view bytes)
      : next_(bytes.data()), end_(bytes.data() + bytes.size()) {}

  /// The next line without its end-of-line bytes; false at the end of the input.
  bool next(std::string_view& line) {
    if (next_ == end_) return false;
    const auto* newline =
        static_cast<const char*>(std::memchr(next_, '\n', static_cast<std::size_t>(end_ - next_)));
    const char* lineEnd = newline ? newline : end_;
    line = std::string_view(next_, static_cast<std::size_t>(lineEnd - next_));
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    next_ = newline ? newline + 1 : end_;
    if (lineNumber_ < std::numeric_limits<int>::max()) ++lineNumber_;
    return true;
  }
  int lineNumber() const { return lineNumber_; }
  /// Bytes after the line last returned.
  std::size_t remainingBytes() const { return static_cast<std::size_t>(end_ - next_); }
  const char* position() const { return next_; }

 private:
  const char* next_;
  const char* end_;
  int lineNumber_ = 0;
};

/// Whitespace-separated tokens of one line.
class Tokens {
 public:
  explicit Tokens(std::string_view line) : rest_(line) {}

  bool next(std::string_view& token) {
    skipBlanks();
    if (rest_.empty()) return false;
    std::size_t end = 0;
    while (end < rest_.size() && !isBlank(rest_[end])) ++end;
    token = rest_.substr(0, end);
    rest_.remove_prefix(end);
    return true;
  }
  bool atEnd() {
    skipBlanks();
    return rest_.empty();
  }

 private:
  void skipBlanks() {
    std::size_t i = 0;
    while (i < rest_.size() && isBlank(rest_[i])) ++i;
    rest_.remove_prefix(i);
  }
  std::string_view rest_;
};

/// Cuts a '#' comment off a line (OFF and OBJ).
inline std::string_view withoutComment(std::string_view line) {
  const std::size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

// ===  Numbers  ==================================================================================

/// The whole token as a double (from_chars: locale-independent, correctly rounded); a leading '+'
/// is accepted. Values beyond the double range become ±inf (validateMesh then reports them) or
/// ±0, as strtod would give.
bool parseDouble(std::string_view token, double& out);

/// The whole token as an integer; a leading '+' is accepted.
bool parseInteger(std::string_view token, long long& out);

bool equalsIgnoringCase(std::string_view a, std::string_view b);

}  // namespace geodex::detail
