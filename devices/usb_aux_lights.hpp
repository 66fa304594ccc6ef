#pragma once
// Lights on the aux outputs of a TTP/1 turntable controller (man 7 ttp, SET_AUX), e.g.
// LED drivers wired to the same microcontroller that turns the table:
//
//   usb-aux:N[,usb=VID:PID#SERIAL]     aux output N (0..n_aux-1) of the controller,
//                                      default the TTP/1 default usb:1209:0001
//
// The firmware latches its outputs, so a level set here stays after exit; the bank
// still switches its lit lights off when destroyed, unless keep_state_on_release().
// All lights of one bank must be on the same controller.

#include <memory>
#include <string>
#include <vector>

#include "capture/light_bank.hpp"
#include "devices/usb_turntable.hpp"

namespace fest::devices {

struct UsbAuxRef {
  unsigned aux = 0;
  UsbSelector device;
  std::string device_uri = "usb:";  // for comparing banks and messages
};

// usage_error for anything but "usb-aux:N[,usb=...]" with N < 16.
UsbAuxRef parse_usb_aux_uri(const std::string& uri);

struct UsbAuxLightSpec {
  std::string id;
  UsbAuxRef ref;
  bool initial_on = false;
};

class UsbAuxLightBank : public capture::LightBank {
 public:
  // Opens the controller, checks it has the aux outputs named (else device_not_found),
  // and sets every light to its initial level with one SET_AUX.
  explicit UsbAuxLightBank(const std::vector<UsbAuxLightSpec>& lights);
  ~UsbAuxLightBank() override;

  std::vector<capture::LightState> list() override;
  void set(const std::string& id, bool on) override;
  void all_off() override;
  void keep_state_on_release() override { keep_ = true; }

 private:
  struct Light {
    std::string id;
    unsigned aux = 0;
    bool on = false;
  };
  std::unique_ptr<UsbTurntable> controller_;
  std::vector<Light> lights_;
  bool keep_ = false;
};

}  // namespace fest::devices
