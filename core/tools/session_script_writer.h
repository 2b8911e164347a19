#pragma once
// Session scripts written back as JSON (docs/file-formats.md "Session script"), e.g. the strokes
// of a take made with the mouse, so that it can be replayed and re-recorded from the command
// line. parseSessionScript reads what this writes to the same events (numbers with 17
// significant digits round-trip exactly).

#include <filesystem>
#include <string>

#include "tools/session_script.h"

namespace sculpt {

/// The script as JSON text. Throws std::invalid_argument for a topology event (those belong to
/// a control mesh's own script, not to a take).
std::string sessionScriptJson(const SessionScript& script, const std::string& description = {});
/// Writes sessionScriptJson(...) atomically. Throws FileError or std::invalid_argument.
void saveSessionScript(const SessionScript& script, const std::filesystem::path& path,
                       const std::string& description = {});

}  // namespace sculpt
