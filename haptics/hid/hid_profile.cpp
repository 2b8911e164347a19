#include "haptics/hid/hid_profile.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <system_error>

#include "io/file_error.h"
#include "io/json_fields.h"

namespace sculpt::haptics {
namespace {

using nlohmann::json;

constexpr std::array<const char*, kAxisCount> kTargetNames = {"tx", "ty", "tz", "rx", "ry", "rz"};
constexpr std::array<const char*, 3> kForceAxisNames = {"fx", "fy", "fz"};

std::string quoted(const std::string& text) {
  std::string out = "'";
  out += text;
  out += '\'';
  return out;
}

// Reads the fields of one JSON object, naming them in errors as "<path>.<key>".
class ObjectReader {
 public:
  ObjectReader(const json& object, std::string path, const std::string& source)
      : object_(object), path_(std::move(path)), source_(source) {
    if (!object_.is_object()) fail(path_, "must be an object");
  }

  [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
    throw FileError(source_ + ": " + field + ": " + problem);
  }
  std::string field(const char* key) const { return path_.empty() ? key : path_ + "." + key; }

  void allowOnly(std::initializer_list<const char*> keys) const {
    if (const std::optional<std::string> unknown = unknownJsonField(object_, keys))
      fail(field(unknown->c_str()), "unknown field (expected " + jsonFieldList(keys) + ")");
  }

  bool has(const char* key) const { return object_.contains(key); }
  const json& at(const char* key) const {
    if (!has(key)) fail(field(key), "is required");
    return object_.at(key);
  }

  std::string string(const char* key) const {
    const json& value = at(key);
    if (!value.is_string()) fail(field(key), "must be a string");
    return value.get<std::string>();
  }

  long long integer(const char* key, long long min, long long max) const {
    const json& value = at(key);
    if (!value.is_number_integer())
      fail(field(key),
           "must be a whole number from " + std::to_string(min) + " to " + std::to_string(max));
    const long long n =
        value.is_number_unsigned()
            ? static_cast<long long>(std::min<uint64_t>(value.get<uint64_t>(), uint64_t{1} << 62))
            : value.get<long long>();
    if (n < min || n > max)
      fail(field(key), std::to_string(n) + " is not from " + std::to_string(min) + " to " +
                           std::to_string(max));
    return n;
  }

  double number(const char* key, double fallback) const {
    if (!has(key)) return fallback;
    const json& value = object_.at(key);
    if (!value.is_number()) fail(field(key), "must be a number");
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(field(key), "must be finite");
    return x;
  }

  bool boolean(const char* key, bool fallback) const {
    if (!has(key)) return fallback;
    const json& value = object_.at(key);
    if (!value.is_boolean()) fail(field(key), "must be true or false");
    return value.get<bool>();
  }

  // A 16-bit ID as hexadecimal text ("046d", "0x046d") or a plain number.
  uint16_t hex16(const char* key) const {
    const json& value = at(key);
    if (value.is_number_integer()) return static_cast<uint16_t>(integer(key, 0, 0xFFFF));
    if (!value.is_string()) fail(field(key), "must be a hexadecimal string such as \"046d\"");
    const std::string given = value.get<std::string>();
    std::string text = given;
    if (text.rfind("0x", 0) == 0 || text.rfind("0X", 0) == 0) text = text.substr(2);
    unsigned parsed = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), parsed, 16);
    if (text.empty() || text.size() > 4 || ec != std::errc() || end != text.data() + text.size())
      fail(field(key), quoted(given) + " is not 1 to 4 hexadecimal digits");
    return static_cast<uint16_t>(parsed);
  }

  const json& array(const char* key) const {
    const json& value = at(key);
    if (!value.is_array()) fail(field(key), "must be an array");
    return value;
  }

 private:
  const json& object_;
  std::string path_;
  const std::string& source_;
};

size_t fieldSize(const ObjectReader& reader, const char* key) {
  if (!reader.has(key)) return 2;
  const long long size = reader.integer(key, 0, 64);
  if (size != 1 && size != 2 && size != 4)
    reader.fail(reader.field(key), std::to_string(size) + " is not 1, 2 or 4 bytes");
  return static_cast<size_t>(size);
}

// The offset of a field of `size` bytes; byte 0 is the report ID unless the report is unnumbered.
size_t fieldOffset(const ObjectReader& reader, size_t size, bool unnumberedInput) {
  const long long first = unnumberedInput ? 0 : 1;
  const long long last = static_cast<long long>(kMaxProfileReportBytes - size);
  const long long offset = reader.integer("byte_offset", 0, std::numeric_limits<int>::max());
  if (offset < first)
    reader.fail(reader.field("byte_offset"),
                "must be at least 1: byte 0 is the report ID (use report_id 0 for a device "
                "without numbered reports)");
  if (offset > last)
    reader.fail(reader.field("byte_offset"),
                std::to_string(offset) + " plus " + std::to_string(size) + " bytes runs past the " +
                    std::to_string(kMaxProfileReportBytes) + "-byte report");
  return static_cast<size_t>(offset);
}

template <size_t N>
size_t nameIndex(const ObjectReader& reader, const std::string& field, const json& value,
                 const std::array<const char*, N>& names) {
  std::string list;
  for (const char* name : names) list += std::string(list.empty() ? "" : ", ") + name;
  if (!value.is_string()) reader.fail(field, "must be one of " + list);
  const std::string text = value.get<std::string>();
  for (size_t i = 0; i < N; ++i)
    if (text == names[i]) return i;
  reader.fail(field, "unknown target " + quoted(text) + " (expected " + list + ")");
}

HidAxisField parseAxis(const json& object, const std::string& path, const std::string& source) {
  const ObjectReader reader(object, path, source);
  reader.allowOnly({"report_id", "byte_offset", "size", "signed", "scale", "dead_zone", "target"});
  HidAxisField axis;
  axis.reportId = static_cast<uint8_t>(reader.integer("report_id", 0, 255));
  axis.size = fieldSize(reader, "size");
  axis.byteOffset = fieldOffset(reader, axis.size, axis.reportId == 0);
  axis.isSigned = reader.boolean("signed", true);
  axis.scale = reader.number("scale", 1.0 / 350.0);
  if (axis.scale == 0.0) reader.fail(reader.field("scale"), "must not be 0");
  axis.deadZone = reader.number("dead_zone", 0.03);
  if (axis.deadZone < 0.0 || axis.deadZone >= 1.0)
    reader.fail(reader.field("dead_zone"), "must be at least 0 and less than 1");
  axis.target = static_cast<AxisTarget>(
      nameIndex(reader, reader.field("target"), reader.at("target"), kTargetNames));
  return axis;
}

HidButtonField parseButton(const json& object, const std::string& path, const std::string& source) {
  const ObjectReader reader(object, path, source);
  reader.allowOnly({"report_id", "byte_offset", "bit", "button"});
  HidButtonField button;
  button.reportId = static_cast<uint8_t>(reader.integer("report_id", 0, 255));
  button.byteOffset = fieldOffset(reader, 1, button.reportId == 0);
  button.bit = static_cast<int>(reader.integer("bit", 0, 7));
  button.button = static_cast<int>(reader.integer("button", 0, 31));
  return button;
}

HidForceOutput parseForceOutput(const json& object, const std::string& source) {
  const ObjectReader reader(object, "force_output", source);
  reader.allowOnly({"report_id", "byte_offset", "size", "signed", "scale", "axes", "max_force"});
  HidForceOutput output;
  output.reportId = static_cast<uint8_t>(reader.integer("report_id", 0, 255));
  output.size = fieldSize(reader, "size");
  output.isSigned = reader.boolean("signed", true);
  output.countsPerNewton = reader.number("scale", 0.0);
  if (!reader.has("scale") || output.countsPerNewton == 0.0)
    reader.fail(reader.field("scale"), "is required: counts per newton, not 0");
  output.maxForce = reader.number("max_force", 0.0);
  if (output.maxForce < 0.0) reader.fail(reader.field("max_force"), "must not be negative");
  const json& axes = reader.array("axes");
  if (axes.empty() || axes.size() > 3)
    reader.fail(reader.field("axes"), "must list 1 to 3 of fx, fy, fz");
  for (size_t i = 0; i < axes.size(); ++i) {
    const std::string field = reader.field("axes") + "[" + std::to_string(i) + "]";
    const auto axis = static_cast<ForceAxis>(nameIndex(reader, field, axes[i], kForceAxisNames));
    if (std::find(output.axes.begin(), output.axes.end(), axis) != output.axes.end())
      reader.fail(field,
                  std::string(kForceAxisNames[static_cast<size_t>(axis)]) + " is listed twice");
    output.axes.push_back(axis);
  }
  // The numbers follow one another: the last one must end inside the report.
  output.byteOffset = fieldOffset(reader, output.size * output.axes.size(), false);
  return output;
}

}  // namespace

const char* axisTargetName(AxisTarget target) { return kTargetNames[static_cast<size_t>(target)]; }

HidProfile parseHidProfile(std::string_view jsonText, const std::string& source) {
  json root;
  try {
    root = json::parse(jsonText.begin(), jsonText.end());
  } catch (const json::parse_error& error) {
    throw FileError(source + ": not valid JSON (" + error.what() + ")");
  } catch (const json::exception&) {  // out_of_range: a number beyond double's range
    throw FileError(source + ": not valid JSON (a number is out of range, not finite)");
  }
  if (!root.is_object()) throw FileError(source + ": a profile must be a JSON object");
  const ObjectReader reader(root, "", source);
  reader.allowOnly({"name", "comment", "vendor_id", "product_id", "usage_page", "usage", "axes",
                    "buttons", "force_output"});
  if (reader.has("comment")) reader.string("comment");  // free text for people, checked as text
  HidProfile profile;
  profile.name = reader.string("name");
  if (profile.name.empty()) reader.fail("name", "must not be empty");
  profile.vendorId = reader.hex16("vendor_id");
  profile.productId = reader.hex16("product_id");
  if (reader.has("usage_page")) profile.usagePage = reader.hex16("usage_page");
  if (reader.has("usage")) profile.usage = reader.hex16("usage");
  if (profile.usagePage.has_value() != profile.usage.has_value())
    reader.fail(profile.usagePage ? "usage" : "usage_page", "is required with the other one");

  const json& axes = reader.array("axes");
  for (size_t i = 0; i < axes.size(); ++i) {
    const std::string path = "axes[" + std::to_string(i) + "]";
    const HidAxisField axis = parseAxis(axes[i], path, source);
    for (const HidAxisField& other : profile.axes)
      if (other.target == axis.target)
        reader.fail(path + ".target", std::string(axisTargetName(axis.target)) +
                                          " is already the target of another axis");
    profile.axes.push_back(axis);
  }
  if (reader.has("buttons")) {
    const json& buttons = reader.array("buttons");
    for (size_t i = 0; i < buttons.size(); ++i) {
      const std::string path = "buttons[" + std::to_string(i) + "]";
      const HidButtonField button = parseButton(buttons[i], path, source);
      for (const HidButtonField& other : profile.buttons)
        if (other.button == button.button)
          reader.fail(path + ".button", std::to_string(button.button) + " is listed twice");
      profile.buttons.push_back(button);
    }
  }
  if (profile.axes.empty() && profile.buttons.empty())
    reader.fail("axes", "a profile needs at least one axis or button");

  // Report ID 0 (no numbered reports) changes where offsets start: it cannot mix with others.
  bool unnumbered = false, numbered = false;
  for (const HidAxisField& axis : profile.axes) (axis.reportId == 0 ? unnumbered : numbered) = true;
  for (const HidButtonField& button : profile.buttons)
    (button.reportId == 0 ? unnumbered : numbered) = true;
  if (unnumbered && numbered)
    reader.fail("axes",
                "report_id 0 (a device without numbered reports) cannot be mixed with "
                "numbered reports");

  if (reader.has("force_output"))
    profile.forceOutput = parseForceOutput(root.at("force_output"), source);
  return profile;
}

HidProfile loadHidProfile(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw FileError(name + ": not a readable file");
  if (std::filesystem::file_size(path, error) > (1u << 20))
    throw FileError(name + ": over 1 MiB, too large for a profile");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(name + ": cannot open it");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return parseHidProfile(text, name);
}

std::vector<uint8_t> buildForceReport(const HidForceOutput& output, const Eigen::Vector3d& forceN) {
  std::vector<uint8_t> report(output.byteOffset + output.size * output.axes.size(), 0);
  report[0] = output.reportId;
  const int bits = static_cast<int>(8 * output.size);
  const double max = output.isSigned ? std::ldexp(1.0, bits - 1) - 1 : std::ldexp(1.0, bits) - 1;
  const double min = output.isSigned ? -std::ldexp(1.0, bits - 1) : 0.0;
  for (size_t i = 0; i < output.axes.size(); ++i) {
    const double force = forceN[static_cast<Eigen::Index>(output.axes[i])];
    const double counts = std::isfinite(force)
                              ? std::clamp(std::round(force * output.countsPerNewton), min, max)
                              : 0.0;
    // Two's complement of the rounded count, least significant byte first.
    const auto value = static_cast<uint64_t>(static_cast<int64_t>(counts));
    for (size_t k = 0; k < output.size; ++k)
      report[output.byteOffset + i * output.size + k] = static_cast<uint8_t>(value >> (8 * k));
  }
  return report;
}

}  // namespace sculpt::haptics
