#include "capture/ttp1.hpp"

#include "core/error.hpp"

namespace fest::capture::ttp1 {
namespace {

void put_u16(std::uint8_t* at, std::uint16_t v) {
  at[0] = std::uint8_t(v & 0xFF);
  at[1] = std::uint8_t(v >> 8);
}
void put_u32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out.push_back(std::uint8_t((v >> (8 * k)) & 0xFF));
}
std::uint16_t get_u16(const std::vector<std::uint8_t>& b, std::size_t at) {
  return std::uint16_t(b[at] | (b[at + 1] << 8));
}
std::uint32_t get_u32(const std::vector<std::uint8_t>& b, std::size_t at) {
  return std::uint32_t(b[at]) | (std::uint32_t(b[at + 1]) << 8) | (std::uint32_t(b[at + 2]) << 16) |
         (std::uint32_t(b[at + 3]) << 24);
}

std::uint16_t speed_field(std::uint32_t steps_s) {
  if (steps_s / 4 > 0xFFFF) throw usage_error("TTP/1: speed {} steps/s exceeds the protocol's {}", steps_s, 0xFFFF * 4);
  return std::uint16_t(steps_s / 4);
}

Transfer out(Request r, std::uint16_t value, std::uint16_t index, std::vector<std::uint8_t> data = {}) {
  Transfer t;
  t.request_type = kRequestTypeOut;
  t.request = std::uint8_t(r);
  t.value = value;
  t.index = index;
  t.length = std::uint16_t(data.size());
  t.data = std::move(data);
  return t;
}

Transfer in(Request r, std::uint16_t length) {
  Transfer t;
  t.request_type = kRequestTypeIn;
  t.request = std::uint8_t(r);
  t.length = length;
  return t;
}

std::vector<std::uint8_t> i32_payload(std::int32_t v) {
  std::vector<std::uint8_t> d;
  put_u32(d, std::uint32_t(v));
  return d;
}

void need(const std::vector<std::uint8_t>& reply, std::size_t size, const char* what) {
  if (reply.size() < size) throw make_error(fest::Status::device_error, "TTP/1 {}: short reply {}/{}", what, reply.size(), size);
}

}  // namespace

std::array<std::uint8_t, 8> Transfer::setup_packet() const {
  std::array<std::uint8_t, 8> s{};
  s[0] = request_type;
  s[1] = request;
  put_u16(&s[2], value);
  put_u16(&s[4], index);
  put_u16(&s[6], length);
  return s;
}

Transfer get_info() { return in(Request::get_info, kInfoSize); }
Transfer get_status() { return in(Request::get_status, kStatusSize); }
Transfer move_abs(std::int32_t target, std::uint32_t speed) {
  return out(Request::move_abs, speed_field(speed), 0, i32_payload(target));
}
Transfer move_rel(std::int32_t delta, std::uint32_t speed) {
  return out(Request::move_rel, speed_field(speed), 0, i32_payload(delta));
}
Transfer home(bool clockwise, std::uint32_t speed) { return out(Request::home, speed_field(speed), clockwise ? 1 : 0); }
Transfer stop(bool immediate) { return out(Request::stop, immediate ? 1 : 0, 0); }
Transfer set_zero() { return out(Request::set_zero, 0, 0); }
Transfer set_motion(std::uint32_t max_speed, std::uint32_t max_accel) {
  std::vector<std::uint8_t> d;
  put_u32(d, max_speed);
  put_u32(d, max_accel);
  return out(Request::set_motion, 0, 0, std::move(d));
}
Transfer enable(bool on) { return out(Request::enable, on ? 1 : 0, 0); }
Transfer set_aux(std::uint16_t mask, std::uint16_t values) { return out(Request::set_aux, mask, values); }
Transfer pulse_aux(std::uint16_t index, std::uint16_t duration_ms) { return out(Request::pulse_aux, index, duration_ms); }

Info decode_info(const std::vector<std::uint8_t>& b) {
  need(b, kInfoSize, "GET_INFO");
  Info i;
  i.proto_major = b[0];
  i.proto_minor = b[1];
  if (i.proto_major != 1)
    throw make_error(fest::Status::device_error, "TTP/1 GET_INFO: protocol version {}.{}, this host speaks 1.x", b[0], b[1]);
  const std::uint16_t flags = get_u16(b, 2);
  i.has_home = flags & 1;
  i.has_encoder = flags & 2;
  i.has_aux = flags & 4;
  i.steps_per_rev = get_u32(b, 4);
  i.max_speed = get_u32(b, 8);
  i.max_accel = get_u32(b, 12);
  i.n_aux = b[16];
  if (i.steps_per_rev == 0) throw make_error(fest::Status::device_error, "TTP/1 GET_INFO: steps_per_rev is 0");
  for (std::size_t k = 20; k < 52 && b[k] != 0; ++k) i.name.push_back(char(b[k]));
  return i;
}

Status decode_status(const std::vector<std::uint8_t>& b) {
  need(b, kStatusSize, "GET_STATUS");
  Status s;
  s.position = std::int32_t(get_u32(b, 0));
  s.target = std::int32_t(get_u32(b, 4));
  if (b[8] > 3) throw make_error(fest::Status::device_error, "TTP/1 GET_STATUS: unknown state {}", b[8]);
  s.state = State(b[8]);
  s.homed = b[9] & 1;
  s.home_switch = b[9] & 2;
  s.stalled = b[9] & 4;
  s.driver_enabled = b[9] & 8;
  s.fault = get_u16(b, 10);
  s.seq = get_u32(b, 12);
  return s;
}

const char* fault_name(std::uint16_t code) {
  switch (code) {
    case 0: return "no fault";
    case 1: return "stall detected";
    case 2: return "home switch not found";
    case 3: return "driver over-temperature";
    case 4: return "e-stop input";
    case 5: return "bad argument";
    default: return "unknown fault";
  }
}

}  // namespace fest::capture::ttp1
