#include "io/obj_surface.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "io/atomic_file.h"
#include "io/file_error.h"
#include "io/input_file.h"
#include "io/number_text.h"

namespace sculpt {
namespace {

constexpr uint32_t kNoIndex = SurfaceCorner::kNoIndex;

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

/// Removes and returns the next blank-separated token of `rest` (empty at the end).
std::string_view nextToken(std::string_view& rest) {
  size_t begin = 0;
  while (begin < rest.size() && isBlank(rest[begin])) ++begin;
  size_t end = begin;
  while (end < rest.size() && !isBlank(rest[end])) ++end;
  const std::string_view token = rest.substr(begin, end - begin);
  rest.remove_prefix(end);
  return token;
}

/// A token quoted for an error message: at most 40 characters, control bytes shown as '?'.
std::string quoted(std::string_view token) {
  constexpr size_t kMaxShown = 40;
  std::string text = "'";
  for (size_t i = 0; i < token.size() && i < kMaxShown; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    text += (c < 0x20 || c == 0x7f) ? '?' : token[i];
  }
  if (token.size() > kMaxShown) text += "...";
  return text + "'";
}

class ObjParser {
 public:
  explicit ObjParser(std::string_view sourceName) : source_(sourceName) {}

  SurfaceMesh parse(std::string_view text) {
    while (!text.empty()) {
      ++line_;
      const size_t end = text.find('\n');
      std::string_view content = text.substr(0, end);
      text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
      if (const size_t hash = content.find('#'); hash != std::string_view::npos) {
        content = content.substr(0, hash);
      }
      parseLine(content);
    }
    if (faces_.numRows() == 0) failFile("no faces (a surface needs at least one 'f' line)");
    return finish();
  }

 private:
  [[noreturn]] void failFile(const std::string& problem) const {
    throw FileError(std::string(source_) + ": " + problem);
  }
  [[noreturn]] void fail(const std::string& problem) const {
    failFile("line " + std::to_string(line_) + ": " + problem);
  }

  void parseLine(std::string_view rest) {
    const std::string_view keyword = nextToken(rest);
    if (keyword == "v") {
      // xyz, then an optional w and/or an rgb colour that we do not keep.
      parseNumbers(rest, "vertex", 3, 7, 3, positions_);
    } else if (keyword == "vt") {
      // u, then optional v and w; a missing v means 0.
      const size_t before = texcoords_.size();
      parseNumbers(rest, "texture coordinate", 1, 3, 2, texcoords_);
      if (texcoords_.size() == before + 1) texcoords_.push_back(0.0);
    } else if (keyword == "vn") {
      parseNumbers(rest, "normal", 3, 3, 3, normals_);
    } else if (keyword == "f") {
      parseFace(rest);
    }
    // Everything else (o, g, s, usemtl, mtllib, l, p, free-form geometry...) has no effect on
    // the polygon surface.
  }

  /// Reads between `minCount` and `maxCount` finite numbers and appends the first `keep` of them
  /// (fewer if fewer were given).
  void parseNumbers(std::string_view rest, const char* what, size_t minCount, size_t maxCount,
                    size_t keep, std::vector<double>& out) {
    size_t count = 0;
    for (std::string_view token = nextToken(rest); !token.empty(); token = nextToken(rest)) {
      if (count == maxCount) {
        fail(std::string(what) + " has more than " + std::to_string(maxCount) + " numbers");
      }
      const double value = parseNumber(token, what);
      if (count < keep) out.push_back(value);
      ++count;
    }
    if (count < minCount) {
      fail(std::string(what) + " has " + std::to_string(count) + " numbers, expected at least " +
           std::to_string(minCount));
    }
  }

  double parseNumber(std::string_view token, const char* what) const {
    std::string_view digits = token;
    if (digits.size() > 1 && digits.front() == '+') digits.remove_prefix(1);  // from_chars: no '+'
    double value = 0.0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error != std::errc() || end != digits.data() + digits.size()) {
      fail(std::string(what) + ": " + quoted(token) + " is not a number");
    }
    if (!std::isfinite(value)) fail(std::string(what) + ": " + quoted(token) + " is not finite");
    return value;
  }

  void parseFace(std::string_view rest) {
    uint32_t corners = 0;
    for (std::string_view token = nextToken(rest); !token.empty(); token = nextToken(rest)) {
      ++corners;
      faces_.values.push_back(parseCorner(token, corners));
    }
    if (corners < 3) {
      fail("face has " + std::to_string(corners) + " corners, a polygon needs at least 3");
    }
    if (faces_.values.size() >= kNoIndex) fail("too many face corners for 32-bit offsets");
    faces_.closeRow();
  }

  /// One corner: v, v/vt, v//vn or v/vt/vn.
  SurfaceCorner parseCorner(std::string_view token, uint32_t cornerNumber) const {
    std::string_view parts[3];
    size_t numParts = 0;
    for (std::string_view rest = token;;) {
      if (numParts == 3) fail(cornerLabel(token, cornerNumber) + "more than three '/' fields");
      const size_t slash = rest.find('/');
      parts[numParts++] = rest.substr(0, slash);
      if (slash == std::string_view::npos) break;
      rest.remove_prefix(slash + 1);
    }
    SurfaceCorner corner;
    corner.position = resolve(parts[0], positions_.size() / 3, "vertex", token, cornerNumber);
    if (numParts >= 2 && !(numParts == 3 && parts[1].empty())) {
      corner.texcoord =
          resolve(parts[1], texcoords_.size() / 2, "texture coordinate", token, cornerNumber);
    }
    if (numParts == 3) {
      corner.normal = resolve(parts[2], normals_.size() / 3, "normal", token, cornerNumber);
    }
    return corner;
  }

  std::string cornerLabel(std::string_view token, uint32_t cornerNumber) const {
    return "face corner " + std::to_string(cornerNumber) + " (" + quoted(token) + "): ";
  }

  /// A 1-based or negative (relative) OBJ index as a 0-based index into a list of `count`.
  uint32_t resolve(std::string_view digits, size_t count, const char* what, std::string_view token,
                   uint32_t cornerNumber) const {
    int64_t index = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
    if (digits.empty() || error != std::errc() || end != digits.data() + digits.size()) {
      fail(cornerLabel(token, cornerNumber) + what + " index " + quoted(digits) +
           " is not an integer");
    }
    if (index == 0) {
      fail(cornerLabel(token, cornerNumber) + what +
           " index 0 is invalid (OBJ indices start at 1)");
    }
    const auto size = static_cast<int64_t>(count);
    const int64_t zeroBased = index > 0 ? index - 1 : size + index;
    if (zeroBased < 0 || zeroBased >= size) {
      fail(cornerLabel(token, cornerNumber) + what + " index " + std::to_string(index) +
           " is out of range (" + std::to_string(count) + " defined above this line)");
    }
    return static_cast<uint32_t>(zeroBased);
  }

  SurfaceMesh finish() {
    if (positions_.size() / 3 >= kNoIndex || normals_.size() / 3 >= kNoIndex ||
        texcoords_.size() / 2 >= kNoIndex) {
      failFile("more than 2^32-2 elements in one list");
    }
    SurfaceMesh surface;
    surface.positions = Eigen::Map<const Points>(
        positions_.data(), static_cast<Eigen::Index>(positions_.size() / 3), 3);
    surface.normals = Eigen::Map<const Points>(normals_.data(),
                                               static_cast<Eigen::Index>(normals_.size() / 3), 3);
    surface.texcoords = Eigen::Map<const TexCoords>(
        texcoords_.data(), static_cast<Eigen::Index>(texcoords_.size() / 2), 2);
    surface.faces = std::move(faces_);
    return surface;
  }

  std::string_view source_;
  uint64_t line_ = 0;
  std::vector<double> positions_;  // x y z x y z ...
  std::vector<double> normals_;
  std::vector<double> texcoords_;  // u v u v ...
  CompressedRows<SurfaceCorner> faces_;
};

/// Appends " v", " v/vt", " v//vn" or " v/vt/vn" (1-based) for one corner.
void appendCorner(std::string& out, const SurfaceCorner& corner) {
  out += ' ';
  appendNumber(out, corner.position + 1);
  if (corner.texcoord == kNoIndex && corner.normal == kNoIndex) return;
  out += '/';
  if (corner.texcoord != kNoIndex) appendNumber(out, corner.texcoord + 1);
  if (corner.normal == kNoIndex) return;
  out += '/';
  appendNumber(out, corner.normal + 1);
}

}  // namespace

SurfaceMesh parseObjSurface(std::string_view text, std::string_view sourceName) {
  return ObjParser(sourceName).parse(text);
}

SurfaceMesh readObjSurface(const std::filesystem::path& path) {
  return parseObjSurface(readInputFile(path, kSurfaceInput), path.string());
}

std::string objSurfaceText(const SurfaceMesh& surface, NumberPrecision precision) {
  std::string out = "# sculpt surface: ";
  appendNumber(out, surface.numVertices());
  out += " vertices, ";
  appendNumber(out, surface.numFaces());
  out += " faces\n";
  for (Eigen::Index i = 0; i < surface.positions.rows(); ++i) {
    appendObjRecord(out, "v", surface.positions.row(i), precision);
  }
  for (Eigen::Index i = 0; i < surface.texcoords.rows(); ++i) {
    appendObjRecord(out, "vt", surface.texcoords.row(i), precision);
  }
  for (Eigen::Index i = 0; i < surface.normals.rows(); ++i) {
    appendObjRecord(out, "vn", surface.normals.row(i), precision);
  }
  for (uint32_t f = 0; f < surface.numFaces(); ++f) {
    out += 'f';
    for (const SurfaceCorner& corner : surface.faces.row(f)) appendCorner(out, corner);
    out += '\n';
  }
  return out;
}

void writeObjSurface(const std::filesystem::path& path, const SurfaceMesh& surface,
                     NumberPrecision precision) {
  if (!surface.positions.allFinite() || !surface.normals.allFinite() ||
      !surface.texcoords.allFinite()) {
    throw FileError(path.string() + ": cannot write a surface with non-finite coordinates");
  }
  writeFileAtomically(path, objSurfaceText(surface, precision));
}

}  // namespace sculpt
