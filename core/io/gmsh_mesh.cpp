#include "io/gmsh_mesh.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/input_file.h"
#include "io/text_scanner.h"
#include "io/volume_mesh_file.h"

namespace sculpt {
namespace {

/// Nodes of the linear volume elements that are read; 0 for every other type.
size_t linearVolumeNodeCount(int64_t type) {
  switch (type) {
    case 4:
      return 4;  // tetrahedron
    case 5:
      return 8;  // hexahedron
    case 6:
      return 6;  // prism
    case 7:
      return 5;  // pyramid
    default:
      return 0;
  }
}

/// Points, lines and surface elements of any order (GmshDefines.h): skipped.
bool isLowerDimensionalElementType(int64_t type) {
  return (type >= 1 && type <= 3) || (type >= 8 && type <= 10) || type == 15 || type == 16 ||
         (type >= 20 && type <= 28) || type == 34 || (type >= 36 && type <= 70);
}

std::string elementTypeDescription(int64_t type) {
  switch (type) {
    case 11:
      return "10-node tetrahedron";
    case 12:
      return "27-node hexahedron";
    case 13:
      return "18-node prism";
    case 14:
      return "14-node pyramid";
    case 17:
      return "20-node hexahedron";
    case 18:
      return "15-node prism";
    case 19:
      return "13-node pyramid";
    case 29:
      return "20-node tetrahedron";
    case 30:
      return "35-node tetrahedron";
    case 31:
      return "56-node tetrahedron";
    case 35:
      return "polyhedron";
    case 92:
      return "64-node hexahedron";
    case 93:
      return "125-node hexahedron";
    default:
      return "unknown";
  }
}

/// Gmsh node tag -> node index. Tags may be sparse: a direct table when they are reasonably
/// dense, a sorted list otherwise.
class NodeTagIndex {
 public:
  /// `tags` in node order; returns the first tag that appears twice, if any.
  std::optional<uint64_t> build(const std::vector<uint64_t>& tags) {
    const uint64_t maxTag = tags.empty() ? 0 : *std::max_element(tags.begin(), tags.end());
    if (maxTag < 4 * static_cast<uint64_t>(tags.size()) + 1024) {
      dense_.assign(static_cast<size_t>(maxTag) + 1, kAbsent);
      for (size_t i = 0; i < tags.size(); ++i) {
        uint32_t& slot = dense_[static_cast<size_t>(tags[i])];
        if (slot != kAbsent) return tags[i];
        slot = static_cast<uint32_t>(i);
      }
      return std::nullopt;
    }
    sparse_.resize(tags.size());
    for (size_t i = 0; i < tags.size(); ++i) sparse_[i] = {tags[i], static_cast<uint32_t>(i)};
    std::sort(sparse_.begin(), sparse_.end());
    for (size_t i = 1; i < sparse_.size(); ++i) {
      if (sparse_[i].first == sparse_[i - 1].first) return sparse_[i].first;
    }
    return std::nullopt;
  }

  std::optional<uint32_t> find(uint64_t tag) const {
    if (!sparse_.empty()) {
      const auto it =
          std::lower_bound(sparse_.begin(), sparse_.end(), std::pair<uint64_t, uint32_t>{tag, 0});
      if (it == sparse_.end() || it->first != tag) return std::nullopt;
      return it->second;
    }
    if (tag >= dense_.size() || dense_[static_cast<size_t>(tag)] == kAbsent) return std::nullopt;
    return dense_[static_cast<size_t>(tag)];
  }

 private:
  static constexpr uint32_t kAbsent = 0xffffffffu;
  std::vector<uint32_t> dense_;
  std::vector<std::pair<uint64_t, uint32_t>> sparse_;
};

class GmshReader {
 public:
  GmshReader(std::string_view text, std::string_view sourceName)
      : scanner_(text, sourceName), source_(sourceName) {}

  VolumeMesh read(CellShapeCheck shapes) {
    shapes_ = shapes;
    readMeshFormat();
    for (std::string_view section = scanner_.token(); !section.empty();
         section = scanner_.token()) {
      if (section == "$Nodes") {
        if (haveNodes_) scanner_.fail("a second $Nodes section");
        version41_ ? readNodes41() : readNodes22();
        scanner_.expectKeyword("$EndNodes");
        haveNodes_ = true;
      } else if (section == "$Elements") {
        if (haveElements_) scanner_.fail("a second $Elements section");
        version41_ ? readElements41() : readElements22();
        scanner_.expectKeyword("$EndElements");
        haveElements_ = true;
      } else if (section.front() == '$' && section.substr(0, 4) != "$End") {
        skipSection(section);
      } else {
        scanner_.fail("expected a section such as $Nodes or $Elements, found " +
                      TextScanner::quoted(section));
      }
    }
    if (!haveNodes_) scanner_.fail("the file has no $Nodes section");
    if (!haveElements_) scanner_.fail("the file has no $Elements section");
    return assemble();
  }

 private:
  // "$MeshFormat / version file-type data-size / $EndMeshFormat"
  void readMeshFormat() {
    if (scanner_.peekToken() != "$MeshFormat") {
      scanner_.fail("not a Gmsh .msh file of version 2 or 4 (expected $MeshFormat, found " +
                    scanner_.describeNext() + ")");
    }
    scanner_.token();
    const std::string_view version = scanner_.token();
    const uint64_t fileType = scanner_.count("the file type (0 for ASCII)");
    if (fileType != 0)
      scanner_.fail("binary .msh is not supported; save the mesh as ASCII 4.1 or 2.2");
    if (version.empty()) scanner_.failExpected("the format version");
    if (version == "4.1") {
      version41_ = true;
    } else if (version != "2" && version != "2.0" && version != "2.1" && version != "2.2") {
      scanner_.fail("MSH version " + TextScanner::printable(version) +
                    " is not supported; save the mesh as ASCII 4.1 or 2.2");
    }
    scanner_.count("the data size");
    scanner_.expectKeyword("$EndMeshFormat");
  }

  void skipSection(std::string_view section) {
    const size_t startLine = scanner_.line();
    const std::string end = "$End" + std::string(section.substr(1));
    for (std::string_view t = scanner_.token(); t != end; t = scanner_.token()) {
      if (t.empty()) {
        scanner_.failAt(startLine,
                        "the file ends inside the " + TextScanner::printable(section) + " section");
      }
    }
  }

  // ---- Numbers with messages that explain a short section -----------------------------------

  /// A number was expected (`what`): a "$End..." there means the section holds fewer entries
  /// than it declares.
  [[noreturn]] void failMissing(const std::string& what) {
    const std::string next = scanner_.describeNext();
    if (next.size() > 2 && next[1] == '$') {
      scanner_.fail("found " + next + " where " + what +
                    " should be: the section holds fewer entries than it declares");
    }
    scanner_.failExpected(what);
  }
  uint64_t count(const char* what, uint64_t index) {
    uint64_t value = 0;
    if (!scanner_.readUnsigned(value)) failMissing(std::string(what) + " " + std::to_string(index));
    return value;
  }
  int64_t integer(const char* what) {
    int64_t value = 0;
    if (!scanner_.readInteger(value)) failMissing(what);
    return value;
  }
  double real(uint64_t node) {
    double value = 0.0;
    if (!scanner_.readReal(value)) failMissing("a coordinate of node " + std::to_string(node));
    return value;
  }
  /// A number that must be on the current line (element records are one line each).
  uint64_t countOnLine(const char* what, uint64_t element) {
    if (scanner_.atLineEnd()) {
      scanner_.fail("element " + std::to_string(element) + ": the line ends before " + what);
    }
    return count(what, element);
  }

  // ---- $Nodes ---------------------------------------------------------------------------------

  void reserveNodes(uint64_t numNodes) {
    // At least a tag and three coordinates, each a digit and a separator.
    scanner_.checkCount(numNodes, 8, "nodes");
    nodeTags_.reserve(numNodes);
    coordinates_.reserve(3 * numNodes);
  }

  void addNodeCoordinates(uint64_t node, size_t extraValues) {
    for (int k = 0; k < 3; ++k) coordinates_.push_back(real(node));
    for (size_t k = 0; k < extraValues; ++k) real(node);  // parametric coordinates: not needed
  }

  struct BlockHeader41 {
    uint64_t numBlocks;
    uint64_t numItems;
  };
  /// The first line of a 4.1 $Nodes or $Elements section, "numEntityBlocks numItems minTag
  /// maxTag", where `item` ("node", "element") names the entries; the tag range is not needed.
  BlockHeader41 readBlockHeader41(const std::string& item) {
    const uint64_t numBlocks = scanner_.count("the number of " + item + " blocks");
    const uint64_t numItems = scanner_.count("the number of " + item + "s");
    scanner_.count("the smallest " + item + " tag");
    scanner_.count("the largest " + item + " tag");
    scanner_.checkCount(numBlocks, 8, item + " blocks");
    return {numBlocks, numItems};
  }

  // "numNodes", then per node "tag x y z".
  void readNodes22() {
    const uint64_t numNodes = scanner_.count("the number of nodes");
    reserveNodes(numNodes);
    for (uint64_t i = 0; i < numNodes; ++i) {
      const uint64_t tag = count("the tag of node", i);
      nodeTags_.push_back(tag);
      addNodeCoordinates(tag, 0);
    }
  }

  // "numEntityBlocks numNodes minTag maxTag", then per block "entityDim entityTag parametric n",
  // the n tags, then the n coordinate rows (x y z, plus entityDim parametric values if asked).
  void readNodes41() {
    const auto [numBlocks, numNodes] = readBlockHeader41("node");
    reserveNodes(numNodes);
    for (uint64_t block = 0; block < numBlocks; ++block) {
      const int64_t dimension = integer("the entity dimension of a node block");
      integer("the entity tag of a node block");
      const int64_t parametric = integer("the parametric flag of a node block");
      const uint64_t blockSize = scanner_.count("the number of nodes in a block");
      if (dimension < 0 || dimension > 3 || (parametric != 0 && parametric != 1)) {
        scanner_.fail("node block " + std::to_string(block) + ": entity dimension " +
                      std::to_string(dimension) + " or parametric flag " +
                      std::to_string(parametric) + " is invalid");
      }
      const uint64_t first = nodeTags_.size();
      if (blockSize > numNodes - first) {
        scanner_.fail("node block " + std::to_string(block) + " brings the nodes beyond the " +
                      std::to_string(numNodes) + " declared");
      }
      for (uint64_t i = 0; i < blockSize; ++i)
        nodeTags_.push_back(count("the tag of node", first + i));
      const size_t extra = parametric != 0 ? static_cast<size_t>(dimension) : 0;
      for (uint64_t i = 0; i < blockSize; ++i) addNodeCoordinates(nodeTags_[first + i], extra);
    }
    if (nodeTags_.size() != numNodes) {
      scanner_.fail("the node blocks hold " + std::to_string(nodeTags_.size()) +
                    " nodes, not the " + std::to_string(numNodes) + " declared");
    }
  }

  // ---- $Elements ------------------------------------------------------------------------------

  /// Reads the node tags of a volume element whose tag and type are read, up to its line end.
  void addVolumeElement(uint64_t tag, int64_t type) {
    const size_t numNodes = linearVolumeNodeCount(type);
    for (size_t k = 0; k < numNodes; ++k)
      elementNodeTags_.push_back(countOnLine("a node tag", tag));
    if (!scanner_.atLineEnd()) {
      scanner_.fail("element " + std::to_string(tag) + ": more than the " +
                    std::to_string(numNodes) + " node tags of element type " +
                    std::to_string(type));
    }
    elementTags_.push_back(tag);
    elementTypes_.push_back(static_cast<uint8_t>(type));
  }

  [[noreturn]] void rejectElementType(uint64_t tag, int64_t type) {
    scanner_.fail("element " + std::to_string(tag) + ": element type " + std::to_string(type) +
                  " (" + elementTypeDescription(type) +
                  ") is not supported; only linear tetrahedra (4), hexahedra (5), prisms (6) and "
                  "pyramids (7) are read");
  }

  // "numElements", then per line "tag type numTags tag... node...".
  void readElements22() {
    const uint64_t numElements = scanner_.count("the number of elements");
    scanner_.checkCount(numElements, 8, "elements");
    for (uint64_t i = 0; i < numElements; ++i) {
      const uint64_t tag = count("the tag of element number", i);
      if (scanner_.atLineEnd()) scanner_.fail("element " + std::to_string(tag) + ": no type");
      const int64_t type = integer("an element type");
      if (isLowerDimensionalElementType(type)) {
        scanner_.skipLine();
        continue;
      }
      if (linearVolumeNodeCount(type) == 0) rejectElementType(tag, type);
      const uint64_t numTags = countOnLine("its number of tags", tag);
      for (uint64_t k = 0; k < numTags; ++k) countOnLine("its tags", tag);
      addVolumeElement(tag, type);
    }
  }

  // "numEntityBlocks numElements minTag maxTag", then per block "entityDim entityTag type n" and
  // n lines "tag node...".
  void readElements41() {
    const auto [numBlocks, numElements] = readBlockHeader41("element");
    scanner_.checkCount(numElements, 4, "elements");
    uint64_t seen = 0;
    for (uint64_t block = 0; block < numBlocks; ++block) {
      const int64_t dimension = integer("the entity dimension of an element block");
      integer("the entity tag of an element block");
      const int64_t type = integer("the element type of an element block");
      const uint64_t blockSize = scanner_.count("the number of elements in a block");
      if (blockSize > numElements - seen) {
        scanner_.fail("element block " + std::to_string(block) +
                      " brings the elements beyond the " + std::to_string(numElements) +
                      " declared");
      }
      seen += blockSize;
      const bool volume = linearVolumeNodeCount(type) != 0;
      const bool skipped = !volume && (dimension < 3 || isLowerDimensionalElementType(type));
      for (uint64_t i = 0; i < blockSize; ++i) {
        const uint64_t tag = count("the tag of element number", i);
        if (skipped) {
          scanner_.skipLine();
        } else if (!volume) {
          rejectElementType(tag, type);
        } else {
          addVolumeElement(tag, type);
        }
      }
    }
    if (seen != numElements) {
      scanner_.fail("the element blocks hold " + std::to_string(seen) + " elements, not the " +
                    std::to_string(numElements) + " declared");
    }
  }

  // ---- Building the mesh ----------------------------------------------------------------------

  [[noreturn]] void failElement(uint64_t tag, const std::string& problem) const {
    throw FileError(source_ + ": element " + std::to_string(tag) + ": " + problem);
  }

  VolumeMesh assemble() {
    NodeTagIndex index;
    if (const auto repeated = index.build(nodeTags_)) {
      throw FileError(source_ + ": node tag " + std::to_string(*repeated) + " appears twice");
    }
    VolumeMesh mesh;
    mesh.positions.resize(static_cast<Eigen::Index>(nodeTags_.size()), 3);
    std::copy(coordinates_.begin(), coordinates_.end(), mesh.positions.data());

    std::vector<uint64_t> elementOfCell;
    size_t next = 0;  // into elementNodeTags_
    for (size_t e = 0; e < elementTags_.size(); ++e) {
      const int64_t type = elementTypes_[e];
      const size_t numNodes = linearVolumeNodeCount(type);
      std::array<uint32_t, 8> v{};
      for (size_t k = 0; k < numNodes; ++k, ++next) {
        const auto node = index.find(elementNodeTags_[next]);
        if (!node) {
          failElement(elementTags_[e], "node tag " + std::to_string(elementNodeTags_[next]) +
                                           " is not in $Nodes (node id out of range)");
        }
        v[k] = *node;
      }
      switch (type) {
        case 4:
          mesh.addTetrahedron({v[0], v[1], v[2], v[3]});
          break;
        case 5:
          mesh.addHexahedron(v);
          break;
        case 6:
          splitWedge(mesh, {v[0], v[1], v[2], v[3], v[4], v[5]});
          break;
        default:
          splitPyramid(mesh, {v[0], v[1], v[2], v[3], v[4]});
          break;
      }
      elementOfCell.resize(mesh.numCells(), elementTags_[e]);
    }
    throwOnVolumeMeshProblem(mesh, elementOfCell, "element", source_, shapes_);
    return mesh;
  }

  TextScanner scanner_;
  std::string source_;
  CellShapeCheck shapes_ = CellShapeCheck::Required;
  bool version41_ = false;
  bool haveNodes_ = false, haveElements_ = false;
  std::vector<uint64_t> nodeTags_;     ///< #nodes, in file order
  std::vector<double> coordinates_;    ///< #nodes*3
  std::vector<uint64_t> elementTags_;  ///< volume elements only
  std::vector<uint8_t> elementTypes_;
  std::vector<uint64_t> elementNodeTags_;
};

}  // namespace

VolumeMesh parseGmshMesh(std::string_view text, std::string_view sourceName,
                         CellShapeCheck shapes) {
  return GmshReader(text, sourceName).read(shapes);
}

VolumeMesh readGmshMesh(const std::filesystem::path& path, CellShapeCheck shapes) {
  const std::string text = readInputFile(path, kVolumeMeshInput);
  return parseGmshMesh(text, path.string(), shapes);
}

}  // namespace sculpt
