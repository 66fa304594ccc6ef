#include "capture/device_uri.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace fest::capture {

std::string DeviceUri::get(const std::string& key, const std::string& fallback) const {
  for (const auto& [k, v] : options)
    if (k == key) return v;
  return fallback;
}

bool DeviceUri::has(const std::string& key) const {
  return std::any_of(options.begin(), options.end(), [&](const auto& o) { return o.first == key; });
}

void DeviceUri::expect_only(const std::vector<std::string>& known) const {
  for (const auto& o : options)
    if (std::find(known.begin(), known.end(), o.first) == known.end())
      throw usage_error("{}: unknown device option '{}'", scheme, o.first);
}

std::vector<DeviceOption> split_device_options(const std::string& list) {
  std::vector<DeviceOption> out;
  std::string rest = list;
  while (!rest.empty()) {
    const std::size_t comma = rest.find(',');
    DeviceOption o;
    o.item = rest.substr(0, comma);
    rest = comma == std::string::npos ? "" : rest.substr(comma + 1);
    const std::size_t eq = o.item.find('=');
    o.key = o.item.substr(0, eq);
    o.has_value = eq != std::string::npos;
    if (o.has_value) o.value = o.item.substr(eq + 1);
    out.push_back(std::move(o));
  }
  return out;
}

DeviceUri parse_device_uri(const std::string& uri) {
  const std::size_t colon = uri.find(':');
  const std::string scheme = uri.substr(0, colon);
  if (scheme.empty() || !std::all_of(scheme.begin(), scheme.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
      }))
    throw usage_error("'{}' is not a device URI (scheme:..., e.g. usb:1209:0001 or sim:)", uri);
  DeviceUri d;
  d.scheme = scheme;
  if (colon == std::string::npos) return d;  // "sim" alone
  std::string rest = uri.substr(colon + 1);
  if (scheme == "exec") {
    d.path = rest;
    return d;
  }
  bool first = true;
  for (const DeviceOption& o : split_device_options(rest)) {
    if (!o.has_value) {
      if (!first) throw usage_error("{}: '{}' is not key=value (in {})", scheme, o.item, uri);
      d.path = o.item;
    } else {
      if (o.key.empty()) throw usage_error("{}: empty option name in '{}'", scheme, uri);
      d.options.emplace_back(o.key, o.value);
    }
    first = false;
  }
  return d;
}

}  // namespace fest::capture
