#pragma once
// Rendered outputs of `sculpt-cli record` (name_####.png, .mp4): images need the window's
// renderer, so the take is recorded and rendered by the window program `sculpt` (installed beside
// sculpt-cli) in headless mode, from the same scene, settings and script (the scene pipeline is
// deterministic, so it records the same take), under xvfb-run when there is no display.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "anim/export_result.h"
#include "anim/take_export.h"
#include "cli/cli_args.h"

namespace sculpt::cli {

struct RenderOptions {
  bool noUi = false;
  std::optional<int> supersample;
  bool transparent = false;
  std::optional<std::string> size;  ///< WxH
};

/// --no-ui, --supersample, --transparent, --size (checked by the window program).
RenderOptions parseRenderOptions(const CliArgs& args);

/// Runs the window program for one rendered output; returns the files it wrote. Throws
/// std::runtime_error with one sentence when it cannot run or fails.
ExportResult renderRecording(const std::string& scene, const CliArgs& args, double seconds,
                             double fps, const std::filesystem::path& out, ExportFormat format,
                             const RenderOptions& render, uint32_t frames);

}  // namespace sculpt::cli
