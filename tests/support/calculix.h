#pragma once
#include "support/required_tool.h"
#include "support/shell_quote.h"
// A CalculiX (ccx) harness for tests: builds linear-elastic hexahedral models, writes a ccx
// input deck, runs `ccx` in a private temporary directory and reads back the nodal
// displacements. It exists so that our own mechanics can be compared against an independent,
// established solver; it only depends on ccx being on PATH (tests fail when it is not:
// SCULPT_REQUIRE_CCX).
//
// Conventions: node ids are 0-based here and written as CalculiX node id + 1; element node
// lists are in CalculiX/Abaqus order (C3D8: corners 1-4 counter-clockwise seen from +z on the
// bottom face, 5-8 above them, which is also VTK_HEXAHEDRON order; C3D20/C3D20R: the 8
// corners, then mid-edges 1-2, 2-3, 3-4, 4-1, 5-6, 6-7, 7-8, 8-5, 1-5, 2-6, 3-7, 4-8).
//
// Analysis: one linear *STATIC step (small displacements), one isotropic material, nodal
// forces (*CLOAD) and zero-displacement constraints (*BOUNDARY).

#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <atomic>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace sculpt::test {

struct CcxModel {
  std::vector<Eigen::Vector3d> nodes;           // node i is CalculiX node i + 1
  std::vector<std::vector<uint32_t>> elements;  // 0-based node ids, CalculiX/Abaqus order
  std::string elementType = "C3D8";             // "C3D8" (full 2x2x2), "C3D20R" or "C3D20"
  double youngs = 1.0, poisson = 0.3;
  std::vector<uint32_t> fixedNodes;  // all three displacement dofs zero
  // Single zero-displacement dofs (node, dof) with dof 1..3 = x, y, z as in CalculiX, for
  // statically determinate "roller" supports that leave Poisson contraction free.
  std::vector<std::pair<uint32_t, int>> fixedDofs;
  // Concentrated nodal forces. Several entries for one node are summed (ccx itself would let
  // a later *CLOAD line for the same node and dof replace an earlier one).
  std::vector<std::pair<uint32_t, Eigen::Vector3d>> loads;
};

struct CcxResult {
  std::vector<Eigen::Vector3d> displacement;  // one per model node
  std::string log;                            // ccx's stdout and stderr
};

// ---------------------------------------------------------------------------------------------
// Element tables (Abaqus numbering, 0-based)
// ---------------------------------------------------------------------------------------------

/// Corner pairs of the 12 hexahedron edges, in the order of the C3D20 mid-edge nodes 9..20.
// clang-format off
inline constexpr std::array<std::array<int, 2>, 12> kHexEdges = {{
    {0, 1}, {1, 2}, {2, 3}, {3, 0},  // bottom face
    {4, 5}, {5, 6}, {6, 7}, {7, 4},  // top face
    {0, 4}, {1, 5}, {2, 6}, {3, 7},  // vertical
}};
// clang-format on

/// Corner loops of the 6 hexahedron faces (Abaqus faces S1..S6, outward).
inline constexpr std::array<std::array<int, 4>, 6> kHexFaces = {
    {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1}, {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}}};

/// Nodes per element of a supported type, 0 for an unsupported one.
inline size_t ccxNodesPerElement(const std::string& type) {
  if (type == "C3D8") return 8;
  if (type == "C3D20" || type == "C3D20R") return 20;
  return 0;
}

/// Index (8..19) of the C3D20 mid-edge node between corners a and b, -1 when a-b is no edge.
inline int hexMidEdgeSlot(int a, int b) {
  for (size_t e = 0; e < kHexEdges.size(); ++e)
    if ((kHexEdges[e][0] == a && kHexEdges[e][1] == b) ||
        (kHexEdges[e][0] == b && kHexEdges[e][1] == a))
      return 8 + static_cast<int>(e);
  return -1;
}

// ---------------------------------------------------------------------------------------------
// Input deck
// ---------------------------------------------------------------------------------------------

/// A real number for a ccx data line. ccx reads each real field as Fortran f20.0 of its first
/// 20 characters only (nodes.f: read(textpart(2)(1:20),'(f20.0)')), silently truncating longer
/// ones, so "10.000000000000000000e-1" would be read as 10. We write the shortest text that
/// round-trips the double (at most 17 significant digits) and, only in the rare case it is still
/// longer than 20 characters, drop digits until it fits (never fewer than 13 significant).
inline std::string ccxReal(double v) {
  std::array<char, 64> buf{};
  auto res = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  std::string s(buf.data(), res.ptr);
  for (int digits = 16; s.size() > 20 && digits >= 1; --digits) {
    res = std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::general, digits);
    s.assign(buf.data(), res.ptr);
  }
  return s;
}

/// Checks what ccx would otherwise reject obscurely (or crash on: an element naming an
/// undefined node makes ccx 2.20 segfault). Returns an empty string when the model is valid.
inline std::string validateCcxModel(const CcxModel& m) {
  const size_t perElement = ccxNodesPerElement(m.elementType);
  if (perElement == 0) return "unsupported element type '" + m.elementType + "'";
  if (m.nodes.empty() || m.elements.empty()) return "model has no nodes or no elements";
  for (size_t i = 0; i < m.nodes.size(); ++i)
    if (!m.nodes[i].allFinite()) return "node " + std::to_string(i) + " is not finite";
  const auto badNode = [&](uint32_t n) { return n >= m.nodes.size(); };
  for (size_t e = 0; e < m.elements.size(); ++e) {
    if (m.elements[e].size() != perElement)
      return "element " + std::to_string(e) + " has " + std::to_string(m.elements[e].size()) +
             " nodes, " + m.elementType + " needs " + std::to_string(perElement);
    for (uint32_t n : m.elements[e])
      if (badNode(n))
        return "element " + std::to_string(e) + " references node " + std::to_string(n) + " of " +
               std::to_string(m.nodes.size());
  }
  for (uint32_t n : m.fixedNodes)
    if (badNode(n)) return "fixed node " + std::to_string(n) + " does not exist";
  for (const auto& [n, dof] : m.fixedDofs)
    if (badNode(n) || dof < 1 || dof > 3)
      return "fixed dof (" + std::to_string(n) + ", " + std::to_string(dof) + ") is invalid";
  for (const auto& [n, f] : m.loads)
    if (badNode(n) || !f.allFinite()) return "load on node " + std::to_string(n) + " is invalid";
  if (!(m.youngs > 0.0) || !(m.poisson > -1.0 && m.poisson < 0.5))
    return "material constants out of range";
  return {};
}

/// The ccx input deck for a (valid) model.
inline std::string writeCcxInput(const CcxModel& m) {
  std::ostringstream out;
  out << "** Written by tests/support/calculix.h\n";
  out << "*NODE, NSET=Nall\n";
  for (size_t i = 0; i < m.nodes.size(); ++i)
    out << i + 1 << ", " << ccxReal(m.nodes[i].x()) << ", " << ccxReal(m.nodes[i].y()) << ", "
        << ccxReal(m.nodes[i].z()) << "\n";

  // At most 16 entries per data line: a 20-node element continues on a second line after a
  // trailing comma (the layout of the ccx examples).
  out << "*ELEMENT, TYPE=" << m.elementType << ", ELSET=Eall\n";
  for (size_t e = 0; e < m.elements.size(); ++e) {
    out << e + 1;
    const auto& nodes = m.elements[e];
    for (size_t k = 0; k < nodes.size(); ++k) out << (k == 10 ? ",\n" : ", ") << nodes[k] + 1;
    out << "\n";
  }

  if (!m.fixedNodes.empty()) {
    out << "*NSET, NSET=Nfix\n";
    for (size_t k = 0; k < m.fixedNodes.size(); ++k)
      out << m.fixedNodes[k] + 1 << ((k % 8 == 7 || k + 1 == m.fixedNodes.size()) ? "\n" : ", ");
  }
  if (!m.fixedNodes.empty() || !m.fixedDofs.empty()) {
    out << "*BOUNDARY\n";
    if (!m.fixedNodes.empty()) out << "Nfix, 1, 3\n";
    for (const auto& [n, dof] : m.fixedDofs) out << n + 1 << ", " << dof << ", " << dof << "\n";
  }

  out << "*MATERIAL, NAME=Mat\n*ELASTIC\n"
      << ccxReal(m.youngs) << ", " << ccxReal(m.poisson) << "\n";
  out << "*SOLID SECTION, ELSET=Eall, MATERIAL=Mat\n";
  out << "*STEP\n*STATIC\n";

  std::map<uint32_t, Eigen::Vector3d> summed;  // ordered: a deterministic deck
  for (const auto& [n, f] : m.loads) {
    auto [it, inserted] = summed.try_emplace(n, Eigen::Vector3d::Zero());
    it->second += f;
  }
  std::ostringstream cload;
  for (const auto& [n, f] : summed)
    for (int d = 0; d < 3; ++d)
      if (f[d] != 0.0) cload << n + 1 << ", " << d + 1 << ", " << ccxReal(f[d]) << "\n";
  if (!cload.str().empty()) out << "*CLOAD\n" << cload.str();

  out << "*NODE PRINT, NSET=Nall\nU\n*END STEP\n";
  return out.str();
}

// ---------------------------------------------------------------------------------------------
// .dat parsing
// ---------------------------------------------------------------------------------------------

/// A real as ccx prints it: Fortran E13.6, which drops the 'E' for three-digit exponents
/// ("9.100000-121"). Returns nullopt unless the whole token is a number.
inline std::optional<double> parseFortranReal(std::string s) {
  for (char& c : s)
    if (c == 'D' || c == 'd') c = 'E';
  if (s.find_first_of("Ee") == std::string::npos) {
    const size_t sign = s.find_last_of("+-");
    if (sign != std::string::npos && sign > 0 && s[sign - 1] != 'E') s.insert(sign, 1, 'E');
  }
  if (!s.empty() && s.front() == '+') s.erase(0, 1);  // from_chars rejects a leading '+'
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || ptr != s.data() + s.size()) return std::nullopt;
  return v;
}

/// Nodal displacements from the text of a ccx .dat file holding a *NODE PRINT U block:
///
///   (blank)
///    displacements (vx,vy,vz) for set NALL and time  0.1000000E+01
///   (blank)
///            1  0.000000E+00  9.100000E-01 -1.950000E-01
///   ...
///
/// (node id as i10, then three E13.6 values). Takes the last such block, requires a finite value
/// for every node 1..nodeCount and nothing else. Returns nullopt and fills *error on failure.
inline std::optional<std::vector<Eigen::Vector3d>> parseCcxDisplacements(const std::string& dat,
                                                                         size_t nodeCount,
                                                                         std::string* error) {
  std::string sink;
  std::string& err = error ? *error : sink;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Eigen::Vector3d> u;
  std::vector<bool> seen;
  bool found = false, inBlock = false;
  std::istringstream in(dat);
  std::string line;
  size_t lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.find("displacements") != std::string::npos) {
      found = inBlock = true;  // a later block (increment) supersedes earlier ones
      u.assign(nodeCount, Eigen::Vector3d::Constant(nan));
      seen.assign(nodeCount, false);
      continue;
    }
    if (!inBlock) continue;
    std::istringstream fields(line);
    std::vector<std::string> tok;
    for (std::string t; fields >> t;) tok.push_back(t);
    if (tok.empty()) continue;
    long long id = 0;
    const auto [ptr, ec] = std::from_chars(tok[0].data(), tok[0].data() + tok[0].size(), id);
    if (tok.size() != 4 || ec != std::errc() || ptr != tok[0].data() + tok[0].size()) {
      inBlock = false;  // the header of some other print block
      continue;
    }
    if (id < 1 || static_cast<size_t>(id) > nodeCount || seen[static_cast<size_t>(id - 1)]) {
      err = "job.dat line " + std::to_string(lineNo) + ": unexpected node " + tok[0];
      return std::nullopt;
    }
    const size_t n = static_cast<size_t>(id - 1);
    for (int d = 0; d < 3; ++d) {
      const auto v = parseFortranReal(tok[static_cast<size_t>(d) + 1]);
      if (!v || !std::isfinite(*v)) {
        err = "job.dat line " + std::to_string(lineNo) + ": bad value '" +
              tok[static_cast<size_t>(d) + 1] + "'";
        return std::nullopt;
      }
      u[n][d] = *v;
    }
    seen[n] = true;
  }
  if (!found) {
    err = "job.dat has no displacement block";
    return std::nullopt;
  }
  for (size_t n = 0; n < nodeCount; ++n)
    if (!seen[n]) {
      err = "job.dat has no displacement for node " + std::to_string(n + 1) + " (of " +
            std::to_string(nodeCount) + ")";
      return std::nullopt;
    }
  return u;
}

// ---------------------------------------------------------------------------------------------
// Running ccx
// ---------------------------------------------------------------------------------------------

/// Whether an executable `ccx` is on PATH (the same lookup the shell in runCalculix does).
inline bool calculixAvailable() {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::istringstream dirs(path);
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const std::string candidate = (dir.empty() ? std::string(".") : dir) + "/ccx";
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0)
      return true;
  }
  return false;
}

/// Fails the current test when ccx is missing (scripts/install-deps.sh installs it).
#define SCULPT_REQUIRE_CCX() \
  SCULPT_REQUIRE_TOOL(::sculpt::test::calculixAvailable(), "ccx (CalculiX)")

namespace detail {

inline std::string readWholeFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The *ERROR lines of a ccx log (with the line after each, which usually carries the
/// detail), else its tail: enough to tell why a run failed.
inline std::string logExcerpt(const std::string& log) {
  std::istringstream in(log);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  std::string errors;
  for (size_t i = 0; i < lines.size() && errors.size() < 2000; ++i)
    if (lines[i].find("*ERROR") != std::string::npos) {
      // ccx repeats a message per integration point: keep each distinct one once.
      std::string message = lines[i] + "\n";
      if (i + 1 < lines.size()) message += lines[i + 1] + "\n";
      if (errors.find(message) == std::string::npos) errors += message;
    }
  if (!errors.empty()) return errors;
  const size_t first = lines.size() > 15 ? lines.size() - 15 : 0;
  std::string tail;
  for (size_t i = first; i < lines.size(); ++i) tail += lines[i] + "\n";
  return tail;
}

/// A fresh directory under the system temporary directory, unique per process and call so
/// that parallel ctest processes (and threads) never share one.
inline std::filesystem::path makeUniqueTempDir(std::string* error) {
  static std::atomic<unsigned> counter{0};
  const auto base = std::filesystem::temp_directory_path();
  for (int attempt = 0; attempt < 100; ++attempt) {
    const auto dir = base / ("sculpt_ccx_" + std::to_string(::getpid()) + "_" +
                             std::to_string(counter.fetch_add(1)));
    std::error_code ec;
    if (std::filesystem::create_directory(dir, ec)) return dir;  // false: exists (pid reuse)
    if (ec) {
      *error = "cannot create " + dir.string() + ": " + ec.message();
      return {};
    }
  }
  *error = "cannot find a free temporary directory name under " + base.string();
  return {};
}

/// Removes the run directory on every path out of runCalculix, unless SCULPT_CCX_KEEP is set
/// (for looking at job.inp / job.dat by hand).
struct RemoveDirOnExit {
  std::filesystem::path dir;
  ~RemoveDirOnExit() {
    if (dir.empty() || std::getenv("SCULPT_CCX_KEEP")) return;
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
};

}  // namespace detail

/// Writes job.inp in a fresh temporary directory, runs `ccx -i job` there (one thread, output
/// to ccx.log), parses the displacements from job.dat and removes the directory. Returns
/// nullopt and fills *error (if given) when the model is invalid, ccx is missing, exits with a
/// non-zero status or a signal, reports an *ERROR, or leaves no complete displacement block.
/// Note a singular model (too few constraints) is not detected: ccx's direct solver then
/// returns huge finite values.
inline std::optional<CcxResult> runCalculix(const CcxModel& model, std::string* error) {
  std::string sink;
  std::string& err = error ? *error : sink;
  if (std::string invalid = validateCcxModel(model); !invalid.empty()) {
    err = "invalid CalculiX model: " + invalid;
    return std::nullopt;
  }
  if (!calculixAvailable()) {
    err = "ccx (CalculiX) not found on PATH";
    return std::nullopt;
  }
  detail::RemoveDirOnExit guard{detail::makeUniqueTempDir(&err)};
  if (guard.dir.empty()) return std::nullopt;
  {
    std::ofstream inp(guard.dir / "job.inp", std::ios::binary);
    inp << writeCcxInput(model);
    if (!inp.flush()) {
      err = "cannot write " + (guard.dir / "job.inp").string();
      return std::nullopt;
    }
  }

  const std::string command = "cd " + shellQuote(guard.dir.string()) +
                              " && OMP_NUM_THREADS=1 ccx -i job > ccx.log 2>&1";
  const int status = std::system(command.c_str());
  CcxResult result;
  result.log = detail::readWholeFile(guard.dir / "ccx.log");
  const std::string where = " (in " + guard.dir.string() + ")";
  if (status == -1 || !WIFEXITED(status)) {
    err = "could not run ccx" + where;
    return std::nullopt;
  }
  // The shell reports a ccx killed by a signal (ccx 2.20 segfaults on some bad decks) as
  // 128 + signal; input errors exit 201.
  if (WEXITSTATUS(status) != 0) {
    err = "ccx exited with status " + std::to_string(WEXITSTATUS(status)) + where + ":\n" +
          detail::logExcerpt(result.log);
    return std::nullopt;
  }
  // Some failures (e.g. an unreadable input file) still exit 0.
  if (result.log.find("*ERROR") != std::string::npos) {
    err = "ccx reported an error" + where + ":\n" + detail::logExcerpt(result.log);
    return std::nullopt;
  }
  auto u =
      parseCcxDisplacements(detail::readWholeFile(guard.dir / "job.dat"), model.nodes.size(), &err);
  if (!u) {
    err += where;
    return std::nullopt;
  }
  result.displacement = std::move(*u);
  return result;
}

// ---------------------------------------------------------------------------------------------
// Structured box meshes and loads
// ---------------------------------------------------------------------------------------------

/// nx by ny by nz C3D8 elements on [0, size.x] x [0, size.y] x [0, size.z]. Node (i, j, k) has
/// id i + (nx + 1) (j + (ny + 1) k); element (i, j, k) has id i + nx (j + ny k).
inline CcxModel boxC3D8(int nx, int ny, int nz, const Eigen::Vector3d& size) {
  if (nx < 1 || ny < 1 || nz < 1) throw std::invalid_argument("boxC3D8: empty grid");
  CcxModel m;
  m.elementType = "C3D8";
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        m.nodes.emplace_back(size.x() * i / nx, size.y() * j / ny, size.z() * k / nz);
  const auto id = [&](int i, int j, int k) {
    return static_cast<uint32_t>(i + (nx + 1) * (j + (ny + 1) * k));
  };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        m.elements.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                              id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
                              id(i, j + 1, k + 1)});
  return m;
}

/// nx by ny by nz 20-node serendipity elements (C3D20R when `reduced`, else C3D20) on the box.
/// The nodes are the points of the doubled (2nx+1)(2ny+1)(2nz+1) lattice with at most one odd
/// lattice coordinate (corners and edge midpoints; no face or body centres), numbered in
/// lattice order (x fastest), so neighbouring elements share their mid-edge nodes.
inline CcxModel boxC3D20(int nx, int ny, int nz, const Eigen::Vector3d& size, bool reduced) {
  if (nx < 1 || ny < 1 || nz < 1) throw std::invalid_argument("boxC3D20: empty grid");
  CcxModel m;
  m.elementType = reduced ? "C3D20R" : "C3D20";
  const int ax = 2 * nx + 1, ay = 2 * ny + 1, az = 2 * nz + 1;
  std::vector<int64_t> lattice(static_cast<size_t>(ax * ay * az), -1);
  const auto slot = [&](int a, int b, int c) { return static_cast<size_t>(a + ax * (b + ay * c)); };
  for (int c = 0; c < az; ++c)
    for (int b = 0; b < ay; ++b)
      for (int a = 0; a < ax; ++a) {
        if ((a % 2) + (b % 2) + (c % 2) > 1) continue;
        lattice[slot(a, b, c)] = static_cast<int64_t>(m.nodes.size());
        m.nodes.emplace_back(size.x() * a / (2 * nx), size.y() * b / (2 * ny),
                             size.z() * c / (2 * nz));
      }
  // Corner offsets on the doubled lattice, in C3D8 order.
  constexpr std::array<std::array<int, 3>, 8> corner = {
      {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 2}, {2, 0, 2}, {2, 2, 2}, {0, 2, 2}}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        std::vector<uint32_t> e;
        const auto at = [&](int a, int b, int c) {
          return static_cast<uint32_t>(lattice[slot(2 * i + a, 2 * j + b, 2 * k + c)]);
        };
        for (const auto& o : corner) e.push_back(at(o[0], o[1], o[2]));
        for (const auto& [p, q] : kHexEdges) {
          const auto& o = corner[static_cast<size_t>(p)];
          const auto& r = corner[static_cast<size_t>(q)];
          e.push_back(at((o[0] + r[0]) / 2, (o[1] + r[1]) / 2, (o[2] + r[2]) / 2));
        }
        m.elements.push_back(std::move(e));
      }
  return m;
}

/// Ids of the nodes whose coordinate `axis` (0..2) is within tol of value.
inline std::vector<uint32_t> nodesOnPlane(const CcxModel& m, int axis, double value,
                                          double tol = 1e-9) {
  std::vector<uint32_t> ids;
  for (size_t i = 0; i < m.nodes.size(); ++i)
    if (std::abs(m.nodes[i][axis] - value) <= tol) ids.push_back(static_cast<uint32_t>(i));
  return ids;
}

/// Id of the node at point p (within tol in every coordinate), if any.
inline std::optional<uint32_t> findNode(const CcxModel& m, const Eigen::Vector3d& p,
                                        double tol = 1e-9) {
  for (size_t i = 0; i < m.nodes.size(); ++i)
    if ((m.nodes[i] - p).cwiseAbs().maxCoeff() <= tol) return static_cast<uint32_t>(i);
  return std::nullopt;
}

/// Adds the consistent nodal forces of a uniform traction with resultant totalForce spread
/// over the element faces whose corners all lie in the plane axis = value. Each face gets the
/// share of its area; within a face, C3D8 (bilinear) puts 1/4 on each corner and C3D20
/// (serendipity 8-node face) -1/12 on each corner and +1/3 on each mid-edge node. The weights
/// are exact for parallelogram faces (all faces of the box meshes). Throws when no element
/// face lies in the plane or a face in it is shared by two elements (an interior plane).
inline void addUniformTraction(CcxModel& m, int axis, double value,
                               const Eigen::Vector3d& totalForce, double tol = 1e-9) {
  const size_t perElement = ccxNodesPerElement(m.elementType);
  if (perElement == 0) throw std::invalid_argument("addUniformTraction: unsupported element");
  struct Face {
    size_t element;
    size_t face;
    double area;
  };
  std::vector<Face> faces;
  std::map<std::array<uint32_t, 4>, int> useCount;
  double totalArea = 0.0;
  const auto onPlane = [&](uint32_t n) { return std::abs(m.nodes[n][axis] - value) <= tol; };
  for (size_t e = 0; e < m.elements.size(); ++e)
    for (size_t f = 0; f < kHexFaces.size(); ++f) {
      std::array<uint32_t, 4> c{};
      for (size_t k = 0; k < 4; ++k) c[k] = m.elements[e][static_cast<size_t>(kHexFaces[f][k])];
      if (!(onPlane(c[0]) && onPlane(c[1]) && onPlane(c[2]) && onPlane(c[3]))) continue;
      // Half the cross product of the diagonals: the area of any planar quadrilateral.
      const double area =
          0.5 * (m.nodes[c[2]] - m.nodes[c[0]]).cross(m.nodes[c[3]] - m.nodes[c[1]]).norm();
      faces.push_back({e, f, area});
      totalArea += area;
      std::sort(c.begin(), c.end());
      if (++useCount[c] > 1) throw std::invalid_argument("addUniformTraction: interior plane");
    }
  if (faces.empty() || !(totalArea > 0.0))
    throw std::invalid_argument("addUniformTraction: no element face in the plane");
  for (const Face& face : faces) {
    const Eigen::Vector3d share = totalForce * (face.area / totalArea);
    const auto& el = m.elements[face.element];
    const auto& corners = kHexFaces[face.face];
    for (size_t k = 0; k < 4; ++k) {
      const uint32_t c = el[static_cast<size_t>(corners[k])];
      if (perElement == 8) {
        m.loads.emplace_back(c, share / 4.0);
      } else {
        const int mid = hexMidEdgeSlot(corners[k], corners[(k + 1) % 4]);
        m.loads.emplace_back(c, -share / 12.0);
        m.loads.emplace_back(el[static_cast<size_t>(mid)], share / 3.0);
      }
    }
  }
}

}  // namespace sculpt::test
