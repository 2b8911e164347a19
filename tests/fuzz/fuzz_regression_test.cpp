// The inputs kept from fuzzing (tests/data/fuzz/<reader>/, docs/fuzzing.md), fed to their
// readers in the normal build: each must be read or refused cleanly, with the reader's
// documented error, as its file name says:
//   accept-*  the reader returns (preferences: without a warning)
//   refuse-*  the reader throws its documented error (preferences: defaults and a warning)
// Anything else (another exception, a crash, a sanitizer report in the sanitizer build) fails.
// A crash, hang or out-of-memory input found by a fuzzer goes here once its reader is fixed,
// minimised, under the name of the outcome the fix gives it.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "haptics/hid/hid_profile.h"
#include "haptics/hid/hid_recording.h"
#include "io/control_mesh_json.h"
#include "io/file_error.h"
#include "io/gltf_surface.h"
#include "io/gmsh_mesh.h"
#include "io/obj_surface.h"
#include "io/tetgen_mesh.h"
#include "io/vtk_volume_mesh.h"
#include "mesh/validation.h"
#include "project/preferences.h"
#include "project/project_file.h"
#include "sculpt/navigation.h"
#include "tools/session_script.h"

namespace sculpt {
namespace {

namespace fs = std::filesystem;

const fs::path kInputs = fs::path(SCULPT_SOURCE_DIR) / "tests" / "data" / "fuzz";

/// Thrown by a reader adapter when the reader refused the input in its documented way.
struct Refused {
  std::string message;
};

/// Reads one input as the fuzz target of the same name does (fuzz/<name>_fuzzer.cpp); throws
/// Refused for a documented refusal and lets everything else through.
using ReadFunction = std::function<void(const std::string& bytes, const fs::path& file)>;

template <typename Error, typename Body>
void refusedAs(Body body) {
  try {
    body();
  } catch (const Error& error) {
    throw Refused{error.what()};
  }
}

void readVolumeMesh(const std::function<VolumeMesh()>& read) {
  refusedAs<FileError>([&] {
    VolumeMesh mesh = read();
    orientCellsPositively(mesh);
    (void)findFoldedFace(mesh);
  });
}

const std::map<std::string, ReadFunction>& readers() {
  static const std::map<std::string, ReadFunction> kReaders = {
      {"control_mesh_json",
       [](const std::string& bytes, const fs::path&) {
         refusedAs<FileError>([&] { (void)validate(parseControlMeshJson(bytes, "fuzz.json")); });
       }},
      {"vtk_volume_mesh",
       [](const std::string& bytes, const fs::path&) {
         readVolumeMesh([&] {
           return parseVtkVolumeMesh(bytes, "fuzz.vtk", CellShapeCheck::OrientationFree);
         });
       }},
      {"gmsh_mesh",
       [](const std::string& bytes, const fs::path&) {
         readVolumeMesh(
             [&] { return parseGmshMesh(bytes, "fuzz.msh", CellShapeCheck::OrientationFree); });
       }},
      {"tetgen_mesh",
       [](const std::string& bytes, const fs::path&) {
         // The .node text, a NUL byte, the .ele text (fuzz/tetgen_mesh_fuzzer.cpp).
         const std::string_view input = bytes;
         const size_t separator = input.find('\0');
         const std::string_view ele =
             separator == std::string_view::npos ? std::string_view() : input.substr(separator + 1);
         readVolumeMesh([&] {
           return parseTetGenMesh(input.substr(0, separator), ele, "fuzz.node", "fuzz.ele",
                                  CellShapeCheck::OrientationFree);
         });
       }},
      {"obj_surface",
       [](const std::string& bytes, const fs::path&) {
         refusedAs<FileError>([&] { (void)parseObjSurface(bytes, "fuzz.obj"); });
       }},
      {"gltf_surface",
       [](const std::string&, const fs::path& file) {
         refusedAs<FileError>([&] { (void)GltfSurfaceFile::read(file); });
       }},
      {"session_script",
       [](const std::string& bytes, const fs::path&) {
         refusedAs<FileError>([&] { (void)parseSessionScript(bytes, "fuzz.json").duration(); });
       }},
      {"project_file",
       [](const std::string& bytes, const fs::path&) {
         refusedAs<FileError>([&] { (void)parseProject(bytes, "fuzz.sculpt"); });
       }},
      {"preferences",
       [](const std::string&, const fs::path& file) {
         // Never throws: a damaged file gives the defaults and a warning.
         const LoadedPreferences loaded = loadPreferences(file);
         if (!loaded.warning.empty()) throw Refused{loaded.warning};
       }},
      {"key_map",
       [](const std::string& bytes, const fs::path&) {
         // The lenient form must never throw; the strict one refuses the first bad line.
         std::string error;
         (void)app::KeyMap::fromText(bytes, &error);
         refusedAs<std::invalid_argument>([&] { (void)app::KeyMap::fromText(bytes, nullptr); });
       }},
      {"hid_profile",
       [](const std::string& bytes, const fs::path&) {
         refusedAs<FileError>([&] { (void)haptics::parseHidProfile(bytes, "fuzz-profile.json"); });
       }},
      {"hid_recording",
       [](const std::string& bytes, const fs::path&) {
         refusedAs<FileError>([&] {
           const haptics::HidRecording recording =
               haptics::parseHidRecording(bytes, "fuzz-recording.txt");
           (void)haptics::topLevelUsage(recording.descriptor);
         });
       }},
  };
  return kReaders;
}

std::string fileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<fs::path> inputsOf(const std::string& reader) {
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(kInputs / reader)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

bool startsWith(const std::string& text, std::string_view prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

TEST(FuzzRegression, EveryReaderHasInputsAndEveryInputDirectoryAReader) {
  for (const auto& [name, read] : readers()) {
    ASSERT_TRUE(fs::is_directory(kInputs / name)) << kInputs / name;
    EXPECT_FALSE(inputsOf(name).empty()) << "no inputs for " << name;
  }
  for (const fs::directory_entry& entry : fs::directory_iterator(kInputs)) {
    if (!entry.is_directory()) continue;
    const std::string name = entry.path().filename().string();
    EXPECT_EQ(readers().count(name), 1u) << "no reader for tests/data/fuzz/" << name;
  }
}

class FuzzInputs : public testing::TestWithParam<std::string> {};

TEST_P(FuzzInputs, AreReadOrRefusedAsTheirNamesSay) {
  const ReadFunction& read = readers().at(GetParam());
  for (const fs::path& file : inputsOf(GetParam())) {
    const std::string name = file.filename().string();
    SCOPED_TRACE(name);
    const bool accept = startsWith(name, "accept-");
    ASSERT_TRUE(accept || startsWith(name, "refuse-"))
        << "name it accept-* or refuse-* (tests/data/fuzz/README.md)";
    try {
      read(fileBytes(file), file);
      EXPECT_TRUE(accept) << "read, but its name says it must be refused";
    } catch (const Refused& refused) {
      EXPECT_FALSE(accept) << "refused, but its name says it must be read: " << refused.message;
      EXPECT_FALSE(refused.message.empty()) << "refused without a message";
    }
  }
}

std::vector<std::string> readerNames() {
  std::vector<std::string> names;
  for (const auto& entry : readers()) names.push_back(entry.first);
  return names;
}

INSTANTIATE_TEST_SUITE_P(Readers, FuzzInputs, testing::ValuesIn(readerNames()),
                         [](const testing::TestParamInfo<std::string>& param) {
                           return param.param;
                         });

}  // namespace
}  // namespace sculpt
