// Messages and numbers for the mesh readers (see text_input.h).

#include "text_input.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <system_error>

#include "../from_chars_double.h"

namespace geodex::detail {

// ===  Messages  =================================================================================

std::string where(const std::string& file, int line) {
  if (line > 0) {
    return file.empty() ? "line " + std::to_string(line) + ": "
                        : file + ":" + std::to_string(line) + ": ";
  }
  return file.empty() ? std::string() : file + ": ";
}

std::string shown(std::string_view token) {
  constexpr std::size_t kMaxShown = 24;
  std::string out = "'";
  for (std::size_t i = 0; i < token.size() && i < kMaxShown; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\x%02x", c);
      out += buffer;
    }
  }
  if (token.size() > kMaxShown) out += "...";
  return out + "'";
}

// ===  Numbers  ==================================================================================

namespace {

/// from_chars rejects a leading '+', which some writers emit; "+-1" stays invalid.
const char* skipPlus(const char* begin, const char* end) {
  if (end - begin >= 2 && begin[0] == '+' && begin[1] != '-' && begin[1] != '+') return begin + 1;
  return begin;
}

}  // namespace

bool parseDouble(std::string_view token, double& out) {
  const char* end = token.data() + token.size();
  const char* begin = skipPlus(token.data(), end);
  if (begin == end) return false;
  const auto [stop, error] = fromCharsDouble(begin, end, out);
  if (stop != end) return false;
  if (error == std::errc()) return true;
  if (error != std::errc::result_out_of_range) return false;
  // Out of range: a negative decimal exponent means too small, anything else too large. (A
  // mantissa like 0.000…1e+5 with hundreds of zeros would be misjudged; no writer emits that.)
  const bool negative = *begin == '-';
  const char* exponent = std::find_if(begin, end, [](char c) { return c == 'e' || c == 'E'; });
  const bool tiny = exponent + 1 < end && exponent[1] == '-';
  const double magnitude = tiny ? 0.0 : std::numeric_limits<double>::infinity();
  out = negative ? -magnitude : magnitude;
  return true;
}

bool parseInteger(std::string_view token, long long& out) {
  const char* end = token.data() + token.size();
  const char* begin = skipPlus(token.data(), end);
  if (begin == end) return false;
  const auto [stop, error] = std::from_chars(begin, end, out);
  return error == std::errc() && stop == end;
}

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

}  // namespace geodex::detail
