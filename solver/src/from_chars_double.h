#pragma once
// std::from_chars for double where the standard library has it (libstdc++ 11+; the Debian build),
// and a strtod_l fallback with the "C" locale where it does not (libc++ before 20, which OSS-Fuzz
// and ClusterFuzzLite build with: `-stdlib=libc++` deletes the floating-point overloads). The
// fallback accepts the same tokens: no leading space or '+', no hexadecimal; the callers check
// that the whole token was consumed.

#include <charconv>
#include <system_error>

#if !(defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L) && defined(_LIBCPP_VERSION)
#include <locale.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#endif

namespace geodex::detail {

inline std::from_chars_result fromCharsDouble(const char* begin, const char* end, double& out) {
#if !(defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L) && defined(_LIBCPP_VERSION)
  if (begin == end || *begin == '+' || std::isspace(static_cast<unsigned char>(*begin)) ||
      std::find_if(begin, end, [](char c) { return c == 'x' || c == 'X'; }) != end)
    return {begin, std::errc::invalid_argument};
  static const locale_t c = newlocale(LC_NUMERIC_MASK, "C", nullptr);
  const std::string token(begin, end);  // strtod needs a terminated string
  char* stop = nullptr;
  errno = 0;
  const double value = strtod_l(token.c_str(), &stop, c);
  if (stop == token.c_str()) return {begin, std::errc::invalid_argument};
  const char* ptr = begin + (stop - token.c_str());
  if (errno == ERANGE) return {ptr, std::errc::result_out_of_range};
  out = value;
  return {ptr, std::errc()};
#else
  return std::from_chars(begin, end, out);
#endif
}

}  // namespace geodex::detail
