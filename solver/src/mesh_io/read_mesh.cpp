// The entry points of mesh input (mesh_io.h): choosing the reader by the file's extension or its
// content, and loadMesh, which reads, validates and builds a Mesh.

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "geodex/error.h"
#include "geodex/mesh_io.h"
#include "readers.h"
#include "text_input.h"

namespace geodex {

bool MeshReadResult::ok() const {
  return std::none_of(issues.begin(), issues.end(),
                      [](const MeshIssue& issue) { return issue.severity == Severity::Error; });
}

namespace {

using detail::LineReader;
using detail::Tokens;

/// "off", "obj", "ply" from the first bytes, or "" when they do not tell.
std::string detectFormat(std::string_view bytes) {
  LineReader lines(bytes);
  std::string_view line;
  std::string_view token;
  while (lines.next(line)) {
    Tokens tokens(detail::withoutComment(line));
    if (!tokens.next(token)) continue;
    if (token == "ply" && lines.lineNumber() == 1) return "ply";
    if (token.size() >= 3 && token.substr(token.size() - 3) == "OFF") return "off";
    static constexpr std::string_view kObjStarts[] = {"v", "vt", "vn", "vp", "f", "g",
                                                      "o", "s",  "l",  "usemtl", "mtllib"};
    if (std::find(std::begin(kObjStarts), std::end(kObjStarts), token) != std::end(kObjStarts)) {
      return "obj";
    }
    long long count = 0;
    if (detail::parseInteger(token, count)) return "off";  // OFF without its optional header line
    return "";
  }
  return "";
}

/// The whole file, or InputError("io") naming why it cannot be read.
std::string readFileBytes(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw InputError("io", path + ": cannot read: " +
                               (error ? error.message() : std::string("not a regular file")));
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    throw InputError("io", path + ": cannot open: " + std::strerror(errno));
  }
  file.seekg(0, std::ios::end);
  const std::streamoff size = file.tellg();
  file.seekg(0, std::ios::beg);
  if (size < 0) throw InputError("io", path + ": cannot read (not a regular file?)");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  if (!file.read(bytes.data(), size)) throw InputError("io", path + ": read error");
  return bytes;
}

/// "off", "obj" or "ply" from the file name's extension (any case), or "" for any other.
std::string formatOfExtension(const std::string& path) {
  std::string format;
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of("/\\");
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) {
    const std::string_view extension = std::string_view(path).substr(dot + 1);
    for (const char* known : {"off", "obj", "ply"}) {
      if (detail::equalsIgnoringCase(extension, known)) format = known;
    }
  }
  return format;
}

}  // namespace

MeshReadResult readMeshFromMemory(std::string_view bytes, const std::string& nameForMessages,
                                  const std::string& formatHint) {
  detail::SoupBuilder builder(nameForMessages);
  std::string format = formatHint;
  std::transform(format.begin(), format.end(), format.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (format.empty()) format = detectFormat(bytes);
  if (format == "obj") {
    detail::parseObj(bytes, builder);
  } else if (format == "off") {
    detail::parseOff(bytes, builder);
  } else if (format == "ply") {
    detail::parsePly(bytes, builder);
  } else if (formatHint.empty()) {
    builder.fail("unknown-format", 0, "cannot tell the mesh format (OFF, OBJ or PLY expected)");
  } else {
    builder.fail(
        "unknown-format", 0,
        "unknown mesh format " + detail::shown(formatHint) + " (off, obj or ply expected)");
  }
  return builder.finish();
}

MeshReadResult readMesh(const std::string& path) {
  const std::string bytes = readFileBytes(path);
  return readMeshFromMemory(bytes, path, formatOfExtension(path));
}

Mesh loadMesh(const std::string& path, std::vector<MeshIssue>* warnings) {
  MeshReadResult result = readMesh(path);
  validateMesh(result.soup, result.issues);
  for (const MeshIssue& issue : result.issues) {
    if (issue.severity == Severity::Error) throw InputError(issue.kind, issue.message);
  }
  if (warnings) warnings->insert(warnings->end(), result.issues.begin(), result.issues.end());
  return Mesh(std::move(result.soup));
}

}  // namespace geodex
