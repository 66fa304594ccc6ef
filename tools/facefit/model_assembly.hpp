#pragma once
// A model from example meshes in correspondence (build, convert --from ply-set), and the
// landmark map and evaluation mask stored with it.

#include <string>
#include <vector>

#include "commands.hpp"
#include "facefit/model.hpp"

namespace fest::facefit_tool {

// PCA of the meshes at `paths` (docs/facefit.md §1) with build's component and variance
// limits; usage errors name the flags, bad input names the mesh that does not correspond.
facefit::Model build_from_meshes(const std::vector<std::string>& paths, const BuildArgs& a);
// Reads the landmark map and the mask (either may be empty) into the model and checks it.
void attach_landmarks(facefit::Model& m, const std::string& landmarks, const std::string& mask);

}  // namespace fest::facefit_tool
