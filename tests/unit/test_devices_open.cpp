// devices/open_devices and the URI parsers of the real backends, on the paths that need
// no hardware: sim: turntables and lights through the same factory `capture run` uses,
// the mixed-kinds rule, usb:/gpio: URI syntax, and the Turntable additions (home,
// set_zero, enable) on the simulator.

#include <functional>

#include <gtest/gtest.h>

#include "capture/sim_lights.hpp"
#include "capture/sim_turntable.hpp"
#include "core/error.hpp"
#include "devices/gpio_lights.hpp"
#include "devices/gpio_stepper.hpp"
#include "devices/open_devices.hpp"
#include "devices/usb_aux_lights.hpp"
#include "devices/usb_turntable.hpp"

namespace {

using namespace fest;
using namespace fest::devices;

Status status_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.status();
  }
  return Status::ok;
}

TEST(DevicesOpen, SimTurntableThroughTheFactory) {
  auto t = open_turntable("sim:steps=3200,speed=90");
  EXPECT_EQ(t->info().steps_per_rev, 3200u);
  EXPECT_EQ(t->info().max_speed, 800u);  // 90 deg/s = 1/4 rev/s
  const capture::MoveResult r = capture::move_to_angle(*t, 45.0);
  EXPECT_EQ(r.steps, 400);
  EXPECT_EQ(t->status().position, 400);
}

TEST(DevicesOpen, SimTurntableZeroHomeEnable) {
  capture::SimTurntable t(capture::parse_sim_turntable_uri("sim:steps=360"));
  capture::move_to_angle(t, 90.0);
  t.set_zero();
  EXPECT_EQ(t.status().position, 0);  // 90 deg is now step 0
  capture::move_to_angle(t, 10.0);
  EXPECT_EQ(t.status().position, 10);
  t.home(false, 0);
  for (int k = 0; k < 100 && t.status().state != capture::MotionState::idle; ++k) t.wait_ms(20);
  EXPECT_EQ(t.status().position, 0);
  EXPECT_TRUE(t.status().home_switch);
  t.enable(false);
  EXPECT_FALSE(t.status().driver_enabled);
}

TEST(DevicesOpen, TurntableSchemes) {
  EXPECT_EQ(status_of([] { open_turntable("grbl:/dev/ttyACM0"); }), Status::usage);
  EXPECT_EQ(status_of([] { open_turntable("nonsense"); }), Status::usage);
  EXPECT_EQ(status_of([] { open_turntable("sim:warp=2"); }), Status::usage);
}

TEST(DevicesOpen, SimLightsStartOffAndHonourInitiallyOn) {
  auto bank = open_lights({{"L0", "sim:", false}, {"BG", "sim:", false}}, {"BG"});
  const auto l = bank->list();
  ASSERT_EQ(l.size(), 2u);
  EXPECT_EQ(l[0].id, "L0");
  EXPECT_FALSE(l[0].on);
  EXPECT_TRUE(l[1].on);
  bank->only("L0");
  EXPECT_TRUE(bank->list()[0].on);
  EXPECT_FALSE(bank->list()[1].on);
  auto* sim = dynamic_cast<capture::SimLightBank*>(bank.get());
  ASSERT_NE(sim, nullptr);  // capture's tests read its timeline
  ASSERT_EQ(sim->timeline().size(), 3u);  // BG on, BG off, L0 on
}

TEST(DevicesOpen, LightKindsMustNotMix) {
  EXPECT_EQ(status_of([] { open_lights({{"A", "sim:", false}, {"B", "gpio:line=3", false}}); }), Status::usage);
  EXPECT_EQ(status_of([] { open_lights({}); }), Status::usage);
  EXPECT_EQ(status_of([] { open_lights({{"A", "exec:lampctl", false}}); }), Status::usage);
  EXPECT_EQ(status_of([] { open_lights({{"A", "usb-aux:1", false}, {"B", "sim:", false}}); }), Status::usage);
  EXPECT_EQ(status_of([] { open_lights({{"A", "usb-aux:1", false}, {"B", "usb-aux:1", false}}); }), Status::usage);
  EXPECT_EQ(status_of([] { open_lights({{"A", "usb-aux:1", true}}); }), Status::usage);  // active_low: meaningless
  EXPECT_EQ(status_of([] { open_lights({{"A", "sim:", false}}, {"Z"}); }), Status::usage);
  EXPECT_EQ(status_of([] { open_lights({{"A", "sim:x=1", false}}); }), Status::usage);
}

TEST(DevicesOpen, MissingGpioChipIsDeviceNotFound) {
  // No /dev/gpiochip97 on any test machine: the real backend's ENOENT path.
  EXPECT_EQ(status_of([] { open_lights({{"A", "gpio:chip=gpiochip97,line=1", false}}); }), Status::device_not_found);
}

TEST(DevicesUri, Usb) {
  UsbSelector s = parse_usb_uri("usb:");
  EXPECT_EQ(s.vid, 0x1209);
  EXPECT_EQ(s.pid, 0x0001);
  EXPECT_TRUE(s.serial.empty());
  s = parse_usb_uri("usb:16c0:05dc#TT-7");
  EXPECT_EQ(s.vid, 0x16c0);
  EXPECT_EQ(s.pid, 0x05dc);
  EXPECT_EQ(s.serial, "TT-7");
  s = parse_usb_uri("usb:#SN1");
  EXPECT_EQ(s.vid, 0x1209);
  EXPECT_EQ(s.serial, "SN1");
  for (const char* bad : {"usb:1209", "usb:12g9:0001", "usb:12090:1", "usb:1209:0001#", "sim:"})
    EXPECT_EQ(status_of([&] { parse_usb_uri(bad); }), Status::usage) << bad;
}

TEST(DevicesUri, GpioStepper) {
  const GpioStepperConfig c =
      parse_gpio_stepper_uri("gpio-stepper:chip=gpiochip1,step=17,dir=GPIO27,en=22,home=23,steps=51200,speed=1500,accel=900,home_active_low");
  EXPECT_EQ(c.chip, "gpiochip1");
  EXPECT_EQ(c.step, "17");
  EXPECT_EQ(c.dir, "GPIO27");
  EXPECT_EQ(c.en, "22");
  EXPECT_EQ(c.home, "23");
  EXPECT_EQ(c.steps_per_rev, 51200u);
  EXPECT_EQ(c.max_speed, 1500u);
  EXPECT_EQ(c.max_accel, 900u);
  EXPECT_TRUE(c.home_active_low);
  EXPECT_FALSE(c.en_active_high);
  for (const char* bad : {"gpio-stepper:step=1", "gpio-stepper:dir=1", "gpio-stepper:step=1,dir=2,steps=-4",
                          "gpio-stepper:step=1,dir=2,speed=fast", "gpio-stepper:step=1,dir=2,x=1", "gpio-stepper:step=1,dir=2,invert"})
    EXPECT_EQ(status_of([&] { parse_gpio_stepper_uri(bad); }), Status::usage) << bad;
  // No such chip on a test machine: the backend's ENOENT path through the factory.
  EXPECT_EQ(status_of([] { open_turntable("gpio-stepper:chip=gpiochip97,step=1,dir=2"); }), Status::device_not_found);
}

TEST(DevicesUri, UsbAux) {
  UsbAuxRef r = parse_usb_aux_uri("usb-aux:3");
  EXPECT_EQ(r.aux, 3u);
  EXPECT_EQ(r.device.vid, 0x1209);
  r = parse_usb_aux_uri("usb-aux:15,usb=16c0:05dc#D1");
  EXPECT_EQ(r.aux, 15u);
  EXPECT_EQ(r.device.pid, 0x05dc);
  EXPECT_EQ(r.device.serial, "D1");
  for (const char* bad : {"usb-aux:", "usb-aux:16", "usb-aux:x", "usb-aux:1,dev=1", "usb-aux:1,usb=1209"})
    EXPECT_EQ(status_of([&] { parse_usb_aux_uri(bad); }), Status::usage) << bad;
}

TEST(DevicesUri, Gpio) {
  GpioLineRef r = parse_gpio_uri("gpio:chip=gpiochip0,line=GPIO17");
  EXPECT_EQ(r.chip, "gpiochip0");
  EXPECT_EQ(r.line, "GPIO17");
  EXPECT_FALSE(r.active_low);
  r = parse_gpio_uri("gpio:line=17,active_low");
  EXPECT_EQ(r.chip, "gpiochip0");
  EXPECT_EQ(r.line, "17");
  EXPECT_TRUE(r.active_low);
  EXPECT_TRUE(parse_gpio_uri("gpio:line=4,active_low=true").active_low);
  EXPECT_FALSE(parse_gpio_uri("gpio:line=4,active_low=0").active_low);
  for (const char* bad : {"gpio:chip=gpiochip0", "gpio:line=", "gpio:line=3,pull=up", "gpio:line=3,active_low=maybe", "sim:"})
    EXPECT_EQ(status_of([&] { parse_gpio_uri(bad); }), Status::usage) << bad;
}

}  // namespace
