#ifndef WOBBLE_APP_OUTPUTS_OBJ_SEQUENCE_H
#define WOBBLE_APP_OUTPUTS_OBJ_SEQUENCE_H

#include <string>

#include "sim/scene.h"

namespace wobble {

// --export-obj-sequence DIR: the positions after every frame as DIR/frame_00001.obj, ..., each
// with the scene's render faces (or its springs as lines), written atomically, for Blender and
// other tools.
class ObjSequence {
 public:
  // Checks that the folder exists or can be made in an existing parent (InputError otherwise),
  // but makes it only when the first frame is written. An empty folder: no output.
  explicit ObjSequence(std::string folder);
  void write(long frame, const Eigen::MatrixXd& positions, const SpringNetwork& network) const;

 private:
  std::string folder_;
  mutable bool folder_made_ = false;  // made at the first frame, once all input was accepted
};

}  // namespace wobble

#endif
