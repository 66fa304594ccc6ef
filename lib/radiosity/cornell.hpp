#pragma once
// The Cornell box (public data of the Cornell Program of Computer Graphics, millimetres;
// docs/radiosity.md §3): floor, ceiling, light, back, left (red) and right (green) walls
// and the two white blocks, faces oriented towards the room (walls) or outwards (blocks);
// the light is lowered 0.1 mm below the ceiling, radiance (17, 12, 4).

#include "radiosity/scene.hpp"

namespace fest::radiosity {

Scene cornell_box(bool blocks = true);

// The camera of the data set: eye (278, 273, -800) looking along +z, up +y, focal length
// 35 mm on a 25 x 25 mm film (field of view 2 atan(12.5/35)).
struct CornellCamera {
  Eigen::Vector3d eye{278, 273, -800}, target{278, 273, 0}, up{0, 1, 0};
  double vertical_fov_degrees = 39.30746768437243;  // 2 atan(12.5 / 35)
};

}  // namespace fest::radiosity
