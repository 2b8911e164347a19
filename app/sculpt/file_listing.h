#pragma once
// What the file browser shows, without ImGui: a folder's entries (folders first), the kinds of
// file it filters by, sizes and dates as people read them, completion of a typed path, and the
// places offered beside the listing. Nothing here throws: file system errors become messages.

#include <cstdint>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

namespace sculpt::app {

/// The kinds of file the browser filters by, in its combo's order.
enum class FileKind { Openable, Project, ControlMesh, Surface, TetMesh, Script, All };
inline constexpr int kFileKindCount = 7;

struct FileFilter {
  std::string label;                    ///< as the combo shows it
  std::vector<std::string> extensions;  ///< lower case with the dot; empty: every file
};

FileFilter fileFilter(FileKind kind);
/// Whether `name`'s extension is one of the filter's (ignoring case).
bool passes(const FileFilter& filter, const std::string& name);

struct FileEntry {
  std::string name;
  bool folder = false;
  uint64_t size = 0;  ///< bytes; 0 for a folder
  std::time_t modified = 0;
};

struct FolderListing {
  std::vector<FileEntry> entries;  ///< folders first, then files, each by name
  std::string error;               ///< why the folder could not be read; empty: it could
};

enum class SortKey { Name, Size, Modified };

/// The folders and the files passing `filter` in `folder`; names starting with a dot only
/// with `hidden`. Entries that vanish or cannot be examined while listing are left out.
FolderListing listFolder(const std::filesystem::path& folder, const FileFilter& filter,
                         bool hidden = false);
/// Folders stay before files; within each, by `key` (ties and names ignore case).
void sortEntries(std::vector<FileEntry>& entries, SortKey key, bool ascending);

/// "532 B", "12.4 kB", "3.0 MB" (powers of 1000).
std::string humanSize(uint64_t bytes);
/// "2026-12-06 14:03" in local time.
std::string humanDate(std::time_t time);

/// The folder above `path` (the root stays the root).
std::filesystem::path parentFolder(const std::filesystem::path& path);
/// A typed path made absolute: "~" is the home folder, a relative path is relative to `folder`.
std::filesystem::path resolveTyped(const std::string& typed, const std::filesystem::path& folder);

struct Completion {
  std::string text;                     ///< the typed text, completed as far as it is sure
  std::vector<std::string> candidates;  ///< the names it could still become (folders end in /)
};
/// Tab completion of `typed` (relative to `folder`): the names in the typed folder that start
/// with the typed last part (folders, and files passing `filter`) extend it to their longest
/// common prefix; a single folder gets its "/". Candidates are listed when more than one match.
Completion completePath(const std::string& typed, const std::filesystem::path& folder,
                        const FileFilter& filter);

/// The path a save writes for `path` when files end with `suffix` (".sculpt", "_####.obj"):
/// unchanged when it already ends so, else with the suffix's extension (and a frame number for
/// a numbered suffix) replaced by the suffix: "walk.obj" or "walk_0003.obj" -> "walk_####.obj".
std::string withSuffix(const std::string& path, const std::string& suffix);
/// Whether saving to `path` replaces something: the file, or for a name_####.ext pattern any
/// file of that sequence already in the folder.
bool targetExists(const std::filesystem::path& path);

struct Place {
  std::string label;
  std::filesystem::path path;
};
/// Home, the working folder, `assets` (when it exists) and the root.
std::vector<Place> standardPlaces(const std::filesystem::path& assets);

}  // namespace sculpt::app
