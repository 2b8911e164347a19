#pragma once
// The file browser: a modal listing a folder (folders first, sizes and dates), with places and
// recent files beside it, a filter by kind of file, a typed path with Tab completion and
// keyboard navigation (Up/Down, Enter, Backspace for the parent folder, Escape). In Save mode a
// name that already exists asks before it is replaced. The listing logic is file_listing.h.

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "sculpt/file_listing.h"

namespace sculpt::app {

/// What the browser was opened for: its title, filters and mode, and where the answer goes.
enum class FileBrowserUse { Open, ImportSurface, SaveProject, Export, ReplayScript };

struct FileBrowser {
  FileBrowserUse use = FileBrowserUse::Open;
  bool save = false;       ///< Save mode: the name may be new; an existing one asks first
  std::string saveSuffix;  ///< what saved names end with (".sculpt", "_####.obj")
  std::vector<FileFilter> filters;
  int filter = 0;              ///< index into filters
  bool hidden = false;         ///< show names starting with a dot
  bool openRequested = false;  ///< opened by the next drawFileBrowser (outside any window)

  std::filesystem::path folder;  ///< absolute; kept between openings
  FolderListing listing;
  SortKey sortKey = SortKey::Name;
  bool ascending = true;
  int selected = -1;  ///< row: 0 is ".." where there is a parent, then listing.entries; -1: none
  bool scrollToSelection = false;

  std::array<char, 1024> typed{};  ///< the path field
  std::string saveName;            ///< Save mode: the name the field returns to after a move
  bool fieldActive = false, focusField = false, replaceField = false;
  std::vector<std::string> candidates;  ///< of the last Tab that did not decide
  std::string message;                  ///< one line: why something could not be done
  std::string pendingOverwrite;         ///< a path waiting for "Replace it?"
  float sizedForFont = 0;               ///< the font size the window was last sized for
};

/// Prepares `browser` for `use` and has it open in the next drawFileBrowser. `start` is a file
/// or folder to begin at (empty: the last folder shown, else the working folder); in Save mode
/// a file's name fills the path field. `saveSuffix` is the Export format's ending.
void openFileBrowser(FileBrowser& browser, FileBrowserUse use, const std::string& start,
                     const std::string& saveSuffix = {});

/// Draws the browser while it is open (call once per frame at the top level, outside any
/// window) and returns the accepted path, absolute, in the frame it is accepted.
std::optional<std::string> drawFileBrowser(FileBrowser& browser,
                                           const std::vector<std::string>& recentFiles);

}  // namespace sculpt::app
