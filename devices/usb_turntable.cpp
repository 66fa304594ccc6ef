#include "devices/usb_turntable.hpp"

#include <libusb.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <thread>

#include "core/error.hpp"

namespace fest::devices {
namespace ttp1 = capture::ttp1;
namespace {

const char* const kUdevHint =
    "install examples/udev/70-ttp.rules into /etc/udev/rules.d (MODE=\"0660\", GROUP=\"plugdev\"), "
    "run 'udevadm control --reload', replug, and add your user to the plugdev group";

// One libusb error as the design's status; `what` names the step, `where` the device.
[[noreturn]] void throw_usb(int rc, const std::string& what, const std::string& where) {
  switch (rc) {
    case LIBUSB_ERROR_NO_DEVICE:
    case LIBUSB_ERROR_NOT_FOUND:
      throw make_error(Status::device_not_found, "turntable unplugged: {} failed ({})", what, where);
    case LIBUSB_ERROR_TIMEOUT:
      throw make_error(Status::timeout, "turntable did not answer {} within {} ms ({})", what, ttp1::kTimeoutMs, where);
    case LIBUSB_ERROR_ACCESS:
      throw make_error(Status::permission, "permission denied on the turntable: {} ({})", kUdevHint, where);
    case LIBUSB_ERROR_BUSY:
      throw make_error(Status::device_error, "turntable busy: another program has claimed it ({})", where);
    case LIBUSB_ERROR_PIPE:
      throw make_error(Status::device_error, "turntable refused {} (STALL) ({})", what, where);
    default:
      throw make_error(Status::device_error, "{} failed: {} ({})", what, libusb_error_name(rc), where);
  }
}

std::uint16_t hex16(const std::string& text, const std::string& uri) {
  char* end = nullptr;
  const unsigned long v = std::strtoul(text.c_str(), &end, 16);
  if (text.empty() || text.size() > 4 || end != text.c_str() + text.size())
    throw usage_error("usb device URI: '{}' is not a 4-digit hex id (in {})", text, uri);
  return std::uint16_t(v);
}

std::string hex4(unsigned v) {
  static const char* digits = "0123456789abcdef";
  std::string s(4, '0');
  for (int k = 3; k >= 0; --k, v >>= 4) s[std::size_t(k)] = digits[v & 15];
  return s;
}

std::string where_of(const UsbSelector& sel, libusb_device* dev) {
  return fmt::format("usb {}:{} bus {} device {}", hex4(sel.vid), hex4(sel.pid), libusb_get_bus_number(dev),
                     libusb_get_device_address(dev));
}

// String descriptors by explicit GET_DESCRIPTOR requests (not libusb's ascii helper), so
// the exact transfers are part of TTP/1's documented start-up sequence (man 7 ttp):
// LANGID table once, then iProduct and iSerialNumber in its first language, 255 bytes
// asked each time.
int get_descriptor(libusb_device_handle* h, std::uint16_t value, std::uint16_t index, unsigned char* buf) {
  return libusb_control_transfer(h, LIBUSB_ENDPOINT_IN | LIBUSB_REQUEST_TYPE_STANDARD | LIBUSB_RECIPIENT_DEVICE,
                                 LIBUSB_REQUEST_GET_DESCRIPTOR, value, index, buf, 255, ttp1::kTimeoutMs);
}

std::uint16_t read_langid(libusb_device_handle* h, const std::string& where) {
  unsigned char buf[256];
  const int rc = get_descriptor(h, LIBUSB_DT_STRING << 8, 0, buf);
  if (rc < 0) throw_usb(rc, "reading the string language table", where);
  if (rc < 4 || buf[1] != LIBUSB_DT_STRING)
    throw make_error(Status::device_error, "bad string language table ({} bytes) ({})", rc, where);
  return std::uint16_t(buf[2] | (buf[3] << 8));
}

// A string descriptor as ASCII (other characters become '?'); index 0 means none.
std::string read_string(libusb_device_handle* h, std::uint8_t index, std::uint16_t langid, const char* what,
                        const std::string& where) {
  if (index == 0) return {};
  unsigned char buf[256];
  const int rc = get_descriptor(h, std::uint16_t((LIBUSB_DT_STRING << 8) | index), langid, buf);
  if (rc < 0) throw_usb(rc, what, where);
  if (rc < 2 || buf[1] != LIBUSB_DT_STRING) throw make_error(Status::device_error, "{}: not a string descriptor ({})", what, where);
  const int n = std::min(rc, int(buf[0]));
  std::string s;
  for (int k = 2; k + 1 < n; k += 2) s.push_back(buf[k + 1] == 0 && buf[k] < 0x80 ? char(buf[k]) : '?');
  return s;
}

struct Context {
  libusb_context* ctx = nullptr;
  Context() {
    const int rc = libusb_init(&ctx);
    if (rc < 0) throw make_error(Status::device_error, "cannot initialise libusb: {}", libusb_error_name(rc));
  }
  ~Context() {
    if (ctx) libusb_exit(ctx);
  }
};

struct DeviceList {
  libusb_device** devs = nullptr;
  ssize_t n = 0;
  explicit DeviceList(libusb_context* ctx) {
    n = libusb_get_device_list(ctx, &devs);
    if (n < 0) throw make_error(Status::device_error, "cannot list USB devices: {}", libusb_error_name(int(n)));
  }
  ~DeviceList() {
    if (devs) libusb_free_device_list(devs, 1);
  }
};

// One opened candidate: a TTP/1 device with the wanted VID:PID.
struct Candidate {
  libusb_device_handle* handle = nullptr;
  std::string product, serial, where;
  int bus = 0, address = 0;
};

// Opens every device with the selector's VID:PID and reads its strings. Devices that
// cannot be opened are reported through `problems` (status + message of the first).
std::vector<Candidate> scan(libusb_context* ctx, const UsbSelector& sel, std::vector<Error>& problems) {
  std::vector<Candidate> found;
  DeviceList list(ctx);
  for (ssize_t i = 0; i < list.n; ++i) {
    libusb_device* dev = list.devs[i];
    libusb_device_descriptor d{};
    if (libusb_get_device_descriptor(dev, &d) < 0 || d.idVendor != sel.vid || d.idProduct != sel.pid) continue;
    Candidate c;
    c.where = where_of(sel, dev);
    c.bus = libusb_get_bus_number(dev);
    c.address = libusb_get_device_address(dev);
    const int rc = libusb_open(dev, &c.handle);
    try {
      if (rc < 0) throw_usb(rc, "opening the device", c.where);
      const std::uint16_t langid = d.iProduct || d.iSerialNumber ? read_langid(c.handle, c.where) : 0;
      c.product = read_string(c.handle, d.iProduct, langid, "reading iProduct", c.where);
      c.serial = read_string(c.handle, d.iSerialNumber, langid, "reading iSerialNumber", c.where);
    } catch (const Error& e) {
      if (c.handle) libusb_close(c.handle);
      problems.push_back(e);
      continue;
    }
    if (c.product.rfind("TTP/1", 0) != 0) {
      problems.push_back(make_error(Status::device_not_found, "{} is not a TTP/1 device (iProduct '{}')", c.where, c.product));
      libusb_close(c.handle);
      continue;
    }
    found.push_back(c);
  }
  return found;
}

}  // namespace

UsbSelector parse_usb_uri(const std::string& uri) {
  if (uri.rfind("usb:", 0) != 0 && uri != "usb") throw usage_error("not a usb: device URI: {}", uri);
  UsbSelector s;
  std::string rest = uri.size() > 4 ? uri.substr(4) : "";
  const std::size_t hash = rest.find('#');
  if (hash != std::string::npos) {
    s.serial = rest.substr(hash + 1);
    if (s.serial.empty()) throw usage_error("usb device URI: empty serial after '#' (in {})", uri);
    rest = rest.substr(0, hash);
  }
  if (rest.empty()) return s;
  const std::size_t colon = rest.find(':');
  if (colon == std::string::npos) throw usage_error("usb device URI: expected VID:PID in hex, got '{}' (in {})", rest, uri);
  s.vid = hex16(rest.substr(0, colon), uri);
  s.pid = hex16(rest.substr(colon + 1), uri);
  return s;
}

std::vector<UsbTurntableListing> list_usb_turntables(const UsbSelector& sel) {
  Context c;
  std::vector<Error> problems;
  std::vector<UsbTurntableListing> out;
  for (Candidate& k : scan(c.ctx, sel, problems)) {
    UsbTurntableListing l;
    l.uri = fmt::format("usb:{}:{}{}{}", hex4(sel.vid), hex4(sel.pid), k.serial.empty() ? "" : "#", k.serial);
    l.product = k.product;
    l.bus = k.bus;
    l.address = k.address;
    out.push_back(l);
    libusb_close(k.handle);
  }
  for (const Error& e : problems) {
    UsbTurntableListing l;
    l.uri = fmt::format("usb:{}:{}", hex4(sel.vid), hex4(sel.pid));
    l.problem = e.what();
    out.push_back(l);
  }
  return out;
}

struct UsbTurntable::Handle {
  Context context;
  libusb_device_handle* handle = nullptr;
  bool claimed = false;
  ~Handle() {
    if (claimed) libusb_release_interface(handle, 0);
    if (handle) libusb_close(handle);
  }
};

UsbTurntable::UsbTurntable(const UsbSelector& sel, bool claim_interface) : usb_(std::make_unique<Handle>()) {
  std::vector<Error> problems;
  std::vector<Candidate> found = scan(usb_->context.ctx, sel, problems);
  std::vector<std::string> serials;
  for (auto it = found.begin(); it != found.end();) {
    serials.push_back(it->serial);
    if (!sel.serial.empty() && it->serial != sel.serial) {
      libusb_close(it->handle);
      it = found.erase(it);
    } else {
      ++it;
    }
  }
  if (found.size() > 1) {
    for (Candidate& k : found) libusb_close(k.handle);
    throw usage_error("{} TTP/1 turntables at usb {}:{}: choose one with usb:{}:{}#SERIAL (serials: {})", found.size(),
                      hex4(sel.vid), hex4(sel.pid), hex4(sel.vid), hex4(sel.pid), fmt::join(serials, ", "));
  }
  if (found.empty()) {
    // A device that is there but could not be opened says more than "not found".
    for (const Error& e : problems)
      if (e.status() != Status::device_not_found) throw e;
    if (!problems.empty() && sel.serial.empty()) throw problems.front();  // e.g. "not a TTP/1 device"
    if (!sel.serial.empty() && !serials.empty())
      throw make_error(Status::device_not_found, "no TTP/1 turntable with serial '{}' at usb {}:{} (found: {})", sel.serial,
                       hex4(sel.vid), hex4(sel.pid), fmt::join(serials, ", "));
    throw make_error(Status::device_not_found, "no TTP/1 turntable at usb {}:{} (plugged in? 'turntable list' shows what is seen)",
                     hex4(sel.vid), hex4(sel.pid));
  }
  usb_->handle = found[0].handle;
  serial_ = found[0].serial;
  where_ = found[0].where;
  if (claim_interface) {
    const int rc = libusb_claim_interface(usb_->handle, 0);
    if (rc < 0) throw_usb(rc, "claiming interface 0", where_);
    usb_->claimed = true;
  }
  info_ = ttp1::decode_info(request_in(ttp1::get_info(), "GET_INFO"));
}

UsbTurntable::~UsbTurntable() = default;

std::vector<std::uint8_t> UsbTurntable::request_in(const ttp1::Transfer& t, const char* name) {
  std::vector<std::uint8_t> buf(t.length);
  const int rc = libusb_control_transfer(usb_->handle, t.request_type, t.request, t.value, t.index, buf.data(), t.length,
                                         ttp1::kTimeoutMs);
  if (rc < 0) throw_usb(rc, name, where_);
  buf.resize(std::size_t(rc));
  return buf;
}

void UsbTurntable::request_out(const ttp1::Transfer& t, const char* name) {
  std::vector<std::uint8_t> data = t.data;
  const int rc = libusb_control_transfer(usb_->handle, t.request_type, t.request, t.value, t.index, data.data(), t.length,
                                         ttp1::kTimeoutMs);
  if (rc == LIBUSB_ERROR_PIPE) {
    // A refused command: the device says why in GET_STATUS's fault code (TTP/1 rules).
    ttp1::Status s;
    try {
      s = ttp1::decode_status(request_in(ttp1::get_status(), "GET_STATUS"));
    } catch (const Error&) {
      throw_usb(rc, name, where_);
    }
    throw make_error(Status::device_error, "turntable refused {} (STALL): fault {} ({}) ({})", name, s.fault,
                     ttp1::fault_name(s.fault), where_);
  }
  if (rc < 0) throw_usb(rc, name, where_);
  if (rc != t.length)
    throw make_error(Status::device_error, "turntable took {} of {} bytes of {} ({})", rc, t.length, name, where_);
}

capture::TurntableInfo UsbTurntable::info() {
  capture::TurntableInfo i;
  i.steps_per_rev = info_.steps_per_rev;
  i.max_speed = info_.max_speed;
  i.max_accel = info_.max_accel;
  i.has_home = info_.has_home;
  i.name = info_.name;
  i.serial = serial_;
  return i;
}

capture::TurntableStatus UsbTurntable::status() {
  const ttp1::Status r = ttp1::decode_status(request_in(ttp1::get_status(), "GET_STATUS"));
  capture::TurntableStatus s;
  s.position = r.position;
  s.target = r.target;
  s.state = capture::MotionState(int(r.state));  // same order: idle, moving, homing, fault
  s.homed = r.homed;
  s.fault = r.fault;
  s.home_switch = r.home_switch;
  s.stalled = r.stalled;
  s.driver_enabled = r.driver_enabled;
  s.seq = r.seq;
  return s;
}

void UsbTurntable::move_abs(std::int32_t target, std::uint32_t speed) { request_out(ttp1::move_abs(target, speed), "MOVE_ABS"); }
void UsbTurntable::stop(bool immediate) { request_out(ttp1::stop(immediate), "STOP"); }
void UsbTurntable::home(bool clockwise, std::uint32_t speed) { request_out(ttp1::home(clockwise, speed), "HOME"); }
void UsbTurntable::set_zero() { request_out(ttp1::set_zero(), "SET_ZERO"); }
void UsbTurntable::enable(bool on) { request_out(ttp1::enable(on), "ENABLE"); }
void UsbTurntable::set_aux(std::uint16_t mask, std::uint16_t values) { request_out(ttp1::set_aux(mask, values), "SET_AUX"); }
void UsbTurntable::wait_ms(unsigned ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

}  // namespace fest::devices
