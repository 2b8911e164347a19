// Session-script parsing: a full script reads back its fields; malformed scripts (truncated,
// wrong types, unknown events or fields, non-finite numbers, negative durations) give the
// documented one-sentence FileError naming the event and field.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/file_error.h"
#include "tools/session_script.h"

namespace sculpt {
namespace {

std::string wrap(const std::string& events) {
  return R"({"format": "sculpt-session", "version": 1, "events": [)" + events + "]}";
}

std::string errorOf(const std::string& text) {
  try {
    parseSessionScript(text, "s.json");
  } catch (const FileError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SessionScript, ParsesEveryEventType) {
  const SessionScript script = parseSessionScript(wrap(R"(
    {"t": 0.5, "type": "grab", "point": [1, 2, 3], "path": [[0, 1, 2, 3], [1, 1, 2, 5]],
     "stiffness": 1e6, "release": 1.5, "keep": true},
    {"t": 0.25, "type": "inflate", "centre": [1, 1, 1], "radius": 0.5, "pressure": -2000, "duration": 0.5},
    {"t": 0, "type": "paint", "centre": [1, 1, 1], "radius": 0.5, "youngs": 1e7, "falloff": "sharp", "mirror": "xz"},
    {"t": 0, "type": "pin", "box": [[0, 0, 0], [3, 0.1, 3]], "unpin": true})"),
                                                  "s.json");
  ASSERT_EQ(script.events.size(), 4u);
  const auto& grab = std::get<GrabEvent>(script.events[0].action);
  EXPECT_EQ(grab.stiffness, 1e6);
  EXPECT_EQ(*grab.release, 1.5);
  EXPECT_TRUE(grab.keep);
  EXPECT_EQ(grab.targetAt(0.5), Eigen::Vector3d(1, 2, 4));
  EXPECT_EQ(grab.targetAt(7), Eigen::Vector3d(1, 2, 5));
  EXPECT_EQ(script.events[0].endTime(), 2.0);
  const auto& inflate = std::get<InflateEvent>(script.events[1].action);
  EXPECT_EQ(inflate.pressure, -2000);
  const auto& paint = std::get<PaintEvent>(script.events[2].action);
  EXPECT_EQ(paint.brush.falloff, Falloff::Sharp);
  EXPECT_TRUE(paint.brush.mirror.x && !paint.brush.mirror.y && paint.brush.mirror.z);
  EXPECT_TRUE(paint.brush.fields.youngs && !paint.brush.fields.density);
  EXPECT_TRUE(std::get<PinEvent>(script.events[3].action).unpin);
  EXPECT_EQ(script.duration(), 2.0);
}

TEST(SessionScript, MalformedScriptsGiveOneSentenceNamingEventAndField) {
  const std::string pin = R"({"t": 0, "type": "pin", "box": [[0, 0, 0], [1, 1, 1]]})";
  struct Case { std::string text, message; };
  const Case cases[] = {
      {wrap(pin).substr(0, 40),
       "s.json: not valid JSON (error at byte 41; truncated or malformed)."},
      {"[]", "s.json: the top level must be a JSON object."},
      {R"({"format": "mesh", "version": 1, "events": []})",
       "s.json: 'format' must be \"sculpt-session\"."},
      {R"({"format": "sculpt-session", "version": 2, "events": []})",
       "s.json: 'version' is 2; this program reads version 1."},
      {wrap(pin + R"(, {"t": 1, "type": "explode"})"),
       "s.json: events[1]: 'type' must be one of grab, inflate, paint, pin, curve, topology (got "
       "\"explode\")."},
      {wrap(R"({"t": "soon", "type": "pin", "box": [[0, 0, 0], [1, 1, 1]]})"),
       "s.json: events[0] (pin): 't' must be a finite number >= 0 (s) (got \"soon\")."},
      {wrap(R"({"t": 0, "type": "inflate", "pressure": 5, "duration": -1})"),
       "s.json: events[0] (inflate): 'duration' must be a finite number >= 0 (got -1)."},
      {wrap(R"({"t": 0, "type": "inflate", "pressure": 1e999, "duration": 1})"),
       "s.json: not valid JSON (a number is out of range, not finite)."},
      {wrap(R"({"t": 0, "type": "grab", "point": [1, 2], "path": [[0, 1, 1, 1]]})"),
       "s.json: events[0] (grab): 'point' must be an array of 3 finite numbers."},
      {wrap(
           R"({"t": 0, "type": "grab", "point": [1, 2, 3], "path": [[1, 1, 1, 1], [0, 1, 1, 1]]})"),
       "s.json: events[0] (grab): 'path[1]' must not go back in time (times must be "
       "non-decreasing)."},
      {wrap(R"({"t": 0, "type": "paint", "centre": [1, 1, 1], "radius": 1})"),
       "s.json: events[0] (paint): a paint needs at least one of 'youngs', 'density', 'damping', "
       "'poisson'."},
      {wrap(R"({"t": 0, "type": "paint", "centre": [1, 1, 1], "radius": 1, "density": 0})"),
       "s.json: events[0] (paint): 'density' must be a finite number > 0 (kg/m^3) (got 0)."},
      {wrap(
           R"({"t": 0, "type": "paint", "centre": [1, 1, 1], "radius": 1, "youngs": 1e6, "falloff": "soft"})"),
       "s.json: events[0] (paint): 'falloff' must be one of smooth, sphere, linear, sharp, "
       "constant (got \"soft\")."},
      {wrap(R"({"t": 0, "type": "pin", "box": [[0, 0, 0], [1, 1, 1]], "colour": 1})"),
       "s.json: events[0] (pin): unknown field 'colour'."},
      {wrap("42"), "s.json: events[0]: must be a JSON object."},
  };
  for (const Case& c : cases) EXPECT_EQ(errorOf(c.text), c.message) << c.text;
}

TEST(SessionScript, MissingFileIsAFileError) {
  EXPECT_THROW(loadSessionScript("/nonexistent/dir/script.json"), FileError);
}

TEST(SessionScript, TheBundledScriptsParse) {
  // The scripts the docs and benchmarks replay; a format change must keep them readable.
  int scripts = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(SCULPT_SOURCE_DIR "/assets/scripts")) {
    if (entry.path().extension() != ".json") continue;
    const SessionScript script = loadSessionScript(entry.path().string());
    EXPECT_FALSE(script.events.empty()) << entry.path();
    ++scripts;
  }
  EXPECT_GE(scripts, 9);
}

}  // namespace
}  // namespace sculpt

namespace sculpt {
namespace {

TEST(SessionScriptNesting, DeeplyNestedFileIsRejectedBeforeParsing) {
  const std::string text =
      "{\"events\": " + std::string(100000, '[') + std::string(100000, ']') + "}";
  try {
    parseSessionScript(text, "deep.json");
    FAIL() << "no error";
  } catch (const FileError& error) {
    EXPECT_NE(std::string(error.what()).find("deep.json: not valid JSON (nested deeper than 16"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace sculpt
