#ifndef WOBBLE_IO_SCENE_SELF_COLLISION_H
#define WOBBLE_IO_SCENE_SELF_COLLISION_H

#include <string>

#include "io/json_fields.h"
#include "sim/contact/self_collision.h"

namespace wobble {

// A Wobble scene's top-level "self_collision": {"thickness": 0.01} object at `key` of `top`.
// Its presence turns self-collision on; "thickness" (m, default 0.01) keeps to
// limits::self_collision_thickness. Throws InputError naming the file and the key path when the
// value is not an object, the thickness is not a number within limits, or the object has any
// other key (a misspelt "thickness" would otherwise quietly become the default).
SelfCollisionParams scene_self_collision(JsonFields& top, const std::string& key);

}  // namespace wobble

#endif
