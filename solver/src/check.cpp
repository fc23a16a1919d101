#include "geodex/check.h"

namespace geodex {

void failCheck(const char* expr, const std::string& message, const char* file, int line) {
  std::ostringstream os;
  os << file << ":" << line << ": check failed: " << expr;
  if (!message.empty()) os << ": " << message;
  throw InternalError(os.str());
}

}  // namespace geodex
