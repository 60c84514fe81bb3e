#include "scene_self_collision.h"

#include "sim/input_error.h"
#include "sim/value_limits.h"

namespace wobble {

SelfCollisionParams scene_self_collision(JsonFields& top, const std::string& key) {
  JsonFields fields = top.object(key);
  // As for colliders, an unknown key is an error rather than a note: a misspelt thickness would
  // otherwise run with the default without a word.
  for (const auto& item : top.raw(key).items()) {
    if (item.key() != "thickness") {
      throw InputError(fields.where(item.key()) + ": unknown key, " + key +
                       " takes only \"thickness\" (m)");
    }
  }
  SelfCollisionParams params;
  params.on = true;
  params.thickness =
      fields.number_in("thickness", limits::self_collision_thickness).value_or(params.thickness);
  return params;
}

}  // namespace wobble
