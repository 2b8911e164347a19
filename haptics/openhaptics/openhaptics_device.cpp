#include "haptics/openhaptics/openhaptics_device.h"

#include <HD/hd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>
#include <thread>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "util/triple_buffer.h"

namespace sculpt::haptics {
namespace {

constexpr double kMetresPerMillimetre = 1e-3;
/// No force command for this long: the scheduler renders zero until one comes.
constexpr int64_t kForceWatchdogNs = 100'000'000;  // 100 ms

int64_t steadyNanoseconds() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

std::string describe(const HDErrorInfo& error) {
  const char* text = hdGetErrorString(error.errorCode);
  return std::string(text ? text : "unknown error") + " (HD error " +
         std::to_string(static_cast<unsigned long>(error.errorCode)) + ", internal " +
         std::to_string(static_cast<long>(error.internalErrorCode)) + ")";
}

/// The arm's state as the scheduler saw it (device frame, m, m/s).
struct ArmState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  uint32_t buttons = 0;
  bool valid = false;  ///< false until the first tick
};

/// The newest force from the servo (N) and when it was sent (steady clock, ns).
struct ForceCommand {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  int64_t sentAt = 0;
};

/// Recommended damping with the SDK's velocity (CHAI3D's figures; the HD API gives none).
double recommendedDamping(const std::string& model) {
  if (model.find("Omni") != std::string::npos) return 5.0;
  if (model.find("Desktop") != std::string::npos) return 5.0;
  return 4.0;  // Touch and others
}

class OpenHapticsDevice final : public HapticDevice {
 public:
  static std::unique_ptr<OpenHapticsDevice> open(std::string* error);
  ~OpenHapticsDevice() override;
  OpenHapticsDevice(const OpenHapticsDevice&) = delete;
  OpenHapticsDevice& operator=(const OpenHapticsDevice&) = delete;

  const DeviceInfo& info() const override { return info_; }
  DeviceSample read(double now) override;
  void sendForce(const Eigen::Vector3d& force) override;

 private:
  OpenHapticsDevice() = default;
  static HDCallbackCode HDCALLBACK onSchedulerTick(void* self);
  HDCallbackCode schedulerTick();
  bool readInfo(std::string* error);

  HHD handle_ = HD_INVALID_HANDLE;
  HDSchedulerHandle callback_ = 0;
  bool scheduled_ = false, schedulerStarted_ = false;
  DeviceInfo info_;

  TripleBuffer<ArmState> state_;      // HD scheduler thread -> servo thread
  TripleBuffer<ForceCommand> force_;  // servo thread -> HD scheduler thread
  std::atomic<bool> failed_{false};   // the scheduler saw a device error and stopped its callback
  std::atomic<bool> stopping_{false};
  std::atomic<bool> zeroRendered_{false};  // a zero force went out after stopping_
};

bool OpenHapticsDevice::readInfo(std::string* error) {
  HDdouble maxForce = 0, maxStiffness = 0;
  HDdouble workspace[6] = {0, 0, 0, 0, 0, 0};  // mm: min x, y, z, max x, y, z
  hdGetDoublev(HD_NOMINAL_MAX_CONTINUOUS_FORCE, &maxForce);
  hdGetDoublev(HD_NOMINAL_MAX_STIFFNESS, &maxStiffness);  // N/mm
  hdGetDoublev(HD_USABLE_WORKSPACE_DIMENSIONS, workspace);
  const char* model = hdGetString(HD_DEVICE_MODEL_TYPE);
  const char* vendor = hdGetString(HD_DEVICE_VENDOR);
  const HDErrorInfo status = hdGetError();
  if (HD_DEVICE_ERROR(status)) {
    if (error)
      *error = std::string("cannot read the OpenHaptics device's limits: ") + describe(status);
    return false;
  }
  info_.model = model ? model : "OpenHaptics device";
  info_.manufacturer = vendor ? vendor : "3D Systems";
  // An arm that reports no sensible limit gets the family's smallest (the Touch's).
  info_.maxForce = maxForce > 0 ? static_cast<double>(maxForce) : 3.3;
  info_.stableStiffness =
      maxStiffness > 0 ? static_cast<double>(maxStiffness) / kMetresPerMillimetre : 400.0;
  info_.damping = recommendedDamping(info_.model);
  double smallestHalfExtent = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const double half = 0.5 * static_cast<double>(workspace[axis + 3] - workspace[axis]);
    smallestHalfExtent = axis == 0 ? half : std::min(smallestHalfExtent, half);
  }
  info_.workspaceRadius =
      smallestHalfExtent > 0 ? smallestHalfExtent * kMetresPerMillimetre : 0.075;
  info_.capabilities = kSensesPosition | kSensesRotation | kSensesButtons | kActuatesForce;
  return true;
}

std::unique_ptr<OpenHapticsDevice> OpenHapticsDevice::open(std::string* error) {
  std::unique_ptr<OpenHapticsDevice> device(new OpenHapticsDevice());
  const HHD handle = hdInitDevice(HD_DEFAULT_DEVICE);
  const HDErrorInfo initStatus = hdGetError();
  if (HD_DEVICE_ERROR(initStatus)) {
    if (error)
      *error = std::string("cannot open the default OpenHaptics device: ") + describe(initStatus);
    return nullptr;
  }
  device->handle_ = handle;
  hdMakeCurrentDevice(handle);
  if (!device->readInfo(error)) return nullptr;  // the destructor closes the device

  hdEnable(HD_FORCE_OUTPUT);
  device->callback_ = hdScheduleAsynchronous(&OpenHapticsDevice::onSchedulerTick, device.get(),
                                             HD_MAX_SCHEDULER_PRIORITY);
  device->scheduled_ = true;
  hdStartScheduler();
  const HDErrorInfo startStatus = hdGetError();
  if (HD_DEVICE_ERROR(startStatus)) {
    if (error)
      *error = std::string("cannot start the OpenHaptics scheduler: ") + describe(startStatus);
    return nullptr;
  }
  device->schedulerStarted_ = true;
  return device;
}

OpenHapticsDevice::~OpenHapticsDevice() {
  if (schedulerStarted_) {
    // Let the callback put out a zero force before the scheduler stops (at most ~100 ms).
    stopping_.store(true, std::memory_order_release);
    for (int wait = 0; wait < 100 && !zeroRendered_.load(std::memory_order_acquire) &&
                       !failed_.load(std::memory_order_acquire);
         ++wait)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    hdStopScheduler();
  }
  if (scheduled_) hdUnschedule(callback_);
  if (handle_ != HD_INVALID_HANDLE) hdDisableDevice(handle_);
}

HDCallbackCode HDCALLBACK OpenHapticsDevice::onSchedulerTick(void* self) {
  return static_cast<OpenHapticsDevice*>(self)->schedulerTick();
}

HDCallbackCode OpenHapticsDevice::schedulerTick() {
  const bool stopping = stopping_.load(std::memory_order_acquire);
  HDdouble position[3] = {0, 0, 0}, velocity[3] = {0, 0, 0};
  HDdouble transform[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  HDint buttons = 0;

  hdBeginFrame(handle_);
  hdGetDoublev(HD_CURRENT_POSITION, position);    // mm
  hdGetDoublev(HD_CURRENT_VELOCITY, velocity);    // mm/s
  hdGetDoublev(HD_CURRENT_TRANSFORM, transform);  // column-major 4x4, translation in mm
  hdGetIntegerv(HD_CURRENT_BUTTONS, &buttons);

  const ForceCommand& command = force_.read();
  Eigen::Vector3d force = command.force;
  const bool fresh = steadyNanoseconds() - command.sentAt <= kForceWatchdogNs;
  if (stopping || !fresh || !force.allFinite()) {
    force.setZero();
  } else if (force.norm() > info_.maxForce) {
    force *= info_.maxForce / force.norm();
  }
  const HDdouble rendered[3] = {force.x(), force.y(), force.z()};
  hdSetDoublev(HD_CURRENT_FORCE, rendered);  // N
  hdEndFrame(handle_);

  const HDErrorInfo status = hdGetError();
  if (HD_DEVICE_ERROR(status)) {
    failed_.store(true, std::memory_order_release);
    return HD_CALLBACK_DONE;  // the servo sees connected = false and zeroes its force
  }

  ArmState state;
  state.position = Eigen::Vector3d(position[0], position[1], position[2]) * kMetresPerMillimetre;
  state.velocity = Eigen::Vector3d(velocity[0], velocity[1], velocity[2]) * kMetresPerMillimetre;
  const Eigen::Map<const Eigen::Matrix4d> pose(transform);  // column-major, as Eigen's default
  state.orientation = Eigen::Quaterniond(Eigen::Matrix3d(pose.topLeftCorner<3, 3>())).normalized();
  state.buttons = static_cast<uint32_t>(buttons);
  state.valid = true;
  state_.publish(state);
  if (stopping) zeroRendered_.store(true, std::memory_order_release);
  return HD_CALLBACK_CONTINUE;
}

DeviceSample OpenHapticsDevice::read(double now) {
  const ArmState& state = state_.read();
  DeviceSample sample;
  sample.time = now;
  sample.position = state.position;
  sample.orientation = state.orientation;
  sample.velocity = state.velocity;
  sample.buttons = state.buttons;
  sample.connected = state.valid && !failed_.load(std::memory_order_acquire);
  return sample;
}

void OpenHapticsDevice::sendForce(const Eigen::Vector3d& force) {
  force_.publish({force, steadyNanoseconds()});
}

}  // namespace

std::unique_ptr<HapticDevice> openOpenHapticsDevice(std::string* error) {
  return OpenHapticsDevice::open(error);
}

}  // namespace sculpt::haptics
