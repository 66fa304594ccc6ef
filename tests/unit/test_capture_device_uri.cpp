#include "capture/device_uri.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

using fest::capture::parse_device_uri;

TEST(DeviceUri, UsbPathKeepsVidPidAndSerial) {
  const auto d = parse_device_uri("usb:1209:0001#SN42");
  EXPECT_EQ(d.scheme, "usb");
  EXPECT_EQ(d.path, "1209:0001#SN42");
  EXPECT_TRUE(d.options.empty());
}

TEST(DeviceUri, OptionsInOrderWithoutPath) {
  const auto d = parse_device_uri("gpio:chip=gpiochip0,line=GPIO17,active_low=1");
  EXPECT_EQ(d.path, "");
  ASSERT_EQ(d.options.size(), 3u);
  EXPECT_EQ(d.get("line"), "GPIO17");
  EXPECT_EQ(d.get("missing", "x"), "x");
  EXPECT_TRUE(d.has("active_low"));
}

TEST(DeviceUri, PathThenOptions) {
  const auto d = parse_device_uri("v4l2:/dev/video0,fourcc=Y16");
  EXPECT_EQ(d.path, "/dev/video0");
  EXPECT_EQ(d.get("fourcc"), "Y16");
}

TEST(DeviceUri, ExecKeepsCommasInTheCommand) {
  const auto d = parse_device_uri("exec:gphoto2 --set-config shutterspeed={shutter},--capture");
  EXPECT_EQ(d.path, "gphoto2 --set-config shutterspeed={shutter},--capture");
}

TEST(DeviceUri, Errors) {
  EXPECT_THROW(parse_device_uri("/dev/gpiochip0"), fest::Error);
  EXPECT_THROW(parse_device_uri(":x"), fest::Error);
  EXPECT_THROW(parse_device_uri("sim:=3"), fest::Error);
  EXPECT_THROW(parse_device_uri("gpio:chip=0,GPIO17"), fest::Error);
  EXPECT_THROW(parse_device_uri("sim:speed=1").expect_only({"accel"}), fest::Error);
  EXPECT_NO_THROW(parse_device_uri("sim").expect_only({}));
}
