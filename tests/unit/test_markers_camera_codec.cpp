// lib/markers/camera_codec: the camera.json of capture calib-camera.
#include <gtest/gtest.h>

#include "expect_error.hpp"
#include "markers/camera_codec.hpp"

using namespace fest::markers;
using fest::test::expect_bad_input;

TEST(MarkersCameraCodec, ReadsCalibCameraOutput) {
  // The shape calib-camera writes (man capture-calib(1)), extra fields included.
  const char* text = R"({"K":[600,0,319.5,0,610,239.5,0,0,1],"dist":[0.1,-0.2,0.001,0.002,0.05],
    "R":[1,0,0,0,1,0,0,0,1],"t":[0,0,0],"width":640,"height":480,"rms":0.3,"board":"9x6x25mm",
    "views":[{"image":"a.png","rms_px":0.3}],"left_out":[]})";
  const CameraModel c = decode_camera_json(text);
  EXPECT_EQ(c.K(0, 0), 600);
  EXPECT_EQ(c.K(1, 1), 610);
  EXPECT_EQ(c.K(0, 2), 319.5);
  EXPECT_EQ(c.dist[4], 0.05);
  EXPECT_EQ(c.width, 640);
  EXPECT_EQ(c.height, 480);
  const CameraModel back = decode_camera_json(encode_camera_json(c));
  EXPECT_EQ(back.K, c.K);
  EXPECT_EQ(back.dist, c.dist);
}

TEST(MarkersCameraCodec, DistortionIsOptional) {
  const CameraModel c = decode_camera_json(R"({"K":[500,0,100,0,500,80,0,0,1],"width":200,"height":160})");
  EXPECT_FALSE(c.has_distortion());
}

TEST(MarkersCameraCodec, RefusesMalformedFiles) {
  expect_bad_input([] { decode_camera_json(""); }, "camera: not valid JSON");
  expect_bad_input([] { decode_camera_json("[1,2]"); }, "not a JSON object");
  expect_bad_input([] { decode_camera_json(R"({"K":[1,2,3],"width":1,"height":1})"); }, "'K' must hold 9 numbers");
  expect_bad_input([] { decode_camera_json(R"({"K":[500,0,1,0,500,1,0,0,1],"height":1})"); }, "'width' missing");
  expect_bad_input([] { decode_camera_json(R"({"K":[-5,0,1,0,500,1,0,0,1],"width":2,"height":2})"); },
                   "positive focal lengths");
  expect_bad_input([] { decode_camera_json(R"({"K":[5,0,1,0,5,1,0,0,2],"width":2,"height":2})"); }, "K must be");
  expect_bad_input([] { decode_camera_json(R"({"K":[5,0,1,0,5,1,0,0,1],"width":-2,"height":2})"); }, "width and height");
  expect_bad_input([] { decode_camera_json(R"({"K":[5,0,1,0,5,1,0,0,1],"dist":[1,2,3,4,5,6],"width":2,"height":2})"); },
                   "'dist' must hold up to 5");
  expect_bad_input([] { decode_camera_json(R"({"K":[5,0,1,0,"x",1,0,0,1],"width":2,"height":2})"); }, "K[4] is not a number");
}
