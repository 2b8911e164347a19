#include "sculpt/file_browser.h"

#include <imgui.h>

#include <algorithm>
#include <cstring>

namespace sculpt::app {
namespace fs = std::filesystem;
namespace {

constexpr const char* kPopupId = "###file browser";
constexpr const char* kReplaceId = "Replace file?###replace";
constexpr int kKeyY = 'Y', kKeyN = 'N';  // GLFW's key codes for letters are their capitals

float scaled(float pixels) { return pixels * ImGui::GetFontSize() / 13.0f; }

const char* titleOf(FileBrowserUse use) {
  switch (use) {
    case FileBrowserUse::Open:
      return "Open";
    case FileBrowserUse::ImportSurface:
      return "Import surface";
    case FileBrowserUse::SaveProject:
      return "Save project as";
    case FileBrowserUse::Export:
      return "Export recording to";
    case FileBrowserUse::ReplayScript:
      return "Replay session script";
  }
  return "File";
}

const FileFilter& currentFilter(const FileBrowser& b) {
  static const FileFilter all = fileFilter(FileKind::All);
  return b.filter >= 0 && b.filter < static_cast<int>(b.filters.size())
             ? b.filters[static_cast<size_t>(b.filter)]
             : all;
}

bool hasParentRow(const FileBrowser& b) { return parentFolder(b.folder) != b.folder; }
int rowCount(const FileBrowser& b) {
  return static_cast<int>(b.listing.entries.size()) + (hasParentRow(b) ? 1 : 0);
}
// The entry at a row; nullptr for the ".." row or none.
const FileEntry* entryAt(const FileBrowser& b, int row) {
  const int index = row - (hasParentRow(b) ? 1 : 0);
  if (row < 0 || index < 0 || index >= static_cast<int>(b.listing.entries.size())) return nullptr;
  return &b.listing.entries[static_cast<size_t>(index)];
}

// The path field's text: written now, and again by the field's callback when it is being
// edited (an active ImGui text field keeps its own copy of the text).
void setField(FileBrowser& b, const std::string& text) {
  const size_t n = std::min(text.size(), b.typed.size() - 1);
  std::memcpy(b.typed.data(), text.data(), n);
  b.typed[n] = 0;
  b.replaceField = b.fieldActive;
  b.candidates.clear();
}

void relist(FileBrowser& b) {
  b.listing = listFolder(b.folder, currentFilter(b), b.hidden);
  sortEntries(b.listing.entries, b.sortKey, b.ascending);
  b.message = b.listing.error;
}

// Shows `folder` when it can be read; otherwise says why and stays. The folder left behind is
// selected when going up, so that Enter goes back down.
bool goTo(FileBrowser& b, const fs::path& folder) {
  FolderListing listing = listFolder(folder, currentFilter(b), b.hidden);
  if (!listing.error.empty() && listing.entries.empty()) {
    b.message = listing.error;
    return false;
  }
  const fs::path from = b.folder;
  b.folder = folder;
  b.listing = std::move(listing);
  sortEntries(b.listing.entries, b.sortKey, b.ascending);
  b.message = b.listing.error;
  b.selected = -1;
  for (int row = 0; row < rowCount(b); ++row)
    if (const FileEntry* e = entryAt(b, row); e && e->folder && folder / e->name == from)
      b.selected = row;
  b.scrollToSelection = b.selected >= 0;
  setField(b, b.save ? b.saveName : std::string());
  b.focusField = true;
  return true;
}

void select(FileBrowser& b, int row) {
  b.selected = std::clamp(row, 0, std::max(0, rowCount(b) - 1));
  if (rowCount(b) == 0) b.selected = -1;
  b.scrollToSelection = true;
  const FileEntry* e = entryAt(b, b.selected);
  if (!e) {
    setField(b, b.selected >= 0 ? ".." : "");
    return;
  }
  setField(b, e->folder ? e->name + "/" : e->name);
  if (!e->folder && b.save) b.saveName = e->name;
}

struct Outcome {
  std::optional<std::string> accepted;
  bool askReplace = false;
};

// Enter on the typed path: a folder is entered, a file accepted (Save: asking first when it
// exists); anything else leaves a message.
Outcome acceptTyped(FileBrowser& b) {
  const std::string text(b.typed.data());
  if (text.empty()) {
    b.message = b.save ? "Type a name to save as." : "Choose a file, or type its path.";
    return {};
  }
  const fs::path path = resolveTyped(text, b.folder);
  std::error_code error;
  if (fs::is_directory(path, error)) {
    goTo(b, path);
    return {};
  }
  if (!b.save) {
    const fs::file_status status = fs::status(path, error);
    if (status.type() == fs::file_type::regular) return {path.string(), false};
    if (status.type() == fs::file_type::not_found)
      b.message = "No such file: " + path.string();
    else if (error)
      b.message = "Cannot open " + path.string() + ": " + error.message();
    else
      b.message = "Not a file: " + path.string();
    return {};
  }
  const fs::path target = withSuffix(path.string(), b.saveSuffix);
  if (!fs::is_directory(target.parent_path(), error)) {
    b.message = "No such folder: " + target.parent_path().string();
    return {};
  }
  if (fs::is_directory(target, error)) {
    b.message = "A folder has that name: " + target.string();
    return {};
  }
  if (targetExists(target)) {
    b.pendingOverwrite = target.string();
    return {std::nullopt, true};
  }
  return {target.string(), false};
}

Outcome activate(FileBrowser& b, int row) {
  if (row < 0) return acceptTyped(b);
  const FileEntry* e = entryAt(b, row);
  if (!e) {
    goTo(b, parentFolder(b.folder));
    return {};
  }
  if (e->folder) {
    goTo(b, b.folder / e->name);
    return {};
  }
  setField(b, e->name);
  if (b.save) b.saveName = e->name;
  return acceptTyped(b);
}

int fieldCallback(ImGuiInputTextCallbackData* data) {
  FileBrowser& b = *static_cast<FileBrowser*>(data->UserData);
  const auto replace = [data](const std::string& text) {
    data->DeleteChars(0, data->BufTextLen);
    data->InsertChars(0, text.c_str());
    data->SelectionStart = data->SelectionEnd = data->CursorPos = data->BufTextLen;
  };
  if (data->EventFlag == ImGuiInputTextFlags_CallbackCompletion) {
    Completion completion = completePath(
        std::string(data->Buf, static_cast<size_t>(data->BufTextLen)), b.folder, currentFilter(b));
    replace(completion.text);
    b.candidates = std::move(completion.candidates);
    b.message.clear();
  } else if (data->EventFlag == ImGuiInputTextFlags_CallbackAlways && b.replaceField) {
    replace(std::string(b.typed.data()));
    b.replaceField = false;
  } else if (data->EventFlag == ImGuiInputTextFlags_CallbackEdit) {
    b.candidates.clear();
    b.message.clear();
  }
  return 0;
}

// The folder's path in the width there is, its start cut when it does not fit.
void folderLine(const std::string& path) {
  const float width = ImGui::GetContentRegionAvail().x;
  std::string shown = path;
  while (shown.size() > 4 && ImGui::CalcTextSize(("..." + shown).c_str()).x > width)
    shown.erase(0, 1);
  if (shown != path) shown = "..." + shown;
  ImGui::TextUnformatted(shown.c_str());
  if (shown != path && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", path.c_str());
}

void sideColumn(FileBrowser& b, const std::vector<std::string>& recent, ImVec2 size) {
  ImGui::BeginChild("places", size, true);
  ImGui::TextDisabled("Places");
  static const std::vector<Place> places = standardPlaces(fs::path(SCULPT_SOURCE_DIR) / "assets");
  for (const Place& place : places) {
    ImGui::PushID(place.path.c_str());
    if (ImGui::Selectable(place.label.c_str(), b.folder == place.path,
                          ImGuiSelectableFlags_DontClosePopups))
      goTo(b, place.path);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", place.path.c_str());
    ImGui::PopID();
  }
  ImGui::Spacing();
  ImGui::TextDisabled("Recent");
  if (recent.empty()) ImGui::TextDisabled("  (none yet)");
  for (const std::string& path : recent) {
    ImGui::PushID(path.c_str());
    const fs::path file(path);
    if (ImGui::Selectable(file.filename().c_str(), false, ImGuiSelectableFlags_DontClosePopups)) {
      std::error_code error;
      if (!fs::exists(file, error)) {
        b.message = "No longer there: " + path;
      } else if (goTo(b, file.parent_path())) {
        for (int row = 0; row < rowCount(b); ++row)
          if (const FileEntry* e = entryAt(b, row); e && e->name == file.filename().string())
            select(b, row);
        if (b.selected < 0 || !entryAt(b, b.selected)) setField(b, path);  // filtered out: typed
      }
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", path.c_str());
    ImGui::PopID();
  }
  ImGui::EndChild();
}

Outcome fileTable(FileBrowser& b, ImVec2 size) {
  Outcome outcome;
  const ImGuiTableFlags flags = ImGuiTableFlags_Sortable | ImGuiTableFlags_RowBg |
                                ImGuiTableFlags_ScrollY | ImGuiTableFlags_BordersOuter |
                                ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_NoSavedSettings;
  if (!ImGui::BeginTable("entries", 3, flags, size)) return outcome;
  const float pad = 2 * ImGui::GetStyle().CellPadding.x;
  ImGui::TableSetupColumn("Name",
                          ImGuiTableColumnFlags_WidthStretch | ImGuiTableColumnFlags_DefaultSort);
  ImGui::TableSetupColumn(
      "Size", ImGuiTableColumnFlags_WidthFixed | ImGuiTableColumnFlags_PreferSortDescending,
      ImGui::CalcTextSize("999.9 MB").x + pad);
  ImGui::TableSetupColumn(
      "Modified", ImGuiTableColumnFlags_WidthFixed | ImGuiTableColumnFlags_PreferSortDescending,
      ImGui::CalcTextSize("0000-00-00 00:00").x + pad);
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableHeadersRow();
  if (ImGuiTableSortSpecs* specs = ImGui::TableGetSortSpecs(); specs && specs->SpecsDirty) {
    if (specs->SpecsCount > 0) {
      const int column = specs->Specs[0].ColumnIndex;
      b.sortKey = column == 1 ? SortKey::Size : column == 2 ? SortKey::Modified : SortKey::Name;
      b.ascending = specs->Specs[0].SortDirection != ImGuiSortDirection_Descending;
      const FileEntry* was = entryAt(b, b.selected);
      const std::string selectedName = was ? was->name : std::string();
      sortEntries(b.listing.entries, b.sortKey, b.ascending);
      for (int row = 0; row < rowCount(b) && was; ++row)
        if (const FileEntry* e = entryAt(b, row); e && e->name == selectedName) b.selected = row;
    }
    specs->SpecsDirty = false;
  }
  const ImVec4 folderColour(0.55f, 0.78f, 1.0f, 1.0f);
  const int rows = rowCount(b);
  int activated = -2;
  for (int row = 0; row < rows; ++row) {
    const FileEntry* e = entryAt(b, row);
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::PushID(row);
    if (!e || e->folder) ImGui::PushStyleColor(ImGuiCol_Text, folderColour);
    const std::string label = !e ? std::string("..") : e->folder ? e->name + "/" : e->name;
    if (ImGui::Selectable(label.c_str(), b.selected == row,
                          ImGuiSelectableFlags_SpanAllColumns |
                              ImGuiSelectableFlags_AllowDoubleClick |
                              ImGuiSelectableFlags_DontClosePopups)) {
      select(b, row);
      if (ImGui::IsMouseDoubleClicked(0)) activated = row;
    }
    if (!e || e->folder) ImGui::PopStyleColor();
    if (b.scrollToSelection && b.selected == row) {
      ImGui::SetScrollHereY();
      b.scrollToSelection = false;
    }
    ImGui::PopID();
    ImGui::TableNextColumn();
    if (e && !e->folder) {
      const std::string bytes = humanSize(e->size);
      ImGui::SetCursorPosX(ImGui::GetCursorPosX() + ImGui::GetContentRegionAvail().x -
                           ImGui::CalcTextSize(bytes.c_str()).x);
      ImGui::TextUnformatted(bytes.c_str());
    }
    ImGui::TableNextColumn();
    if (e && e->modified != 0) ImGui::TextUnformatted(humanDate(e->modified).c_str());
  }
  if (rows == 0 || (rows == 1 && hasParentRow(b))) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextDisabled(b.listing.error.empty() ? "(no folders or matching files)"
                                                : "(unreadable)");
  }
  b.scrollToSelection = false;
  ImGui::EndTable();
  if (activated >= -1) outcome = activate(b, activated);
  return outcome;
}

// "Replace it?" over the browser: Yes (Y) gives the path, No (N, Escape) goes back to the list.
std::optional<std::string> replaceQuestion(FileBrowser& b) {
  std::optional<std::string> accepted;
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  if (!ImGui::BeginPopupModal(kReplaceId, nullptr, ImGuiWindowFlags_AlwaysAutoResize))
    return accepted;
  const std::string name = fs::path(b.pendingOverwrite).filename().string();
  ImGui::Text(
      name.find('#') == std::string::npos ? "%s already exists." : "Frames of %s already exist.",
      name.c_str());
  ImGui::TextDisabled("%s", fs::path(b.pendingOverwrite).parent_path().c_str());
  ImGui::TextUnformatted("Replace it?");
  const bool yes = ImGui::Button("Yes, replace (Y)") || ImGui::IsKeyPressed(kKeyY, false);
  ImGui::SameLine();
  const bool no = ImGui::Button("No (N)") || ImGui::IsKeyPressed(kKeyN, false) ||
                  ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
  if (yes) {
    accepted = b.pendingOverwrite;
  } else if (no) {
    b.message = "Not replaced: choose another name.";
    b.focusField = true;
  }
  if (yes || no) {
    b.pendingOverwrite.clear();
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
  return accepted;
}

}  // namespace

void openFileBrowser(FileBrowser& b, FileBrowserUse use, const std::string& start,
                     const std::string& saveSuffix) {
  b.use = use;
  b.save = use == FileBrowserUse::SaveProject || use == FileBrowserUse::Export;
  b.filters.clear();
  switch (use) {
    case FileBrowserUse::ReplayScript:
      b.filters = {fileFilter(FileKind::Script), fileFilter(FileKind::All)};
      b.filter = 0;
      b.saveSuffix.clear();
      break;
    case FileBrowserUse::Open:
    case FileBrowserUse::ImportSurface:
      for (int k = 0; k < kFileKindCount; ++k)
        b.filters.push_back(fileFilter(static_cast<FileKind>(k)));
      b.filter =
          static_cast<int>(use == FileBrowserUse::Open ? FileKind::Openable : FileKind::Surface);
      b.saveSuffix.clear();
      break;
    case FileBrowserUse::SaveProject:
      b.filters = {fileFilter(FileKind::Project), fileFilter(FileKind::All)};
      b.filter = 0;
      b.saveSuffix = ".sculpt";
      break;
    case FileBrowserUse::Export: {
      const std::string extension = fs::path(saveSuffix).extension().string();
      // (No "####" in a label: ImGui reads "##" as the start of an id.)
      b.filters = {{"This format (" + extension + ")", {extension}}, fileFilter(FileKind::All)};
      b.filter = 0;
      b.saveSuffix = saveSuffix;
      break;
    }
  }
  std::error_code error;
  const fs::path startPath = start.empty() ? fs::path() : fs::absolute(start, error);
  fs::path folder = b.folder;
  b.saveName.clear();
  if (!startPath.empty()) {
    if (fs::is_directory(startPath, error)) {
      folder = startPath;
    } else {
      if (fs::is_directory(startPath.parent_path(), error)) folder = startPath.parent_path();
      if (b.save) b.saveName = withSuffix(startPath.filename().string(), b.saveSuffix);
    }
  }
  if (b.save && b.saveName.empty()) b.saveName = withSuffix("untitled", b.saveSuffix);
  if (folder.empty() || !fs::is_directory(folder, error)) folder = fs::current_path(error);
  b.folder.clear();
  b.fieldActive = false;
  b.pendingOverwrite.clear();
  if (!goTo(b, folder.lexically_normal())) {  // unreadable: show the root rather than nothing
    const std::string why = b.message;
    goTo(b, "/");
    b.message = why;
  }
  b.openRequested = true;
}

std::optional<std::string> drawFileBrowser(FileBrowser& b,
                                           const std::vector<std::string>& recentFiles) {
  if (b.openRequested) {
    b.openRequested = false;
    ImGui::OpenPopup(kPopupId);
  }
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  // Placed and sized as it opens, and again when the UI scale changes under it.
  const bool rescaled = b.sizedForFont != ImGui::GetFontSize();
  b.sizedForFont = ImGui::GetFontSize();
  ImGui::SetNextWindowPos(viewport->GetCenter(), rescaled ? ImGuiCond_Always : ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(std::min(scaled(800), 0.95f * viewport->WorkSize.x),
                                  std::min(scaled(480), 0.9f * viewport->WorkSize.y)),
                           rescaled ? ImGuiCond_Always : ImGuiCond_Appearing);
  const std::string title = std::string(titleOf(b.use)) + kPopupId;
  if (!ImGui::BeginPopupModal(title.c_str(), nullptr, ImGuiWindowFlags_NoSavedSettings)) {
    b.fieldActive = false;
    return std::nullopt;
  }
  Outcome outcome;
  const ImGuiStyle& style = ImGui::GetStyle();

  // The folder, with Up
  if (ImGui::ArrowButton("##up", ImGuiDir_Up)) goTo(b, parentFolder(b.folder));
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Parent folder (Backspace)");
  ImGui::SameLine();
  folderLine(b.folder.string());

  // Places and recent files | the listing
  const float below = 3 * ImGui::GetFrameHeightWithSpacing();
  const float height = std::max(scaled(80), ImGui::GetContentRegionAvail().y - below);
  sideColumn(b, recentFiles,
             ImVec2(std::min(scaled(180), 0.3f * ImGui::GetContentRegionAvail().x), height));
  ImGui::SameLine();
  Outcome clicked = fileTable(b, ImVec2(0, height));
  if (clicked.accepted || clicked.askReplace) outcome = clicked;

  // The typed path, with the answer buttons
  const char* action = b.save ? "Save" : "Open";
  const float buttons = ImGui::CalcTextSize(action).x + ImGui::CalcTextSize("Cancel").x +
                        4 * style.FramePadding.x + 2 * style.ItemSpacing.x;
  ImGui::SetNextItemWidth(std::max(scaled(120), ImGui::GetContentRegionAvail().x - buttons));
  if (ImGui::IsWindowAppearing() || b.focusField) {
    ImGui::SetKeyboardFocusHere();
    b.focusField = false;
  }
  const bool entered = ImGui::InputTextWithHint(
      "##path", b.save ? "file name or path" : "path (Tab completes)", b.typed.data(),
      b.typed.size(),
      ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll |
          ImGuiInputTextFlags_CallbackCompletion | ImGuiInputTextFlags_CallbackAlways |
          ImGuiInputTextFlags_CallbackEdit,
      fieldCallback, &b);
  b.fieldActive = ImGui::IsItemActive();
  if (b.save && b.fieldActive && b.typed[0] != 0 && std::string(b.typed.data()).back() != '/')
    b.saveName = fs::path(b.typed.data()).filename().string();
  ImGui::SameLine();
  const bool pressed = ImGui::Button(action);
  ImGui::SameLine();
  bool cancel = ImGui::Button("Cancel");

  // One line under the field: what went wrong, else the completions, else a hint.
  if (!b.message.empty()) {
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", b.message.c_str());
  } else if (!b.candidates.empty()) {
    std::string line = std::to_string(b.candidates.size()) + " matches:";
    for (const std::string& c : b.candidates) line += "  " + c;
    ImGui::TextDisabled("%s", line.c_str());
  } else {
    ImGui::TextDisabled(
        "Up/Down choose, Enter opens, Backspace goes up, Tab completes a typed path");
  }
  if (ImGui::IsItemHovered() && !b.candidates.empty()) {
    std::string all;
    for (const std::string& c : b.candidates) all += c + "\n";
    ImGui::SetTooltip("%s", all.c_str());
  }

  // The filter, as wide as its longest label where there is room
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("Show");
  ImGui::SameLine();
  std::vector<const char*> labels;
  float longest = 0;
  for (const FileFilter& f : b.filters) {
    labels.push_back(f.label.c_str());
    longest = std::max(longest, ImGui::CalcTextSize(f.label.c_str()).x);
  }
  const float checkbox = ImGui::GetFrameHeight() + style.ItemInnerSpacing.x +
                         ImGui::CalcTextSize("Hidden files").x + style.ItemSpacing.x;
  ImGui::SetNextItemWidth(std::min(longest + ImGui::GetFrameHeight() + 2 * style.FramePadding.x,
                                   ImGui::GetContentRegionAvail().x - checkbox));
  if (ImGui::Combo("##filter", &b.filter, labels.data(), static_cast<int>(labels.size()))) {
    relist(b);
    b.selected = -1;
  }
  ImGui::SameLine();
  if (ImGui::Checkbox("Hidden files", &b.hidden)) relist(b);

  // Keys, unless the question is up (it has its own)
  const bool asking = !b.pendingOverwrite.empty();
  if (!asking && !outcome.accepted && !outcome.askReplace) {
    const auto key = [](ImGuiKey k) { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(k)); };
    if (entered || pressed ||
        (!b.fieldActive && key(ImGuiKey_Enter) && !ImGui::IsAnyItemActive())) {
      outcome = entered || pressed || b.typed[0] != 0 ? acceptTyped(b) : activate(b, b.selected);
      if (!outcome.accepted && !outcome.askReplace) b.focusField = true;
    } else if (key(ImGuiKey_DownArrow)) {
      select(b, b.selected + 1);
    } else if (key(ImGuiKey_UpArrow)) {
      select(b, b.selected < 0 ? 0 : b.selected - 1);
    } else if (!b.fieldActive && !ImGui::IsAnyItemActive() && key(ImGuiKey_Backspace)) {
      goTo(b, parentFolder(b.folder));
    } else if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
      cancel = true;
    }
  }
  if (outcome.askReplace) ImGui::OpenPopup(kReplaceId);
  std::optional<std::string> accepted = outcome.accepted;
  if (std::optional<std::string> replace = replaceQuestion(b)) accepted = replace;
  if (accepted) {
    b.folder = fs::path(*accepted).parent_path();  // the next opening starts here
    b.message.clear();
    b.candidates.clear();
  }
  if (accepted || cancel) {
    b.pendingOverwrite.clear();
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
  return accepted;
}

}  // namespace sculpt::app
