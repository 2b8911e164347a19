#include "cli/record_rendering.h"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "anim/frame_pattern.h"
#include "cli/scene_options.h"
#include "io/number_text.h"
#include "util/shell_command.h"

namespace sculpt::cli {
namespace {

namespace fs = std::filesystem;


// The window program beside this executable.
fs::path windowProgram() {
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  const fs::path beside = error ? fs::path() : self.parent_path() / "sculpt";
  if (beside.empty() || !fs::exists(beside))
    throw std::runtime_error("rendering .png and .mp4 needs the window program 'sculpt' beside "
                             "sculpt-cli (build the 'sculpt' target)");
  return beside;
}

std::string formatNumber(double value) {
  std::string text;
  appendNumber(text, value);  // 17 digits, locale-free: the window program reads it back exactly
  return text;
}

}  // namespace

RenderOptions parseRenderOptions(const CliArgs& args) {
  RenderOptions options;
  options.noUi = args.has("no-ui");
  options.transparent = args.has("transparent");
  if (args.has("supersample")) options.supersample = args.intValue("supersample", 1, 1, 4);
  if (args.has("size")) options.size = args.requiredValue("size");
  return options;
}

ExportResult renderRecording(const std::string& scene, const CliArgs& args, double seconds,
                             double fps, const fs::path& out, ExportFormat format,
                             const RenderOptions& render, uint32_t frames) {
  if (args.has("integrator"))
    throw std::runtime_error(out.string() + ": --integrator is not available for rendered "
                             "outputs (the window program takes the scene's or project's)");
  std::vector<std::string> command = {windowProgram().string(), "--headless",
                                      "--record-seconds", formatNumber(seconds), "--fps",
                                      formatNumber(fps), "--record-out", out.string()};
  if (scene != kDefaultSceneName) command.insert(command.end(), {"--scene", scene});
  for (const char* option : {"script", "cage", "dt"})
    if (args.has(option))
      command.insert(command.end(), {std::string("--") + option, args.requiredValue(option)});
  if (args.has("levels") || args.has("level"))
    command.insert(command.end(),
                   {"--level", args.requiredValue(args.has("levels") ? "levels" : "level")});
  if (render.noUi) command.push_back("--no-ui");
  if (render.transparent) command.push_back("--transparent");
  if (render.supersample)
    command.insert(command.end(), {"--supersample", std::to_string(*render.supersample)});
  if (render.size) command.insert(command.end(), {"--size", *render.size});

  std::string line;
  if (!std::getenv("DISPLAY")) {
    if (!programOnPath("xvfb-run"))
      throw std::runtime_error(out.string() + ": rendering needs a display: set DISPLAY or install "
                               "xvfb-run (scripts/install-deps.sh installs it)");
    line = "xvfb-run -a -s '-screen 0 1920x1200x24' ";
  }
  for (const std::string& word : command) line += shellQuote(word) + ' ';
  line += "> /dev/null";  // the window program's summary line; ours comes at the end
  std::cerr << "record: rendering " << out.string() << " with the window program\n";
  const int status = std::system(line.c_str());
  if (status != 0)
    throw std::runtime_error(
        out.string() + ": the window program failed to render it (exit status " +
        std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : status) + ")");

  ExportResult result;
  result.frames = frames;
  if (format == ExportFormat::PngSequence) {
    const FramePattern pattern = framePatternOrThrow(out);
    for (uint32_t k = 1; k <= frames; ++k) result.files.push_back(framePath(pattern, k));
  } else {
    result.files.push_back(out);
  }
  for (const fs::path& file : result.files) {
    std::error_code error;
    const uintmax_t size = fs::file_size(file, error);
    if (error) throw std::runtime_error(file.string() + ": the window program did not write it");
    result.bytes += size;
  }
  return result;
}

}  // namespace sculpt::cli
