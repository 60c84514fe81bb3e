#include "app/outputs/obj_sequence.h"

#include "app/outputs/image_outputs.h"
#include "io/atomic_file.h"
#include "io/write_obj.h"

namespace wobble {

ObjSequence::ObjSequence(std::string folder) : folder_(std::move(folder)) {
  if (folder_.empty()) return;
  check_output_folder("--export-obj-sequence", folder_,
                      ImageOutputs::frame_file(folder_, 1, ".obj"));
}

void ObjSequence::write(long frame, const Eigen::MatrixXd& positions,
                        const SpringNetwork& network) const {
  if (folder_.empty()) return;
  if (!folder_made_) ImageOutputs::start_frame_folder(folder_, ".obj");
  folder_made_ = true;
  write_obj(ImageOutputs::frame_file(folder_, frame, ".obj"), positions, network.F, network.E);
}

}  // namespace wobble
