#pragma once
// The USB turntable backend: a TTP/1 controller (docs/turntable.md §3, ttp(7)) spoken
// to through libusb-1.0 with vendor control transfers on EP0.
//
//   usb:[VID:PID][#SERIAL]      default 1209:0001; iProduct must start with "TTP/1";
//                               #SERIAL selects one of several tables
//
// libusb errors become the device exit statuses: device gone -> 5, STALL -> 6 with the fault
// code read back by GET_STATUS, transfer timeout (1000 ms) -> 7, access denied -> 8 with
// the udev rule that fixes it.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "capture/ttp1.hpp"
#include "capture/turntable.hpp"

namespace fest::devices {

struct UsbSelector {
  std::uint16_t vid = 0x1209, pid = 0x0001;
  std::string serial;  // empty = the only matching device
};

// Parses "usb:", "usb:1209:0001", "usb:#SN", "usb:1209:0001#SN"; usage_error otherwise.
UsbSelector parse_usb_uri(const std::string& uri);

struct UsbTurntableListing {
  std::string uri;       // usb:VID:PID#SERIAL, ready for --device
  std::string product;   // iProduct
  int bus = 0, address = 0;
  std::string problem;   // empty, or why it could not be opened (e.g. permission)
};

// Every TTP/1 device with the selector's VID:PID (the serial is ignored).
std::vector<UsbTurntableListing> list_usb_turntables(const UsbSelector& sel);

class UsbTurntable : public capture::Turntable {
 public:
  // Opens the device, checks iProduct and reads GET_INFO (cached for info()). Without
  // claim_interface the handle only sends control requests to the device recipient,
  // which needs no claim, so a light bank on the aux outputs can share the controller
  // with the process's turntable handle.
  explicit UsbTurntable(const UsbSelector& sel, bool claim_interface = true);
  ~UsbTurntable() override;
  UsbTurntable(const UsbTurntable&) = delete;
  UsbTurntable& operator=(const UsbTurntable&) = delete;

  capture::TurntableInfo info() override;
  capture::TurntableStatus status() override;
  void move_abs(std::int32_t target, std::uint32_t speed_steps_s) override;
  void stop(bool immediate) override;
  void wait_ms(unsigned ms) override;
  void home(bool clockwise, std::uint32_t speed_steps_s) override;
  void set_zero() override;
  void enable(bool on) override;

  const capture::ttp1::Info& ttp_info() const { return info_; }
  // SET_AUX: the aux outputs in `mask` take the bits of `values`.
  void set_aux(std::uint16_t mask, std::uint16_t values);

 private:
  struct Handle;
  std::vector<std::uint8_t> request_in(const capture::ttp1::Transfer& t, const char* name);
  void request_out(const capture::ttp1::Transfer& t, const char* name);
  std::unique_ptr<Handle> usb_;
  capture::ttp1::Info info_;
  std::string serial_, where_;
};

}  // namespace fest::devices
