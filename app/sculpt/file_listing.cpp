#include "sculpt/file_listing.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>

namespace sculpt::app {
namespace fs = std::filesystem;
namespace {

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

bool endsWith(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// Names ignoring case first, so that "Block.json" sits beside "block3.json"; then exactly, so
// that the order is total.
bool nameBefore(const std::string& a, const std::string& b) {
  const std::string la = lower(a), lb = lower(b);
  return la != lb ? la < lb : a < b;
}

std::time_t toTimeT(fs::file_time_type time) {
  const auto system = std::chrono::file_clock::to_sys(time);
  return std::chrono::system_clock::to_time_t(
      std::chrono::time_point_cast<std::chrono::system_clock::duration>(system));
}

fs::path homeFolder() {
  const char* home = std::getenv("HOME");
  return home && *home ? fs::path(home) : fs::path("/");
}

// "name_####.ext": the part before the #'s, their count and the part after; count 0 for a
// name without a run of #'s.
struct Pattern {
  std::string before, after;
  size_t count = 0;
};
Pattern patternOf(const std::string& name) {
  const size_t first = name.find('#');
  if (first == std::string::npos) return {};
  const size_t last = name.find_first_not_of('#', first);
  const size_t end = last == std::string::npos ? name.size() : last;
  return {name.substr(0, first), name.substr(end), end - first};
}

bool matchesPattern(const Pattern& p, const std::string& name) {
  if (name.size() < p.before.size() + p.after.size() + 1) return false;
  if (name.compare(0, p.before.size(), p.before) != 0 || !endsWith(name, p.after)) return false;
  const std::string digits =
      name.substr(p.before.size(), name.size() - p.before.size() - p.after.size());
  return digits.size() >= p.count &&
         std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

FileFilter fileFilter(FileKind kind) {
  switch (kind) {
    case FileKind::Openable:
      return {"Openable (.sculpt .json .obj .gltf .glb)",
              {".sculpt", ".json", ".obj", ".gltf", ".glb"}};
    case FileKind::Project:
      return {"Projects (.sculpt)", {".sculpt"}};
    case FileKind::ControlMesh:
      return {"Control meshes (.json)", {".json"}};
    case FileKind::Surface:
      return {"Surfaces (.obj .gltf .glb)", {".obj", ".gltf", ".glb"}};
    case FileKind::TetMesh:
      return {"Tet meshes (.vtk .msh .node/.ele)", {".vtk", ".msh", ".node", ".ele"}};
    case FileKind::Script:
      return {"Session scripts (.json)", {".json"}};
    case FileKind::All:
      break;
  }
  return {"All files", {}};
}

bool passes(const FileFilter& filter, const std::string& name) {
  if (filter.extensions.empty()) return true;
  const std::string extension = lower(fs::path(name).extension().string());
  return std::find(filter.extensions.begin(), filter.extensions.end(), extension) !=
         filter.extensions.end();
}

FolderListing listFolder(const fs::path& folder, const FileFilter& filter, bool hidden) {
  FolderListing listing;
  std::error_code error;
  fs::directory_iterator it(folder, error);
  if (error) {
    listing.error =
        (error == std::errc::no_such_file_or_directory ? "No such folder: " : "Cannot read ") +
        folder.string() +
        (error == std::errc::no_such_file_or_directory ? "" : ": " + error.message());
    return listing;
  }
  for (; it != fs::directory_iterator(); it.increment(error)) {
    if (error) break;
    const fs::directory_entry& item = *it;
    FileEntry entry;
    entry.name = item.path().filename().string();
    if (!hidden && entry.name.starts_with('.')) continue;
    std::error_code ignored;
    entry.folder = item.is_directory(ignored);  // follows links: a link to a folder is a folder
    if (!entry.folder) {
      if (!item.is_regular_file(ignored) || !passes(filter, entry.name)) continue;
      const uintmax_t size = item.file_size(ignored);
      entry.size = ignored ? 0 : static_cast<uint64_t>(size);
    }
    const fs::file_time_type time = item.last_write_time(ignored);
    entry.modified = ignored ? 0 : toTimeT(time);
    listing.entries.push_back(std::move(entry));
  }
  if (error)  // the folder changed or became unreadable part way
    listing.error = "Cannot read all of " + folder.string() + ": " + error.message();
  sortEntries(listing.entries, SortKey::Name, true);
  return listing;
}

void sortEntries(std::vector<FileEntry>& entries, SortKey key, bool ascending) {
  std::sort(entries.begin(), entries.end(), [&](const FileEntry& a, const FileEntry& b) {
    if (a.folder != b.folder) return a.folder;
    const FileEntry& x = ascending ? a : b;
    const FileEntry& y = ascending ? b : a;
    if (key == SortKey::Size && x.size != y.size) return x.size < y.size;
    if (key == SortKey::Modified && x.modified != y.modified) return x.modified < y.modified;
    return nameBefore(x.name, y.name);
  });
}

std::string humanSize(uint64_t bytes) {
  if (bytes < 1000) return std::to_string(bytes) + " B";
  static const char* const units[] = {"kB", "MB", "GB", "TB", "PB"};
  double value = static_cast<double>(bytes) / 1000.0;
  size_t unit = 0;
  while (value >= 999.95 && unit + 1 < std::size(units)) value /= 1000.0, ++unit;
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %s", value, units[unit]);
  return text;
}

std::string humanDate(std::time_t time) {
  std::tm local{};
  if (!localtime_r(&time, &local)) return "?";
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M", &local);
  return text;
}

fs::path parentFolder(const fs::path& path) {
  fs::path normal = path.lexically_normal();
  if (normal.has_relative_path() && !normal.has_filename())
    normal = normal.parent_path();  // "a/b/"
  const fs::path parent = normal.parent_path();
  return parent.empty() ? normal : parent;
}

fs::path resolveTyped(const std::string& typed, const fs::path& folder) {
  fs::path path;
  if (typed == "~")
    path = homeFolder();
  else if (typed.starts_with("~/"))
    path = homeFolder() / typed.substr(2);
  else
    path = folder / typed;  // an absolute typed path replaces the folder
  path = path.lexically_normal();
  if (!path.has_filename() && path.has_relative_path()) path = path.parent_path();  // "a/b/"
  return path;
}

Completion completePath(const std::string& typed, const fs::path& folder,
                        const FileFilter& filter) {
  Completion result{typed, {}};
  const size_t slash = typed.find_last_of('/');
  const std::string head = slash == std::string::npos ? std::string() : typed.substr(0, slash + 1);
  const std::string prefix = slash == std::string::npos ? typed : typed.substr(slash + 1);
  const fs::path where = head.empty() ? folder : resolveTyped(head, folder);
  const FolderListing listing = listFolder(where, filter, prefix.starts_with('.'));
  std::vector<const FileEntry*> matches;
  for (const FileEntry& entry : listing.entries)
    if (entry.name.starts_with(prefix)) matches.push_back(&entry);
  if (matches.empty()) return result;
  std::string common = matches.front()->name;
  for (const FileEntry* entry : matches) {
    size_t n = 0;
    while (n < common.size() && n < entry->name.size() && common[n] == entry->name[n]) ++n;
    common.resize(n);
  }
  result.text = head + common;
  if (matches.size() == 1) {
    if (matches.front()->folder) result.text += '/';
    return result;
  }
  for (const FileEntry* entry : matches)
    result.candidates.push_back(entry->name + (entry->folder ? "/" : ""));
  return result;
}

std::string withSuffix(const std::string& path, const std::string& suffix) {
  if (suffix.empty() || endsWith(path, suffix)) return path;
  std::string base = path;
  const size_t dot =
      suffix.find_last_of('.');  // (".sculpt" alone is a name without extension to std::filesystem)
  const std::string extension = dot == std::string::npos ? std::string() : suffix.substr(dot);
  const size_t slash = base.find_last_of('/');
  const size_t nameStart = slash == std::string::npos ? 0 : slash + 1;
  if (!extension.empty() && endsWith(lower(base), lower(extension)) &&
      base.size() - extension.size() > nameStart)
    base.resize(base.size() - extension.size());
  const Pattern pattern = patternOf(suffix);
  if (pattern.count > 0) {  // "walk_0003" (a file of the sequence) -> "walk"
    size_t digits = base.size();
    while (digits > nameStart && std::isdigit(static_cast<unsigned char>(base[digits - 1])))
      --digits;
    if (digits < base.size() && base.size() - digits >= pattern.count &&
        endsWith(base.substr(0, digits), pattern.before) &&
        digits - pattern.before.size() > nameStart)
      base.resize(digits - pattern.before.size());
  }
  return base + suffix;
}

bool targetExists(const fs::path& path) {
  std::error_code ignored;
  const std::string name = path.filename().string();
  const Pattern pattern = patternOf(name);
  if (pattern.count == 0) return fs::exists(path, ignored);
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  for (fs::directory_iterator it(folder, ignored), end; !ignored && it != end;
       it.increment(ignored))
    if (matchesPattern(pattern, it->path().filename().string())) return true;
  return false;
}

std::vector<Place> standardPlaces(const fs::path& assets) {
  std::vector<Place> places;
  places.push_back({"Home", homeFolder()});
  std::error_code error;
  const fs::path working = fs::current_path(error);
  if (!error) places.push_back({"Working folder", working});
  if (fs::is_directory(assets, error)) places.push_back({"Assets", assets.lexically_normal()});
  places.push_back({"/", "/"});
  return places;
}

}  // namespace sculpt::app
