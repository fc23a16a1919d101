#pragma once
// Errors about the user's input: what is wrong and where (file, line, element index).

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace geodex {

/// Bad input: a mesh the solver refuses, a source outside the mesh, a malformed file. The CLI
/// maps it to exit code 2 and prints what() after "error: ".
class InputError : public std::runtime_error {
 public:
  /// @param kind     short stable name of the problem, e.g. "non-manifold-edge", "nan-coordinate"
  /// @param message  the full sentence; should already name the element and, if known, file:line
  InputError(std::string kind, const std::string& message)
      : std::runtime_error(message), kind_(std::move(kind)) {}
  const std::string& kind() const { return kind_; }

 private:
  std::string kind_;
};

}  // namespace geodex
