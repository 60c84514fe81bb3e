#ifndef WOBBLE_IO_SCENE_COLLIDERS_H
#define WOBBLE_IO_SCENE_COLLIDERS_H

#include <string>
#include <vector>

#include "io/json_fields.h"
#include "sim/contact/collider.h"

namespace wobble {

// The colliders a Wobble scene lists at `key` of `top` ("colliders"): a list of at most
// limits::max_colliders objects, each with a "type" and the keys of that type (metres):
//   ground   "height" (default 0)
//   plane    "point" [x, y, z] and "normal" [x, y, z] (non-zero; normalized here)
//   sphere   "center" [x, y, z] and "radius"
//   box      "center" [x, y, z] and "size" [x, y, z], full edge lengths, axis-aligned
//   capsule  "from" [x, y, z], "to" [x, y, z] and "radius"
// and, on any, "friction" μ (default: the material's, Collider::friction = −1). Positions keep
// to limits::coordinate, sizes to limits::collider_size, μ to limits::friction. `file` names the
// scene in messages. Throws InputError naming the file and the key path ("scene.json:
// colliders[1].radius: expected ..."), also for a key that is not one of the collider's type:
// a misspelt "friction" would otherwise quietly become the material's.
std::vector<Collider> scene_colliders(const std::string& file, JsonFields& top,
                                      const std::string& key);

}  // namespace wobble

#endif
