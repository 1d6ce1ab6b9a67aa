// An Embree device owned by one object (released on every way out), and Embree's errors as exceptions: the
// builder and the CPU hit reference both need one.
#pragma once

#include <string>

#include "renderer/bvh/embree_api.h"

namespace raylab {

class EmbreeDevice {
 public:
  EmbreeDevice();  // throws std::runtime_error when Embree cannot make a device
  ~EmbreeDevice();
  EmbreeDevice(const EmbreeDevice&) = delete;
  EmbreeDevice& operator=(const EmbreeDevice&) = delete;

  RTCDevice get() const { return device_; }
  // Throws std::runtime_error naming `what` and Embree's last error, if there is one; either way the error
  // is cleared (Embree clears its code when read, this clears the message).
  void check(const char* what);
  // Reads and clears the last error: its message (or its name when Embree gave none), empty if none.
  std::string takeError();
  // The message of the last error Embree reported through its callback (empty if none since check).
  const std::string& lastMessage() const { return message_; }

 private:
  RTCDevice device_ = nullptr;
  std::string message_;
};

}  // namespace raylab
