#pragma once
// TTP/1, the vendor protocol of fest's USB turntables (ttp(7), docs/turntable.md §3): every
// command is a control transfer to the device recipient on EP0, little-endian fields.
// This file only turns commands into setup packets and payloads and replies into
// structs; the transport (libusb) lives in its backend.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace fest::capture::ttp1 {

constexpr std::uint8_t kRequestTypeIn = 0xC0;   // device-to-host | vendor | device
constexpr std::uint8_t kRequestTypeOut = 0x40;  // host-to-device | vendor | device
constexpr unsigned kTimeoutMs = 1000;
constexpr std::size_t kInfoSize = 64;
constexpr std::size_t kStatusSize = 16;

enum class Request : std::uint8_t {
  get_info = 0x00,
  get_status = 0x01,
  move_abs = 0x10,
  move_rel = 0x11,
  home = 0x12,
  stop = 0x13,
  set_zero = 0x14,
  set_motion = 0x15,
  enable = 0x16,
  set_aux = 0x20,
  pulse_aux = 0x21,
};

// One control transfer: the 8-byte setup packet fields and, for OUT requests, the data.
struct Transfer {
  std::uint8_t request_type = 0;
  std::uint8_t request = 0;
  std::uint16_t value = 0;
  std::uint16_t index = 0;
  std::uint16_t length = 0;         // wLength: data bytes to send (OUT) or expect (IN)
  std::vector<std::uint8_t> data;   // OUT payload

  // The setup packet as it goes on the wire (and into a usbmon capture).
  std::array<std::uint8_t, 8> setup_packet() const;
};

// Speeds travel in wValue as steps/s / 4 (0 = the device's default); values that do not
// fit are usage errors.
Transfer get_info();
Transfer get_status();
Transfer move_abs(std::int32_t target, std::uint32_t speed_steps_s = 0);
Transfer move_rel(std::int32_t delta, std::uint32_t speed_steps_s = 0);
Transfer home(bool clockwise, std::uint32_t speed_steps_s = 0);
Transfer stop(bool immediate);
Transfer set_zero();
Transfer set_motion(std::uint32_t max_speed, std::uint32_t max_accel);
Transfer enable(bool on);
Transfer set_aux(std::uint16_t mask, std::uint16_t values);
Transfer pulse_aux(std::uint16_t index, std::uint16_t duration_ms);

struct Info {
  std::uint8_t proto_major = 0, proto_minor = 0;
  bool has_home = false, has_encoder = false, has_aux = false;
  std::uint32_t steps_per_rev = 0, max_speed = 0, max_accel = 0;
  std::uint8_t n_aux = 0;
  std::string name;
};

enum class State : std::uint8_t { idle = 0, moving = 1, homing = 2, fault = 3 };

struct Status {
  std::int32_t position = 0, target = 0;
  State state = State::idle;
  bool homed = false, home_switch = false, stalled = false, driver_enabled = false;
  std::uint16_t fault = 0;
  std::uint32_t seq = 0;
};

// Throw fest::Error(device_error) for a reply shorter than the structure ("short reply
// 12/16"), an unknown state, a protocol major version other than 1, a zero
// steps_per_rev.
Info decode_info(const std::vector<std::uint8_t>& reply);
Status decode_status(const std::vector<std::uint8_t>& reply);

// Fault codes of GET_STATUS, for messages: "stall detected", ...
const char* fault_name(std::uint16_t code);

}  // namespace fest::capture::ttp1
