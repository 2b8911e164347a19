#pragma once
// PHANTOM-class arms (3D Systems Touch, Phantom Omni, Desktop) through the vendor's OpenHaptics
// HD API. The HD scheduler runs its own 1 kHz thread; a callback at its highest priority stores
// the arm's newest state and renders the newest force the servo sent, both through triple
// buffers, so read() and sendForce() never block. The callback also guards the arm by itself:
// it clamps to the arm's maximum force, renders zero for a non-finite force and when no force
// has arrived for 100 ms (a stopped servo must not leave a force on the hand).
//
// Built only where the SDK (HD/hd.h, libHD) is found: haptics/CMakeLists.txt then compiles this
// folder and defines SCULPT_HAS_OPENHAPTICS=1. It is untested without hardware: the build
// machines have neither the SDK nor an arm, so only its syntax has been checked, against
// declarations of the HD functions it calls.

#include <memory>
#include <string>

#include "haptics/device/haptic_device.h"

namespace sculpt::haptics {

/// Opens the default OpenHaptics device (HD_DEFAULT_DEVICE), enables force output and starts
/// the HD scheduler. Returns null (and, when `error` is given, a sentence saying why) when there
/// is no device or the SDK fails. Defined only where SCULPT_HAS_OPENHAPTICS is 1: guard calls
/// with `#if SCULPT_HAS_OPENHAPTICS`.
std::unique_ptr<HapticDevice> openOpenHapticsDevice(std::string* error);

}  // namespace sculpt::haptics
