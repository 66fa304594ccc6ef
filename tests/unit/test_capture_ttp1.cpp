// TTP/1 codec (ttp(7), docs/capture.md §6): every request against setup packets and
// payloads written out by hand from the protocol table (bmRequestType, bRequest, wValue,
// wIndex, wLength little-endian), replies decoded from hand-made blobs, short replies
// refused with status 6.

#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "capture/ttp1.hpp"
#include "core/error.hpp"

namespace {

using namespace fest::capture::ttp1;
using Bytes = std::vector<std::uint8_t>;
using Packet = std::array<std::uint8_t, 8>;

TEST(CaptureTtp1, InRequests) {
  EXPECT_EQ(get_info().setup_packet(), (Packet{0xC0, 0x00, 0, 0, 0, 0, 64, 0}));
  EXPECT_EQ(get_status().setup_packet(), (Packet{0xC0, 0x01, 0, 0, 0, 0, 16, 0}));
  EXPECT_TRUE(get_status().data.empty());
}

TEST(CaptureTtp1, MoveRequests) {
  // MOVE_ABS to 6400 steps at 2000 steps/s: wValue = 500 = 0x01F4, data = 6400 = 0x1900.
  const Transfer m = move_abs(6400, 2000);
  EXPECT_EQ(m.setup_packet(), (Packet{0x40, 0x10, 0xF4, 0x01, 0, 0, 4, 0}));
  EXPECT_EQ(m.data, (Bytes{0x00, 0x19, 0x00, 0x00}));
  // MOVE_REL by -1 at the default speed: two's complement.
  const Transfer r = move_rel(-1);
  EXPECT_EQ(r.setup_packet(), (Packet{0x40, 0x11, 0, 0, 0, 0, 4, 0}));
  EXPECT_EQ(r.data, (Bytes{0xFF, 0xFF, 0xFF, 0xFF}));
  EXPECT_THROW(move_abs(0, 4u * 65536u), fest::Error);
}

TEST(CaptureTtp1, OtherOutRequests) {
  EXPECT_EQ(home(true, 400).setup_packet(), (Packet{0x40, 0x12, 100, 0, 1, 0, 0, 0}));
  EXPECT_EQ(home(false).setup_packet(), (Packet{0x40, 0x12, 0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(stop(true).setup_packet(), (Packet{0x40, 0x13, 1, 0, 0, 0, 0, 0}));
  EXPECT_EQ(stop(false).setup_packet(), (Packet{0x40, 0x13, 0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(set_zero().setup_packet(), (Packet{0x40, 0x14, 0, 0, 0, 0, 0, 0}));
  const Transfer m = set_motion(2000, 0x00012345);
  EXPECT_EQ(m.setup_packet(), (Packet{0x40, 0x15, 0, 0, 0, 0, 8, 0}));
  EXPECT_EQ(m.data, (Bytes{0xD0, 0x07, 0, 0, 0x45, 0x23, 0x01, 0x00}));
  EXPECT_EQ(enable(true).setup_packet(), (Packet{0x40, 0x16, 1, 0, 0, 0, 0, 0}));
  EXPECT_EQ(set_aux(0x0005, 0x0004).setup_packet(), (Packet{0x40, 0x20, 5, 0, 4, 0, 0, 0}));
  EXPECT_EQ(pulse_aux(2, 300).setup_packet(), (Packet{0x40, 0x21, 2, 0, 0x2C, 0x01, 0, 0}));
}

Bytes info_blob() {
  Bytes b(64, 0);
  b[0] = 1;
  b[1] = 2;
  b[2] = 0x05;                                        // has_home | has_aux
  b[4] = 0x00; b[5] = 0xC8; b[6] = 0x00; b[7] = 0x00;  // 51200 steps/rev
  b[8] = 0xD0; b[9] = 0x07;                           // 2000 steps/s
  b[12] = 0x40; b[13] = 0x1F;                         // 8000 steps/s^2
  b[16] = 3;
  const char* name = "Pico turntable";
  for (int k = 0; name[k]; ++k) b[std::size_t(20 + k)] = std::uint8_t(name[k]);
  return b;
}

TEST(CaptureTtp1, DecodesInfo) {
  const Info i = decode_info(info_blob());
  EXPECT_EQ(i.proto_major, 1);
  EXPECT_EQ(i.proto_minor, 2);
  EXPECT_TRUE(i.has_home);
  EXPECT_FALSE(i.has_encoder);
  EXPECT_TRUE(i.has_aux);
  EXPECT_EQ(i.steps_per_rev, 51200u);
  EXPECT_EQ(i.max_speed, 2000u);
  EXPECT_EQ(i.max_accel, 8000u);
  EXPECT_EQ(i.n_aux, 3);
  EXPECT_EQ(i.name, "Pico turntable");
}

TEST(CaptureTtp1, DecodesStatus) {
  const Bytes b{0xFE, 0xFF, 0xFF, 0xFF,  // position -2
                0x00, 0x19, 0x00, 0x00,  // target 6400
                1,                       // moving
                0x09,                    // homed | driver_enabled
                0x00, 0x00,              // no fault
                0x2A, 0x00, 0x00, 0x00};  // seq 42
  const Status s = decode_status(b);
  EXPECT_EQ(s.position, -2);
  EXPECT_EQ(s.target, 6400);
  EXPECT_EQ(s.state, State::moving);
  EXPECT_TRUE(s.homed);
  EXPECT_FALSE(s.home_switch);
  EXPECT_FALSE(s.stalled);
  EXPECT_TRUE(s.driver_enabled);
  EXPECT_EQ(s.seq, 42u);
  Bytes f = b;
  f[8] = 3;
  f[10] = 2;
  EXPECT_EQ(decode_status(f).fault, 2);
  EXPECT_STREQ(fault_name(2), "home switch not found");
}

fest::Error error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const fest::Error& e) {
    return e;
  }
  return fest::Error(fest::Status::ok, "");
}

TEST(CaptureTtp1, RefusesShortAndMalformedReplies) {
  const fest::Error shortie = error_of([] { decode_status(Bytes(12, 0)); });
  EXPECT_EQ(shortie.status(), fest::Status::device_error);
  EXPECT_NE(std::string(shortie.what()).find("short reply 12/16"), std::string::npos) << shortie.what();
  EXPECT_EQ(error_of([] { decode_info(Bytes(63, 0)); }).status(), fest::Status::device_error);
  Bytes v2 = info_blob();
  v2[0] = 2;
  EXPECT_EQ(error_of([&] { decode_info(v2); }).status(), fest::Status::device_error);
  Bytes zero = info_blob();
  zero[5] = 0;
  EXPECT_EQ(error_of([&] { decode_info(zero); }).status(), fest::Status::device_error);
  Bytes state(16, 0);
  state[8] = 4;
  EXPECT_EQ(error_of([&] { decode_status(state); }).status(), fest::Status::device_error);
}

}  // namespace
