#include "renderer/bvh/embree_device.h"

#include <stdexcept>

namespace raylab {
namespace {

// Embree calls this on the thread that hit the error; the message is kept for the exception.
void keepEmbreeMessage(void* user, RTCError, const char* message) {
  *static_cast<std::string*>(user) = message ? message : "";
}

const char* embreeErrorName(RTCError e) {
  switch (e) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
    default: return "unknown error";
  }
}

}  // namespace

EmbreeDevice::EmbreeDevice() {
  device_ = rtcNewDevice(nullptr);
  if (!device_)
    throw std::runtime_error(std::string("Embree: no device (") + embreeErrorName(rtcGetDeviceError(nullptr)) + ")");
  rtcSetDeviceErrorFunction(device_, keepEmbreeMessage, &message_);
}

EmbreeDevice::~EmbreeDevice() {
  if (device_) rtcReleaseDevice(device_);
}

std::string EmbreeDevice::takeError() {
  RTCError e = rtcGetDeviceError(device_);
  std::string message = std::move(message_);
  message_.clear();
  if (e == RTC_ERROR_NONE) return "";
  return message.empty() ? embreeErrorName(e) : message;
}

void EmbreeDevice::check(const char* what) {
  RTCError e = rtcGetDeviceError(device_);
  std::string message = std::move(message_);
  message_.clear();
  if (e == RTC_ERROR_NONE) return;
  throw std::runtime_error(std::string("Embree: ") + what + ": " + embreeErrorName(e) +
                           (message.empty() ? "" : " (" + message + ")"));
}

}  // namespace raylab
