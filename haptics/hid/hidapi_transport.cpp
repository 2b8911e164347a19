#include "haptics/hid/hidapi_transport.h"

#include <hidapi/hidapi.h>

#include <cwchar>
#include <mutex>
#include <stdexcept>

namespace sculpt::haptics {
namespace {

// hidapi's strings are wchar_t, UTF-32 on Linux. Code points that are not Unicode scalar values
// become U+FFFD.
std::string toUtf8(const wchar_t* text) {
  std::string out;
  if (text == nullptr) return out;
  for (; *text != L'\0'; ++text) {
    auto code = static_cast<uint32_t>(*text);
    if (code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) code = 0xFFFD;
    if (code < 0x80) {
      out.push_back(static_cast<char>(code));
    } else if (code < 0x800) {
      out.push_back(static_cast<char>(0xC0 | (code >> 6)));
      out.push_back(static_cast<char>(0x80 | (code & 0x3F)));
    } else if (code < 0x10000) {
      out.push_back(static_cast<char>(0xE0 | (code >> 12)));
      out.push_back(static_cast<char>(0x80 | ((code >> 6) & 0x3F)));
      out.push_back(static_cast<char>(0x80 | (code & 0x3F)));
    } else {
      out.push_back(static_cast<char>(0xF0 | (code >> 18)));
      out.push_back(static_cast<char>(0x80 | ((code >> 12) & 0x3F)));
      out.push_back(static_cast<char>(0x80 | ((code >> 6) & 0x3F)));
      out.push_back(static_cast<char>(0x80 | (code & 0x3F)));
    }
  }
  return out;
}

// hid_init and hid_exit are process-wide: the first transport initialises, the last one exits.
std::mutex gLibraryMutex;
int gLibraryUsers = 0;

class HidapiConnection : public HidConnection {
 public:
  explicit HidapiConnection(hid_device* device) : device_(device) {}
  ~HidapiConnection() override { hid_close(device_); }
  HidapiConnection(const HidapiConnection&) = delete;
  HidapiConnection& operator=(const HidapiConnection&) = delete;

  int read(uint8_t* data, size_t size, int timeoutMs) override {
    return hid_read_timeout(device_, data, size, timeoutMs);
  }
  int write(const uint8_t* data, size_t size) override { return hid_write(device_, data, size); }
  int getFeatureReport(uint8_t* data, size_t size) override {
    return hid_get_feature_report(device_, data, size);
  }
  int sendFeatureReport(const uint8_t* data, size_t size) override {
    return hid_send_feature_report(device_, data, size);
  }
  std::string lastError() const override { return toUtf8(hid_error(device_)); }

 private:
  hid_device* device_;
};

}  // namespace

HidapiTransport::HidapiTransport() {
  std::lock_guard<std::mutex> lock(gLibraryMutex);
  if (gLibraryUsers == 0 && hid_init() != 0)
    throw std::runtime_error("hidapi: hid_init failed: " + toUtf8(hid_error(nullptr)));
  ++gLibraryUsers;
}

HidapiTransport::~HidapiTransport() {
  std::lock_guard<std::mutex> lock(gLibraryMutex);
  if (--gLibraryUsers == 0) hid_exit();
}

std::vector<HidDeviceInfo> HidapiTransport::enumerate() {
  std::vector<HidDeviceInfo> devices;
  // A null list is either no devices or a failure; both mean nothing to open now.
  hid_device_info* const list = hid_enumerate(0, 0);
  for (const hid_device_info* entry = list; entry != nullptr; entry = entry->next) {
    if (entry->path == nullptr) continue;
    HidDeviceInfo device;
    device.path = entry->path;
    device.vendorId = entry->vendor_id;
    device.productId = entry->product_id;
    device.manufacturer = toUtf8(entry->manufacturer_string);
    device.product = toUtf8(entry->product_string);
    device.serial = toUtf8(entry->serial_number);
    device.usagePage = entry->usage_page;
    device.usage = entry->usage;
    device.interfaceNumber = entry->interface_number;
    devices.push_back(std::move(device));
  }
  hid_free_enumeration(list);
  return deduplicateByPath(devices);
}

std::unique_ptr<HidConnection> HidapiTransport::open(const std::string& path, std::string* error) {
  hid_device* const device = hid_open_path(path.c_str());
  if (device == nullptr) {
    if (error != nullptr) *error = toUtf8(hid_error(nullptr));
    return nullptr;
  }
  return std::make_unique<HidapiConnection>(device);
}

}  // namespace sculpt::haptics
