#ifndef WOBBLE_APP_INTERACTION_VIEW_FRAMING_H
#define WOBBLE_APP_INTERACTION_VIEW_FRAMING_H

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "render/camera.h"

namespace wobble {

// The part of a view the panel leaves free, where F frames the shape: the full height of the
// wider side beside the panel, as fractions of the view. The whole view when the panel is
// hidden (panel_right <= panel_left) or leaves neither side a quarter of the view's width,
// since framing behind the panel then beats framing into a sliver.
//   view_width               the view's width, in window units
//   panel_left, panel_right  the panel's left and right edges, in the same units from the
//                            view's left edge
ViewportRegion region_beside_panel(float view_width, float panel_left, float panel_right);

// The same for any windows over the view (the panel, the plots' column): the widest stretch of
// the view's width that none of `covers` (each [left, right] in window units from the view's left
// edge; an empty one, right <= left, covers nothing) covers, at full height. The whole view when
// that stretch is narrower than a quarter of the view.
ViewportRegion region_free_of(float view_width, const std::vector<std::pair<float, float>>& covers);

// Below a window that spans the view's width (the panel on a phone held upright): the view's
// full width under `cover_bottom` (window units from the view's top edge), when that leaves at
// least a third of `view_height`; otherwise the whole view.
ViewportRegion region_below(float view_height, float cover_bottom);

// Grow the box [lower, upper] (m, y up) to the room a shape moves in: down to the ground at
// `ground_height` (m), where hanging cloth falls, and a quarter of the box's largest side to
// either side in x and z, where it swings.
void add_room_to_move(Eigen::Vector3f& lower, Eigen::Vector3f& upper, float ground_height);

}  // namespace wobble

#endif
