#ifndef WOBBLE_TESTS_APP_VIEWER_SCREEN_H
#define WOBBLE_TESTS_APP_VIEWER_SCREEN_H

#include <Eigen/Core>

#include "../shared_constants.h"
#include "app/interaction/picking.h"
#include "app/viewer/viewer.h"
#include "render/camera.h"

namespace wobble::testing {

// Where the viewer's camera draws vertex i of its simulation, in the coordinates of a window of
// `window` size (as the mouse events use them).
inline Eigen::Vector2f vertex_on_screen(const Viewer& viewer, int i,
                                        const Eigen::Vector2f& window) {
  const Eigen::Matrix4f view_projection =
      projection_matrix(viewer.drawing().camera(), window.x() / window.y()) *
      view_matrix(viewer.drawing().camera());
  const Eigen::Vector3f p = viewer.session().simulation().positions().row(i).cast<float>();
  return project_to_window(view_projection, p, window)->head<2>();
}

// Key `key` pressed over the 3-D view of a 1280 × 720 window (testing::window).
inline void press(Viewer& viewer, int key) {
  InputEvent event;
  event.type = InputEvent::Type::key_press;
  event.code = key;
  viewer.handle_events({event}, false, false, window);
}

}  // namespace wobble::testing

#endif
