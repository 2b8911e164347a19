// The file browser's logic on real folders (app/sculpt/file_listing.h): listing order and
// filters, sizes and dates as shown, Tab completion, the parent folder, save names with their
// suffix, and errors that become messages instead of exceptions.

#include "sculpt/file_listing.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "support/scratch_directory.h"

namespace sculpt::app {
namespace {

namespace fs = std::filesystem;

// HOME set for one scope, then restored (later tests and the preferences still need it).
class ScopedHome {
 public:
  explicit ScopedHome(const std::string& value) {
    if (const char* old = std::getenv("HOME")) old_ = old, had_ = true;
    ::setenv("HOME", value.c_str(), 1);
  }
  ~ScopedHome() { had_ ? ::setenv("HOME", old_.c_str(), 1) : ::unsetenv("HOME"); }
  ScopedHome(const ScopedHome&) = delete;
  ScopedHome& operator=(const ScopedHome&) = delete;

 private:
  std::string old_;
  bool had_ = false;
};

class FileListing : public ::testing::Test {
 protected:
  void file(const std::string& name, size_t bytes) {
    fs::create_directories((dir_.path() / name).parent_path());
    std::ofstream(dir_.path() / name, std::ios::binary) << std::string(bytes, 'x');
  }
  std::vector<std::string> names(const FolderListing& listing) {
    std::vector<std::string> result;
    for (const FileEntry& e : listing.entries) result.push_back(e.name + (e.folder ? "/" : ""));
    return result;
  }

  test::ScratchDirectory dir_{"file_listing"};
};

TEST_F(FileListing, FoldersComeFirstThenFilesByNameIgnoringCase) {
  file("zeta.sculpt", 10);
  file("Alpha.json", 2000);
  file("beta.obj", 3);
  file(".hidden.json", 1);
  fs::create_directory(dir_.path() / "meshes");
  fs::create_directory(dir_.path() / "Archive");
  const FolderListing listing = listFolder(dir_.path(), fileFilter(FileKind::All));
  EXPECT_TRUE(listing.error.empty());
  EXPECT_EQ(names(listing), (std::vector<std::string>{"Archive/", "meshes/", "Alpha.json",
                                                      "beta.obj", "zeta.sculpt"}));
  EXPECT_EQ(listing.entries[2].size, 2000u);
  EXPECT_EQ(listing.entries[0].size, 0u);
  EXPECT_FALSE(listing.entries[2].folder);
  EXPECT_TRUE(listing.entries[0].folder);
  // Modification times are the files' own (written just now).
  EXPECT_LE(std::abs(static_cast<double>(listing.entries[2].modified - std::time(nullptr))), 60.0);
  // Hidden names only when asked for.
  EXPECT_EQ(listFolder(dir_.path(), fileFilter(FileKind::All), true).entries.size(), 6u);
}

TEST_F(FileListing, SortingBySizeOrDateKeepsFoldersFirst) {
  file("small.obj", 5);
  file("large.obj", 5000);
  file("medium.obj", 500);
  fs::create_directory(dir_.path() / "sub");
  std::vector<FileEntry> entries = listFolder(dir_.path(), fileFilter(FileKind::All)).entries;
  sortEntries(entries, SortKey::Size, false);
  ASSERT_EQ(entries.size(), 4u);
  EXPECT_EQ(entries[0].name, "sub");
  EXPECT_EQ(entries[1].name, "large.obj");
  EXPECT_EQ(entries[3].name, "small.obj");
  sortEntries(entries, SortKey::Name, false);
  EXPECT_EQ(entries[0].name, "sub");
  EXPECT_EQ(entries[1].name, "small.obj");
  // Dates: an older file sorts first ascending.
  fs::last_write_time(dir_.path() / "medium.obj",
                      fs::last_write_time(dir_.path() / "small.obj") - std::chrono::hours(48));
  entries = listFolder(dir_.path(), fileFilter(FileKind::All)).entries;
  sortEntries(entries, SortKey::Modified, true);
  EXPECT_EQ(entries[1].name, "medium.obj");
}

TEST_F(FileListing, FiltersTakeTheirKindsOfFileIgnoringCase) {
  for (const char* name : {"a.sculpt", "b.json", "c.OBJ", "d.gltf", "e.glb", "f.vtk", "g.msh",
                           "h.node", "h.ele", "i.txt", "noextension"})
    file(name, 1);
  fs::create_directory(dir_.path() / "folder.obj");  // folders pass every filter
  const auto listed = [&](FileKind kind) {
    return names(listFolder(dir_.path(), fileFilter(kind)));
  };
  EXPECT_EQ(
      listed(FileKind::Openable),
      (std::vector<std::string>{"folder.obj/", "a.sculpt", "b.json", "c.OBJ", "d.gltf", "e.glb"}));
  EXPECT_EQ(listed(FileKind::Project), (std::vector<std::string>{"folder.obj/", "a.sculpt"}));
  EXPECT_EQ(listed(FileKind::ControlMesh), (std::vector<std::string>{"folder.obj/", "b.json"}));
  EXPECT_EQ(listed(FileKind::Script), (std::vector<std::string>{"folder.obj/", "b.json"}));
  EXPECT_EQ(listed(FileKind::Surface),
            (std::vector<std::string>{"folder.obj/", "c.OBJ", "d.gltf", "e.glb"}));
  EXPECT_EQ(listed(FileKind::TetMesh),
            (std::vector<std::string>{"folder.obj/", "f.vtk", "g.msh", "h.ele", "h.node"}));
  EXPECT_EQ(listed(FileKind::All).size(), 12u);
  EXPECT_EQ(fileFilter(FileKind::Project).label, "Projects (.sculpt)");
  EXPECT_TRUE(passes(fileFilter(FileKind::Surface), "x.GLB"));
  EXPECT_FALSE(passes(fileFilter(FileKind::Surface), "x.glb.txt"));
}

TEST_F(FileListing, SizesAndDatesReadAsPeopleWriteThem) {
  EXPECT_EQ(humanSize(0), "0 B");
  EXPECT_EQ(humanSize(999), "999 B");
  EXPECT_EQ(humanSize(1000), "1.0 kB");
  EXPECT_EQ(humanSize(12400), "12.4 kB");
  EXPECT_EQ(humanSize(999949), "999.9 kB");
  EXPECT_EQ(humanSize(999950), "1.0 MB");
  EXPECT_EQ(humanSize(3'000'000), "3.0 MB");
  EXPECT_EQ(humanSize(2'500'000'000ull), "2.5 GB");
  std::tm when{};
  when.tm_year = 2026 - 1900, when.tm_mon = 11, when.tm_mday = 6, when.tm_hour = 14,
  when.tm_min = 3;
  when.tm_isdst = -1;
  EXPECT_EQ(humanDate(std::mktime(&when)), "2026-12-06 14:03");  // local time both ways
}

TEST_F(FileListing, ParentFolderAndTypedPaths) {
  EXPECT_EQ(parentFolder("/a/b/c"), fs::path("/a/b"));
  EXPECT_EQ(parentFolder("/a/b/"), fs::path("/a"));
  EXPECT_EQ(parentFolder("/a"), fs::path("/"));
  EXPECT_EQ(parentFolder("/"), fs::path("/"));
  EXPECT_EQ(resolveTyped("x.json", "/data"), fs::path("/data/x.json"));
  EXPECT_EQ(resolveTyped("../y/", "/data/in"), fs::path("/data/y"));
  EXPECT_EQ(resolveTyped("/etc/passwd", "/data"), fs::path("/etc/passwd"));
  ScopedHome home("/home/someone");
  EXPECT_EQ(resolveTyped("~", "/data"), fs::path("/home/someone"));
  EXPECT_EQ(resolveTyped("~/m.sculpt", "/data"), fs::path("/home/someone/m.sculpt"));
}

TEST_F(FileListing, TabCompletesToTheLongestCommonPrefix) {
  file("block3.json", 1);
  file("block10.json", 1);
  file("blob.txt", 1);
  file("meshes/cube.json", 1);
  file("meshes/cage.json", 1);
  const FileFilter openable = fileFilter(FileKind::Openable);

  // Ambiguous: as far as the names agree, with the candidates (the .txt is filtered out).
  Completion c = completePath("bl", dir_.path(), openable);
  EXPECT_EQ(c.text, "block");
  EXPECT_EQ(c.candidates, (std::vector<std::string>{"block10.json", "block3.json"}));
  // With every file, "blob.txt" joins and the prefix stays "blo".
  c = completePath("bl", dir_.path(), fileFilter(FileKind::All));
  EXPECT_EQ(c.text, "blo");
  EXPECT_EQ(c.candidates.size(), 3u);
  // Unique: the whole name; a folder gets its slash.
  c = completePath("block3", dir_.path(), openable);
  EXPECT_EQ(c.text, "block3.json");
  EXPECT_TRUE(c.candidates.empty());
  c = completePath("me", dir_.path(), openable);
  EXPECT_EQ(c.text, "meshes/");
  // Inside a typed folder, relative or absolute.
  c = completePath("meshes/c", dir_.path(), openable);
  EXPECT_EQ(c.text, "meshes/c");
  EXPECT_EQ(c.candidates, (std::vector<std::string>{"cage.json", "cube.json"}));
  c = completePath((dir_.path() / "meshes" / "cu").string(), "/", openable);
  EXPECT_EQ(c.text, (dir_.path() / "meshes" / "cube.json").string());
  // Nothing matches, or the folder is missing: the text stays as typed.
  c = completePath("zzz", dir_.path(), openable);
  EXPECT_EQ(c.text, "zzz");
  EXPECT_TRUE(c.candidates.empty());
  c = completePath("nowhere/x", dir_.path(), openable);
  EXPECT_EQ(c.text, "nowhere/x");
}

TEST_F(FileListing, SaveNamesGetTheirSuffix) {
  EXPECT_EQ(withSuffix("/d/model", ".sculpt"), "/d/model.sculpt");
  EXPECT_EQ(withSuffix("/d/model.sculpt", ".sculpt"), "/d/model.sculpt");
  EXPECT_EQ(withSuffix("/d/model.SCULPT", ".sculpt"), "/d/model.sculpt");
  EXPECT_EQ(withSuffix("/d/take.glb", ".glb"), "/d/take.glb");
  EXPECT_EQ(withSuffix("/d/walk.obj", "_####.obj"), "/d/walk_####.obj");
  EXPECT_EQ(withSuffix("/d/walk_0003.obj", "_####.obj"), "/d/walk_####.obj");
  EXPECT_EQ(withSuffix("/d/walk_####.obj", "_####.obj"), "/d/walk_####.obj");
  EXPECT_EQ(withSuffix("/d/.obj", "_####.obj"), "/d/.obj_####.obj");  // never an empty name
  EXPECT_EQ(withSuffix("/d/x", ""), "/d/x");
}

TEST_F(FileListing, TargetsExistAsFilesOrAsSequences) {
  file("old.sculpt", 3);
  file("walk_0001.obj", 3);
  EXPECT_TRUE(targetExists(dir_.path() / "old.sculpt"));
  EXPECT_FALSE(targetExists(dir_.path() / "new.sculpt"));
  EXPECT_TRUE(targetExists(dir_.path() / "walk_####.obj"));
  EXPECT_FALSE(targetExists(dir_.path() / "run_####.obj"));
  EXPECT_FALSE(targetExists(dir_.path() / "walk_####.vtk"));
  EXPECT_FALSE(targetExists(dir_.path() / "missing" / "walk_####.obj"));
}

TEST_F(FileListing, UnreadableAndMissingFoldersGiveAMessageNotAnException) {
  FolderListing listing = listFolder(dir_.path() / "missing", fileFilter(FileKind::All));
  EXPECT_TRUE(listing.entries.empty());
  EXPECT_EQ(listing.error, "No such folder: " + (dir_.path() / "missing").string());
  // A file is not a folder.
  file("plain.json", 1);
  listing = listFolder(dir_.path() / "plain.json", fileFilter(FileKind::All));
  EXPECT_NE(listing.error.find("Cannot read"), std::string::npos) << listing.error;
  // A folder without read permission (root reads everything: nothing to test then).
  const fs::path locked = dir_.path() / "locked";
  fs::create_directory(locked);
  fs::permissions(locked, fs::perms::none);
  if (::geteuid() != 0) {
    listing = listFolder(locked, fileFilter(FileKind::All));
    EXPECT_TRUE(listing.entries.empty());
    EXPECT_EQ(listing.error, "Cannot read " + locked.string() + ": Permission denied");
    EXPECT_EQ(completePath("locked/a", dir_.path(), fileFilter(FileKind::All)).text, "locked/a");
  }
  fs::permissions(locked, fs::perms::owner_all);
}

TEST_F(FileListing, PlacesHaveHomeTheWorkingFolderAssetsAndTheRoot) {
  ScopedHome home(dir_.path().string());
  std::vector<Place> places = standardPlaces(dir_.path() / "no-assets");
  ASSERT_EQ(places.size(), 3u);
  EXPECT_EQ(places[0].path, dir_.path());
  EXPECT_EQ(places[1].path, fs::current_path());
  EXPECT_EQ(places[2].path, fs::path("/"));
  fs::create_directory(dir_.path() / "assets");
  places = standardPlaces(dir_.path() / "assets");
  ASSERT_EQ(places.size(), 4u);
  EXPECT_EQ(places[2].label, "Assets");
  EXPECT_EQ(places[2].path, dir_.path() / "assets");
}

}  // namespace
}  // namespace sculpt::app
