// gpiomock: an emulated GPIO chip for the lights CLI tests (docs/lights.md §4). A
// shared object preloaded after umockdev's preload library; its constructor builds a
// umockdev testbed with /dev/gpiochip0 and answers the GPIO v1 uAPI ioctls that libgpiod
// 1.6 makes, so the unmodified `lights` binary drives it like a kernel chip:
//
//   GPIOMOCK=1 GPIOMOCK_LOG=log.txt LD_PRELOAD=libumockdev-preload.so.0:$BIN/libgpiomock.so
//     lights --station s.json on L0
//
// The chip "gpiochip0" (label "fest-mock") has 32 lines named GPIO0..GPIO31. Each line
// request is answered with a fd on a second emulated node /dev/gpiochip0-handleK whose
// handler takes GPIOHANDLE_SET/GET_LINE_VALUES. Environment:
//   GPIOMOCK=1                 build the testbed (cleared at once, so children do not)
//   GPIOMOCK_LOG=FILE          append "request|request-input|set OFFSET NAME LEVEL" per event,
//                              LEVEL being the physical pin level (active-low applied)
//   GPIOMOCK_BUSY=N:CONSUMER   line N is already held by CONSUMER (request -> EBUSY)
//   GPIOMOCK_DENY=1            the chip refuses every ioctl with EACCES
//   GPIOMOCK_HOME=L:S:N        input line L (a home switch) reads high once output line S
//                              (a STEP line) has had N rising edges

#include <fcntl.h>
#include <ftw.h>
#include <linux/gpio.h>
#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <umockdev.h>

namespace {

constexpr unsigned kLines = 32;
// Line handles are fds on emulated nodes /dev/gpiochip0-handleK, one node per request;
// umockdev needs ~25 ms per node to set up, so there are only a few.
constexpr unsigned kSlots = 6;

// Plain zero-initialised data only: the constructor below may run before this file's
// dynamic initialisers, which would reset anything with a constructor.
struct Line {
  bool requested, active_low, busy, input;
  int level;  // physical
  unsigned rising_edges;
  char consumer[32];
};

Line g_lines[kLines];
unsigned g_slot_line[kSlots];
unsigned g_slots_used;
char g_log[4096];
bool g_deny;
// GPIOMOCK_HOME=LINE:STEPLINE:N -- input LINE reads high once STEPLINE had N rising edges.
bool g_home;
unsigned g_home_line, g_home_step_line, g_home_after;
UMockdevTestbed* g_testbed;
char g_root[4096];

void log_event(const char* what, unsigned offset) {
  if (!g_log[0]) return;
  if (FILE* f = std::fopen(g_log, "a")) {
    std::fprintf(f, "%s %u GPIO%u %d\n", what, offset, offset, g_lines[offset].level);
    std::fclose(f);
  }
}

template <typename T>
T* arg_data(UMockdevIoctlClient* client, UMockdevIoctlData** resolved) {
  GError* err = nullptr;
  *resolved = umockdev_ioctl_data_resolve(umockdev_ioctl_client_get_arg(client), 0, sizeof(T), &err);
  if (!*resolved) {
    if (err) g_error_free(err);
    return nullptr;
  }
  return reinterpret_cast<T*>((*resolved)->data);
}

gboolean chip_ioctl(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer) {
  const gulong request = umockdev_ioctl_client_get_request(client);
  if (g_deny) {
    umockdev_ioctl_client_complete(client, -1, EACCES);
    return TRUE;
  }
  UMockdevIoctlData* d = nullptr;
  if (request == GPIO_GET_CHIPINFO_IOCTL) {
    auto* info = arg_data<gpiochip_info>(client, &d);
    if (!info) return FALSE;
    std::memset(info, 0, sizeof *info);
    std::snprintf(info->name, sizeof info->name, "gpiochip0");
    std::snprintf(info->label, sizeof info->label, "fest-mock");
    info->lines = kLines;
  } else if (request == GPIO_GET_LINEINFO_IOCTL) {
    auto* info = arg_data<gpioline_info>(client, &d);
    if (!info) return FALSE;
    const unsigned off = info->line_offset;
    if (off >= kLines) {
      umockdev_ioctl_client_complete(client, -1, EINVAL);
      return TRUE;
    }
    const Line& l = g_lines[off];
    std::memset(info->name, 0, sizeof info->name);
    std::memset(info->consumer, 0, sizeof info->consumer);
    std::snprintf(info->name, sizeof info->name, "GPIO%u", off);
    info->flags = 0;
    if (l.busy || l.requested) {
      info->flags |= GPIOLINE_FLAG_KERNEL;
      std::snprintf(info->consumer, sizeof info->consumer, "%s", l.consumer);
    }
    if (l.requested) info->flags |= GPIOLINE_FLAG_IS_OUT | (l.active_low ? GPIOLINE_FLAG_ACTIVE_LOW : 0);
  } else if (request == GPIO_GET_LINEHANDLE_IOCTL) {
    auto* req = arg_data<gpiohandle_request>(client, &d);
    if (!req) return FALSE;
    const unsigned off = req->lineoffsets[0];
    const bool input = req->flags & GPIOHANDLE_REQUEST_INPUT;
    if (req->lines != 1 || off >= kLines || (!input && !(req->flags & GPIOHANDLE_REQUEST_OUTPUT))) {
      umockdev_ioctl_client_complete(client, -1, EINVAL);
      return TRUE;
    }
    Line& l = g_lines[off];
    if (l.busy || l.requested) {
      umockdev_ioctl_client_complete(client, -1, EBUSY);
      return TRUE;
    }
    l.requested = true;
    l.active_low = req->flags & GPIOHANDLE_REQUEST_ACTIVE_LOW;
    std::snprintf(l.consumer, sizeof l.consumer, "%s", req->consumer_label);
    l.input = input;
    if (input) {
      log_event("request-input", off);
    } else {
      l.level = (req->default_values[0] ? 1 : 0) ^ (l.active_low ? 1 : 0);
      log_event("request", off);
    }
    if (g_slots_used == kSlots) {
      umockdev_ioctl_client_complete(client, -1, ENOMEM);
      return TRUE;
    }
    g_slot_line[g_slots_used] = off;
    const std::string node = "/dev/gpiochip0-handle" + std::to_string(g_slots_used++);
    req->fd = open(node.c_str(), O_RDWR | O_CLOEXEC);
    if (req->fd < 0) {
      umockdev_ioctl_client_complete(client, -1, EIO);
      return TRUE;
    }
  } else {
    return FALSE;
  }
  umockdev_ioctl_client_complete(client, 0, 0);
  return TRUE;
}

gboolean handle_ioctl(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer user) {
  const unsigned off = g_slot_line[GPOINTER_TO_UINT(user)];
  const gulong request = umockdev_ioctl_client_get_request(client);
  UMockdevIoctlData* d = nullptr;
  auto* data = arg_data<gpiohandle_data>(client, &d);
  if (!data) return FALSE;
  Line& l = g_lines[off];
  if (request == GPIOHANDLE_SET_LINE_VALUES_IOCTL && !l.input) {
    const int level = (data->values[0] ? 1 : 0) ^ (l.active_low ? 1 : 0);
    if (level == 1 && l.level == 0) ++l.rising_edges;
    l.level = level;
    log_event("set", off);
  } else if (request == GPIOHANDLE_GET_LINE_VALUES_IOCTL) {
    if (l.input && g_home && off == g_home_line) l.level = g_lines[g_home_step_line].rising_edges >= g_home_after ? 1 : 0;
    data->values[0] = std::uint8_t(l.level ^ (l.active_low ? 1 : 0));
  } else {
    return FALSE;
  }
  umockdev_ioctl_client_complete(client, 0, 0);
  return TRUE;
}

void attach(const char* devnode, GCallback cb, gpointer user) {
  UMockdevIoctlBase* h = UMOCKDEV_IOCTL_BASE(g_object_new(UMOCKDEV_TYPE_IOCTL_BASE, nullptr));
  g_signal_connect(h, "handle-ioctl", cb, user);
  GError* err = nullptr;
  if (!umockdev_testbed_attach_ioctl(g_testbed, devnode, h, &err)) {
    std::fprintf(stderr, "gpiomock: cannot attach %s: %s\n", devnode, err ? err->message : "?");
    std::exit(99);
  }
}

int remove_entry(const char* path, const struct stat*, int, struct FTW*) { return ::remove(path); }

void cleanup() {
  // Removes the testbed's temporary root (itself; finalising the testbed takes 250 ms).
  if (g_root[0]) nftw(g_root, remove_entry, 16, FTW_DEPTH | FTW_PHYS);
}

__attribute__((constructor)) void gpiomock_init() {
  const char* on = std::getenv("GPIOMOCK");
  if (!on || std::strcmp(on, "1") != 0) return;
  unsetenv("GPIOMOCK");  // children (if any) must not build a second testbed
  if (const char* log = std::getenv("GPIOMOCK_LOG")) std::snprintf(g_log, sizeof g_log, "%s", log);
  if (const char* deny = std::getenv("GPIOMOCK_DENY")) g_deny = std::strcmp(deny, "1") == 0;
  if (const char* busy = std::getenv("GPIOMOCK_BUSY")) {
    const char* colon = std::strchr(busy, ':');
    const unsigned off = unsigned(std::atoi(busy));
    if (colon && off < kLines) {
      g_lines[off].busy = true;
      std::snprintf(g_lines[off].consumer, sizeof g_lines[off].consumer, "%s", colon + 1);
    }
  }
  // umockdev serves the ioctls on threads started here; they must not take the stop
  // signals that `lights hold` waits for with sigtimedwait in its main thread.
  sigset_t stop, old;
  sigemptyset(&stop);
  sigaddset(&stop, SIGINT);
  sigaddset(&stop, SIGTERM);
  sigaddset(&stop, SIGHUP);
  pthread_sigmask(SIG_BLOCK, &stop, &old);
  if (const char* home = std::getenv("GPIOMOCK_HOME"))
    g_home = std::sscanf(home, "%u:%u:%u", &g_home_line, &g_home_step_line, &g_home_after) == 3 && g_home_line < kLines &&
             g_home_step_line < kLines;
  g_testbed = umockdev_testbed_new();
  std::string desc =
      "P: /devices/platform/gpio-mock/gpiochip0\nN: gpiochip0\nE: SUBSYSTEM=gpio\nE: DEVNAME=/dev/gpiochip0\n"
      "E: MAJOR=254\nE: MINOR=0\nA: dev=254:0\\n\n\n";
  for (unsigned k = 0; k < kSlots; ++k)
    desc += "P: /devices/platform/gpio-mock/gpiochip0-handle" + std::to_string(k) + "\nN: gpiochip0-handle" + std::to_string(k) +
            "\nE: SUBSYSTEM=gpio-mock-handle\nE: DEVNAME=/dev/gpiochip0-handle" + std::to_string(k) + "\nE: MAJOR=254\nE: MINOR=" +
            std::to_string(k + 1) + "\nA: dev=254:" + std::to_string(k + 1) + "\\n\n\n";
  GError* err = nullptr;
  if (!umockdev_testbed_add_from_string(g_testbed, desc.c_str(), &err)) {
    std::fprintf(stderr, "gpiomock: testbed: %s\n", err ? err->message : "?");
    std::exit(99);
  }
  // libgpiod checks /sys/bus/gpio/devices/<chip>/dev against the node's device number.
  gchar* root = umockdev_testbed_get_root_dir(g_testbed);
  std::snprintf(g_root, sizeof g_root, "%s", root);
  const std::string bus = std::string(root) + "/sys/bus/gpio/devices";
  g_mkdir_with_parents(bus.c_str(), 0755);
  const std::string link = bus + "/gpiochip0";
  if (symlink("../../../devices/platform/gpio-mock/gpiochip0", link.c_str()) != 0 && errno != EEXIST) {
    std::fprintf(stderr, "gpiomock: cannot link %s: %s\n", link.c_str(), std::strerror(errno));
    std::exit(99);
  }
  g_free(root);
  attach("/dev/gpiochip0", G_CALLBACK(chip_ioctl), nullptr);
  for (unsigned k = 0; k < kSlots; ++k)
    attach(("/dev/gpiochip0-handle" + std::to_string(k)).c_str(), G_CALLBACK(handle_ioctl), GUINT_TO_POINTER(k));
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  std::atexit(cleanup);
}

}  // namespace
