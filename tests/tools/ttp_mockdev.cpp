// ttp_mockdev: writes a replayable TTP/1 turntable for umockdev (docs/turntable.md §4):
// PREFIX.umockdev (the sysfs description of a full-speed USB device 1209:0001 with one
// vendor interface) and PREFIX.pcap (usbmon records, DLT_USB_LINUX_MMAPPED, of the
// control transfers the host is expected to make, in order, with the device's answers).
// The TTP/1 requests are encoded by lib/capture/ttp1, the code under test's own codec,
// while the replies are laid out here byte by byte from the protocol table, so a codec
// mistake in a reply field shows up as a mismatch.
//
//   ttp_mockdev PREFIX [--vid 1209 --pid 0001 --product "TTP/1 ..." --serial SN] EXCHANGE...
//
// EXCHANGE (one control transfer each; the string-descriptor reads of device opening
// come first automatically unless --no-open):
//   info:steps=N,speed=N,accel=N,home=0|1,name=TEXT       GET_INFO and its 64-byte reply
//   status:pos=N,target=N,state=idle|moving|homing|fault,homed=0|1,switch=0|1,
//          stalled=0|1,enabled=0|1,fault=N,seq=N           GET_STATUS and its reply
//   move_abs:TARGET[,speed=STEPS_S]  move_rel:DELTA[,speed=]  home[:cw][,speed=]
//   stop[:now]  zero  enable:0|1  set_aux:mask=M,values=V
//   (info also takes aux=N: has_aux with N outputs)
// suffixes (comma-separated, on any exchange):
//   !stall     the device answers with a STALL (completion status -32, EPIPE)
//   !gone      the device is unplugged (completion status -19, ENODEV; 'C' record only)
//   !short=N   an IN reply cut to N bytes
// The sysfs path to give umockdev-run --pcap is printed on standard output.

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "capture/ttp1.hpp"

namespace {

namespace ttp1 = fest::capture::ttp1;
using Bytes = std::vector<std::uint8_t>;

const char* const kSysfs = "/devices/pci0000:00/0000:00:14.0/usb1/1-1";
const int kBus = 1, kDev = 2;

void le(Bytes& b, std::uint64_t v, int n) {
  for (int k = 0; k < n; ++k) b.push_back(std::uint8_t((v >> (8 * k)) & 0xFF));
}

std::string hex(const Bytes& b) {
  static const char* d = "0123456789ABCDEF";
  std::string s;
  for (std::uint8_t c : b) {
    s += d[c >> 4];
    s += d[c & 15];
  }
  return s;
}

// One expected control transfer and the device's answer.
struct Exchange {
  std::array<std::uint8_t, 8> setup{};
  bool in = false;
  Bytes out_data;  // OUT: what the host must send
  Bytes reply;     // IN: what the device answers
  int status = 0;  // completion status (0, -32 stall, -19 gone)
};

struct Pcap {
  Bytes bytes;
  std::uint64_t urb = 0xffff88810000a000ULL;
  std::uint32_t usec = 0;

  Pcap() {
    le(bytes, 0xa1b2c3d4, 4);
    le(bytes, 2, 2);
    le(bytes, 4, 2);
    le(bytes, 0, 4);
    le(bytes, 0, 4);
    le(bytes, 65535, 4);
    le(bytes, 220, 4);  // LINKTYPE_USB_LINUX_MMAPPED
  }

  // The 64-byte usbmon header (struct usbmon_packet of Documentation/usb/usbmon) + data.
  void record(char event, std::uint8_t ep, const std::array<std::uint8_t, 8>* setup, std::uint32_t urb_len,
              const Bytes& data, int status) {
    Bytes p;
    le(p, urb, 8);
    p.push_back(std::uint8_t(event));
    p.push_back(2);  // control transfer
    p.push_back(ep);
    p.push_back(std::uint8_t(kDev));
    le(p, kBus, 2);
    p.push_back(setup ? 0 : '-');
    p.push_back(!data.empty() ? 0 : (event == 'S' ? '<' : '>'));
    le(p, 0, 8);  // ts_sec
    usec += 1000;
    le(p, usec, 4);
    le(p, std::uint32_t(status), 4);
    le(p, urb_len, 4);
    le(p, data.size(), 4);
    for (int k = 0; k < 8; ++k) p.push_back(setup ? (*setup)[std::size_t(k)] : 0);
    le(p, 0, 4);  // interval
    le(p, 0, 4);  // start_frame
    le(p, 0, 4);  // xfer_flags
    le(p, 0, 4);  // ndesc
    p.insert(p.end(), data.begin(), data.end());
    le(bytes, 0, 4);
    le(bytes, usec, 4);
    le(bytes, p.size(), 4);
    le(bytes, p.size(), 4);
    bytes.insert(bytes.end(), p.begin(), p.end());
  }

  void add(const Exchange& x) {
    ++urb;
    const std::uint16_t wlength = std::uint16_t(x.setup[6] | (x.setup[7] << 8));
    const std::uint8_t ep = x.in ? 0x80 : 0x00;
    record('S', ep, &x.setup, wlength, x.in ? Bytes{} : x.out_data, -115);  // -EINPROGRESS
    if (x.status != 0) {
      record('C', ep, nullptr, 0, {}, x.status);
    } else {
      record('C', ep, nullptr, x.in ? std::uint32_t(x.reply.size()) : wlength, x.in ? x.reply : Bytes{}, 0);
    }
  }
};

Exchange from_transfer(const ttp1::Transfer& t) {
  Exchange x;
  x.setup = t.setup_packet();
  x.in = (t.request_type & 0x80) != 0;
  x.out_data = t.data;
  return x;
}

Exchange get_descriptor(std::uint16_t value, std::uint16_t index, Bytes reply) {
  Exchange x;
  x.setup = {0x80, 6, std::uint8_t(value & 0xFF), std::uint8_t(value >> 8), std::uint8_t(index & 0xFF),
             std::uint8_t(index >> 8), 255, 0};
  x.in = true;
  x.reply = std::move(reply);
  return x;
}

Bytes string_descriptor(const std::string& s) {
  Bytes b{std::uint8_t(2 + 2 * s.size()), 3};
  for (char c : s) le(b, std::uint8_t(c), 2);
  return b;
}

std::map<std::string, std::string> options(const std::string& text, std::string& head) {
  std::map<std::string, std::string> m;
  std::size_t at = 0;
  bool first = true;
  while (at <= text.size()) {
    const std::size_t comma = text.find(',', at);
    const std::string item = text.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    at = comma == std::string::npos ? text.size() + 1 : comma + 1;
    const std::size_t eq = item.find('=');
    if (first && eq == std::string::npos) head = item;
    else if (eq == std::string::npos) m[item] = "1";
    else m[item.substr(0, eq)] = item.substr(eq + 1);
    first = false;
  }
  return m;
}

long num(const std::map<std::string, std::string>& m, const std::string& k, long fallback) {
  const auto it = m.find(k);
  return it == m.end() ? fallback : std::strtol(it->second.c_str(), nullptr, 0);
}

Exchange parse_exchange(const std::string& spec) {
  const std::size_t colon = spec.find(':');
  const std::string kind = spec.substr(0, colon);
  std::string head;
  const auto o = options(colon == std::string::npos ? "" : spec.substr(colon + 1), head);
  const std::uint32_t speed = std::uint32_t(num(o, "speed", 0));
  Exchange x;
  if (kind == "info") {
    x = from_transfer(ttp1::get_info());
    Bytes r{1, 0};                                                       // proto 1.0
    le(r, (num(o, "home", 1) ? 1 : 0) | (num(o, "aux", 0) ? 4 : 0), 2);  // flags: b0 has_home, b2 has_aux
    le(r, std::uint32_t(num(o, "steps", 3200)), 4);
    le(r, std::uint32_t(num(o, "speed", 1600)), 4);
    le(r, std::uint32_t(num(o, "accel", 3200)), 4);
    r.push_back(std::uint8_t(num(o, "aux", 0)));                         // n_aux
    r.insert(r.end(), 3, 0);                                             // reserved
    const std::string name = o.count("name") ? o.at("name") : "fest mock turntable";
    for (std::size_t k = 0; k < 32; ++k) r.push_back(k < name.size() ? std::uint8_t(name[k]) : 0);
    r.insert(r.end(), 12, 0);
    x.reply = r;
  } else if (kind == "status") {
    x = from_transfer(ttp1::get_status());
    static const std::map<std::string, int> states = {{"idle", 0}, {"moving", 1}, {"homing", 2}, {"fault", 3}};
    const std::string st = o.count("state") ? o.at("state") : "idle";
    if (!states.count(st)) throw std::runtime_error("unknown state " + st);
    Bytes r;
    le(r, std::uint32_t(num(o, "pos", 0)), 4);
    le(r, std::uint32_t(num(o, "target", num(o, "pos", 0))), 4);
    r.push_back(std::uint8_t(states.at(st)));
    r.push_back(std::uint8_t((num(o, "homed", 0) ? 1 : 0) | (num(o, "switch", 0) ? 2 : 0) | (num(o, "stalled", 0) ? 4 : 0) |
                             (num(o, "enabled", 1) ? 8 : 0)));
    le(r, std::uint16_t(num(o, "fault", 0)), 2);
    le(r, std::uint32_t(num(o, "seq", 0)), 4);
    x.reply = r;
  } else if (kind == "move_abs") {
    x = from_transfer(ttp1::move_abs(std::int32_t(std::strtol(head.c_str(), nullptr, 0)), speed));
  } else if (kind == "move_rel") {
    x = from_transfer(ttp1::move_rel(std::int32_t(std::strtol(head.c_str(), nullptr, 0)), speed));
  } else if (kind == "home") {
    x = from_transfer(ttp1::home(head == "cw", speed));
  } else if (kind == "stop") {
    x = from_transfer(ttp1::stop(head == "now"));
  } else if (kind == "set_aux") {
    x = from_transfer(ttp1::set_aux(std::uint16_t(num(o, "mask", 0)), std::uint16_t(num(o, "values", 0))));
  } else if (kind == "zero") {
    x = from_transfer(ttp1::set_zero());
  } else if (kind == "enable") {
    x = from_transfer(ttp1::enable(head == "1"));
  } else {
    throw std::runtime_error("unknown exchange '" + spec + "'");
  }
  if (o.count("!stall")) x.status = -32;
  if (o.count("!gone")) x.status = -19;
  if (o.count("!short")) x.reply.resize(std::size_t(num(o, "!short", 0)));
  return x;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc < 2) throw std::runtime_error("usage: ttp_mockdev PREFIX [--vid V --pid P --product S --serial S --no-open] EXCHANGE...");
    const std::string prefix = argv[1];
    std::uint16_t vid = 0x1209, pid = 0x0001;
    std::string product = "TTP/1 fest mock turntable", serial = "MOCK0001";
    bool open_sequence = true;
    std::vector<Exchange> xs;
    for (int i = 2; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--vid" && i + 1 < argc) vid = std::uint16_t(std::strtol(argv[++i], nullptr, 16));
      else if (a == "--pid" && i + 1 < argc) pid = std::uint16_t(std::strtol(argv[++i], nullptr, 16));
      else if (a == "--product" && i + 1 < argc) product = argv[++i];
      else if (a == "--serial" && i + 1 < argc) serial = argv[++i];
      else if (a == "--no-open") open_sequence = false;
      else xs.push_back(parse_exchange(a));
    }
    // Descriptors: device (iManufacturer 1, iProduct 2, iSerialNumber 3), then one
    // configuration with one vendor-class interface and no endpoints besides EP0.
    Bytes desc{18, 1};
    le(desc, 0x0200, 2);
    desc.insert(desc.end(), {0, 0, 0, 64});
    le(desc, vid, 2);
    le(desc, pid, 2);
    le(desc, 0x0100, 2);
    desc.insert(desc.end(), {1, 2, 3, 1});
    desc.insert(desc.end(), {9, 2, 18, 0, 1, 1, 0, 0x80, 50});
    desc.insert(desc.end(), {9, 4, 0, 0, 0, 0xFF, 0, 0, 0});
    char ids[16];
    std::snprintf(ids, sizeof ids, "%04x %04x", vid, pid);
    const std::string v(ids, 4), p(ids + 5, 4);
    std::ofstream u(prefix + ".umockdev");
    u << "P: " << kSysfs << "\n"
      << "N: bus/usb/001/002=" << hex(desc) << "\n"
      << "E: BUSNUM=001\nE: DEVNAME=/dev/bus/usb/001/002\nE: DEVNUM=002\nE: DEVTYPE=usb_device\nE: DRIVER=usb\n"
      << "E: ID_VENDOR_ID=" << v << "\nE: ID_MODEL_ID=" << p << "\nE: MAJOR=189\nE: MINOR=1\n"
      << "E: PRODUCT=" << std::hex << vid << "/" << pid << std::dec << "/100\nE: SUBSYSTEM=usb\n"
      << "A: busnum=1\\n\nA: devnum=2\\n\nA: dev=189:1\n"
      << "A: idVendor=" << v << "\nA: idProduct=" << p << "\n"
      << "A: bConfigurationValue=1\nA: bNumConfigurations=1\nA: speed=12\n"
      << "H: descriptors=" << hex(desc) << "\n";
    if (!u) throw std::runtime_error("cannot write " + prefix + ".umockdev");
    Pcap pcap;
    if (open_sequence) {
      pcap.add(get_descriptor(0x0300, 0, {4, 3, 0x09, 0x04}));  // LANGID table: en-US
      pcap.add(get_descriptor(0x0302, 0x0409, string_descriptor(product)));
      pcap.add(get_descriptor(0x0303, 0x0409, string_descriptor(serial)));
    }
    for (const Exchange& x : xs) pcap.add(x);
    std::ofstream f(prefix + ".pcap", std::ios::binary);
    f.write(reinterpret_cast<const char*>(pcap.bytes.data()), std::streamsize(pcap.bytes.size()));
    if (!f) throw std::runtime_error("cannot write " + prefix + ".pcap");
    std::cout << "/sys" << kSysfs << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "ttp_mockdev: error: " << e.what() << "\n";
    return 2;
  }
}
